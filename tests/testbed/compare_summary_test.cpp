// The summary `dyop compare` opens with (report/compare_summary): first on standard output and in
// report.md, at most twenty lines, every figure the run's own.
#include "report/compare_summary.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "program/compare_command.hpp"
#include "report/compare_in_world.hpp"
#include "report/compare_report.hpp"
#include "report/format.hpp"

namespace dyop::report {
namespace {

// The scenes and sections the summary draws on, a few steps each: seconds, not minutes.
experiments::CompareOptions summary_test_options(const std::string& dir) {
  experiments::CompareOptions options;
  options.quick = true;
  options.steps = 20;
  options.scenes = {"pyramid", "rain", "slide", "tiles", "tile-map"};
  options.sections = {"in-world", "slide", "viewer"};
  options.out_dir = dir;
  return options;
}

std::vector<std::string> summary_test_lines(std::istream& in, std::size_t count) {
  std::vector<std::string> out;
  for (std::string line; out.size() < count && std::getline(in, line);) out.push_back(line);
  return out;
}

bool has_line_with(const std::vector<std::string>& lines, const std::string& text) {
  return std::any_of(lines.begin(), lines.end(),
                     [&](const std::string& l) { return l.find(text) != std::string::npos; });
}

TEST(CompareSummary, FiguresAreTheRunsRecordsInAtMostTwentyLines) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("dyop_summary_figures_test_" + std::to_string(getpid()));
  std::filesystem::remove_all(dir);
  std::ostringstream progress;
  const Comparison c = run_comparison(summary_test_options(dir.string()), progress);
  ASSERT_TRUE(write_report(c).empty());
  const std::vector<std::string> lines = summary_lines(c);
  EXPECT_LE(static_cast<int>(lines.size()), summary_max_lines);
  const SummaryFigures f = summary_figures(c);
  EXPECT_NE(lines.front().find(f.machine), std::string::npos) << "the CPU named";

  // Depth: the largest of the main table's errors, each side.
  double own = 0, plugin = 0;
  for (const scenes::SceneMetrics& m : c.main.rows) {
    if (m.runner == box2d::Backend::Box2D) own = std::max(own, m.pd_error_max);
    if (m.runner == box2d::Backend::Dyop) plugin = std::max(plugin, m.pd_error_max);
  }
  ASSERT_TRUE(f.depth_own && f.depth_dyop);
  EXPECT_EQ(f.depth_own->max_m, own);
  EXPECT_EQ(f.depth_dyop->max_m, plugin);
  EXPECT_TRUE(has_line_with(lines, "Box2D's own " + metres(own) + " m"));
  EXPECT_TRUE(has_line_with(lines, "the plug-in " + metres(plugin) + " m"));

  // Wall time: the in-world section's rows of `dyop`, for the three piles.
  const InWorldSection* in_world = c.section<InWorldSection>();
  ASSERT_NE(in_world, nullptr);
  int wall_times = 0;
  for (const experiments::InWorldRatio& r : in_world->rows()) {
    if (r.backend != box2d::Backend::Dyop || r.scene == "slide" || r.scene == "tiles") continue;
    ++wall_times;
    EXPECT_TRUE(has_line_with(lines, "(" + r.scene + "): " + fmt("%.2f", r.narrowphase_ratio()) +
                                         "x, " + fmt("%.2f", r.step_ratio()) + "x"))
        << r.scene;
  }
  EXPECT_EQ(wall_times, 3);

  // Ghost collisions: the slide section's records as its CSV has them, sliding bodies only.
  ASSERT_EQ(f.glides.size(), 2u);
  for (const GlideFigures& g : f.glides) {
    std::ifstream csv(dir / (g.scene + ".csv"));
    double speed[2] = {0, 0}, travel[2] = {1, 1};  // Box2D's own, dyop
    std::string line;
    std::getline(csv, line);  // the header
    while (std::getline(csv, line)) {
      std::vector<std::string> cells;
      std::istringstream fields(line);
      for (std::string cell; std::getline(fields, cell, ',');) cells.push_back(cell);
      ASSERT_GE(cells.size(), 9u) << line;
      const int side = cells[0] == "box2d-own" ? 0 : cells[0] == "dyop" ? 1 : -1;
      if (side < 0 || cells[3] == "true") continue;  // another runner, or a rolling wheel
      speed[side] = std::max(speed[side], std::stod(cells[6]));
      travel[side] = std::min(travel[side], std::stod(cells[8]));
    }
    // The CSV's six significant digits.
    const auto near = [](double a, double b) {
      return std::abs(a - b) <= 1e-5 * (1 + std::abs(b));
    };
    EXPECT_TRUE(near(g.own_vertical_speed, speed[0])) << g.scene;
    EXPECT_TRUE(near(g.own_travel, travel[0])) << g.scene;
    EXPECT_TRUE(near(g.plugin_vertical_speed, speed[1])) << g.scene;
    EXPECT_TRUE(near(g.plugin_travel, travel[1])) << g.scene;
    EXPECT_TRUE(has_line_with(
        lines, "(" + g.scene + "): Box2D's own " + fmt("%.3f", g.own_vertical_speed) + " m/s"))
        << g.scene;
  }
  EXPECT_TRUE(has_line_with(lines, dir.string() + "/report.md"));
  EXPECT_TRUE(has_line_with(lines, dir.string() + "/view_<scene>.html"));
  if (!HasFailure()) std::filesystem::remove_all(dir);
}

TEST(CompareSummary, OpensStandardOutputAndTheReport) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("dyop_summary_opens_test_" + std::to_string(getpid()));
  std::filesystem::remove_all(dir);
  std::ostringstream out, err;
  ASSERT_EQ(cli::run_compare_command(summary_test_options(dir.string()), out, err), 0) << err.str();
  // The summary is what comes before the first table, then a blank line.
  std::istringstream printed(out.str());
  std::vector<std::string> summary;
  for (std::string line; std::getline(printed, line) && line.rfind("| ", 0) != 0;) {
    summary.push_back(line);
  }
  ASSERT_GE(summary.size(), 2u);
  EXPECT_EQ(summary.back(), "");
  summary.pop_back();
  EXPECT_LE(static_cast<int>(summary.size()), summary_max_lines);
  EXPECT_EQ(summary.front().rfind("# DyOP-PD against Box2D 2.4's own contact, on ", 0), 0u);
  EXPECT_TRUE(has_line_with(summary, "Depth error"));
  EXPECT_TRUE(has_line_with(summary, "Ghost collisions"));
  EXPECT_TRUE(has_line_with(summary, "Wall time"));
  std::ifstream report(dir / "report.md");
  EXPECT_EQ(summary_test_lines(report, summary.size()), summary) << "report.md opens with it";
  if (!HasFailure()) std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace dyop::report
