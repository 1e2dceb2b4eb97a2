// `dyop compare` (program/compare_command): a tiny run writes the report, the CSVs behind it,
// and (with gnuplot) the charts.
#include "program/compare_command.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "report/compare_section.hpp"
#include "scenes/scene.hpp"

namespace dyop::scenes {
namespace {

using namespace experiments;  // the experiments these tests run over the scenes

std::string read(const std::filesystem::path& p) {
  std::ifstream in(p);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

TEST(Compare, TinyRunWritesTheReportTheCsvAndTheCharts) {
  const auto dir =
      std::filesystem::temp_directory_path() / ("dyop_compare_test_" + std::to_string(getpid()));
  std::filesystem::remove_all(dir);
  CompareOptions options;
  options.quick = true;
  options.steps = 3;
  options.out_dir = dir.string();
  options.sections = report::compare_section_names();  // those --quick leaves out too
  std::ostringstream out, err;
  ASSERT_EQ(cli::run_compare_command(options, out, err), 0) << err.str();

  const int runs = static_cast<int>(scene_catalog().size() * compare_backends(options).size());
  EXPECT_NE(err.str().find("[" + std::to_string(runs) + "/" + std::to_string(runs) + "]"),
            std::string::npos)
      << "one progress line per scene and backend";
  EXPECT_NE(out.str().find("| rain | dyop |"), std::string::npos);
  EXPECT_NE(out.str().find("lin-canny-warm / dyop"), std::string::npos) << "the Figure-7 table";
  EXPECT_NE(out.str().find("report: " + dir.string() + "/report.md"), std::string::npos);

  const std::string report = read(dir / "report.md");
  EXPECT_NE(report.find("## Results"), std::string::npos);
  EXPECT_NE(report.find("## The paper's experiment"), std::string::npos);
  const std::string csv = read(dir / "compare.csv");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), runs + 1);

  // The skip section: every skip scene under every skip backend, none then all, and each skip
  // alone (lin-canny-cache left out) in the breakdown scenes.
  const int skip_runs = static_cast<int>(skip_scenes.size() * skip_backends.size());
  EXPECT_NE(
      err.str().find("[skips " + std::to_string(skip_runs) + "/" + std::to_string(skip_runs) + "]"),
      std::string::npos);
  EXPECT_NE(report.find("## Skipping what a scene doesn't need"), std::string::npos);
  EXPECT_NE(report.find("**Target**"), std::string::npos);
  EXPECT_NE(out.str().find("| rain | dyop | 3 |"), std::string::npos) << "skips on against off";
  const std::string skips = read(dir / "skips.csv");
  const int rows =
      skip_runs + static_cast<int>(skip_target_scenes.size()) * (skip_switch_count - 1);
  EXPECT_EQ(std::count(skips.begin(), skips.end(), '\n'), rows + 1);
  EXPECT_NE(skips.find("rain,dyop,3,warm-axis,"), std::string::npos) << "a skip alone";
  EXPECT_NE(skips.find("rain,dyop,3,all,"), std::string::npos) << "every skip on";
  EXPECT_FALSE(read(dir / "paper_figure7.csv").empty());
  EXPECT_FALSE(read(dir / "paper_methods.csv").empty());
  for (const SceneInfo& s : scene_catalog()) {
    EXPECT_TRUE(std::filesystem::exists(dir / ("scene_" + std::string(s.name) + ".svg"))) << s.name;
  }
  // The slide section: Box2D's own contact and the two exact backends, 8 sliders each.
  EXPECT_NE(report.find("## Sliding over triangulated grounds"), std::string::npos);
  EXPECT_NE(out.str().find("| box2d-own |"), std::string::npos) << "the slide table";
  const std::string slide = read(dir / "slide.csv");
  EXPECT_EQ(std::count(slide.begin(), slide.end(), '\n'), 3 * 8 + 1);
  for (const char* runner : {"box2d-own", "dyop", "sat"}) {
    EXPECT_TRUE(std::filesystem::exists(dir / ("slide_" + std::string(runner) + ".svg"))) << runner;
    EXPECT_TRUE(std::filesystem::exists(dir / ("tiles_" + std::string(runner) + ".svg"))) << runner;
  }
  // Its tiles part: 6 grounds, 3 sliders each.
  EXPECT_NE(report.find("## Sliding over tiled grounds"), std::string::npos);
  const std::string tiles = read(dir / "tiles.csv");
  EXPECT_EQ(std::count(tiles.begin(), tiles.end(), '\n'), 3 * 18 + 1);
  // The worlds-on-threads section: 1, 2 and 4 rain worlds under each of the two runners.
  EXPECT_NE(report.find("## Worlds on threads"), std::string::npos);
  const std::string threads = read(dir / "threads.csv");
  EXPECT_EQ(std::count(threads.begin(), threads.end(), '\n'), 3 * 2 + 1);
  // The viewer section: one page per scene, each linked from the report.
  EXPECT_NE(report.find("## Viewer"), std::string::npos);
  for (const SceneInfo& s : scene_catalog()) {
    const std::string page = "view_" + std::string(s.name) + ".html";
    if (left_out_of_quick_sections(s.name)) {
      EXPECT_FALSE(std::filesystem::exists(dir / page)) << page << ": left out of --quick";
      continue;
    }
    EXPECT_GT(std::filesystem::file_size(dir / page), 10000u) << page;
    EXPECT_NE(report.find("](" + page + ")"), std::string::npos) << page;
  }
  // Every section's files are listed in the report.
  for (const char* file :
       {"inworld.csv", "slide.csv", "tiles.csv", "skips.csv", "paper_methods.csv", "threads.csv"}) {
    EXPECT_NE(report.find(std::string("`") + file + "`"), std::string::npos) << file;
  }
  if (std::system("command -v gnuplot >/dev/null 2>&1") == 0) {
    for (const char* chart : {"time_per_method.svg", "time_vs_error.svg", "paper_figure7.svg",
                              "slide_paths.svg", "tiles_paths.svg"}) {
      EXPECT_GT(std::filesystem::file_size(dir / chart), 1000u) << chart;
      EXPECT_NE(report.find(std::string("](") + chart + ")"), std::string::npos) << chart;
    }
  } else {
    GTEST_LOG_(INFO) << "gnuplot not installed: charts not checked";
    EXPECT_NE(report.find("not drawn"), std::string::npos);
  }
  if (!HasFailure()) std::filesystem::remove_all(dir);  // kept to look at when something failed
}

// A point of a chart as gnuplot draws it: where, and whether within the chart's axes ('i'),
// outside them ('o') or undefined ('u').
struct PlottedPoint {
  double x = 0, y = 0;
  char type = 'u';
};

// Every point the chart's script `gp` plots, from gnuplot itself: the script run with its
// terminal replaced by `set table` (which lists each curve's points) and no output file.
std::vector<PlottedPoint> plotted_points(const std::filesystem::path& gp) {
  const std::filesystem::path table = gp.string() + ".table", script = gp.string() + ".check";
  {
    std::ifstream in(gp);
    std::ofstream out(script);
    for (std::string line; std::getline(in, line);) {
      if (line.rfind("set terminal", 0) == 0) {
        out << "set table '" << table.string() << "'\n";
      } else if (line.rfind("set output", 0) != 0) {
        out << line << '\n';
      }
    }
  }
  const std::string command = "gnuplot '" + script.string() + "' >/dev/null 2>&1";
  EXPECT_EQ(std::system(command.c_str()), 0) << command;
  std::vector<PlottedPoint> points;
  std::ifstream in(table);
  for (std::string line; std::getline(in, line);) {
    std::istringstream fields(line);
    PlottedPoint p;
    if (line.empty() || line[0] == '#' || !(fields >> p.x >> p.y >> p.type)) continue;
    points.push_back(p);
  }
  return points;
}

// The recycling chart plots, per scene and distance, the narrow phase's and the step's ratio to
// Box2D's own contact and the kept manifolds' error: every one of them must be drawn, and within
// the axes (the first distance of each scene was once taken for the legend's title instead).
TEST(Compare, RecyclingChartDrawsEveryPointWithinItsAxes) {
  if (std::system("command -v gnuplot >/dev/null 2>&1") != 0) GTEST_SKIP() << "no gnuplot";
  const auto dir = std::filesystem::temp_directory_path() /
                   ("dyop_recycling_chart_test_" + std::to_string(getpid()));
  std::filesystem::remove_all(dir);
  CompareOptions options;
  options.quick = true;
  options.steps = 30;
  options.scenes = {"pyramid"};
  options.sections = {"recycling"};
  options.out_dir = dir.string();
  std::ostringstream out, err;
  ASSERT_EQ(cli::run_compare_command(options, out, err), 0) << err.str();

  const std::vector<PlottedPoint> points = plotted_points(dir / "recycling.gp");
  const auto drawn = [&](double x, double y) {
    for (const PlottedPoint& p : points) {
      // The data file has six significant digits, and gnuplot lists what it read.
      if (p.type == 'i' && std::abs(p.x - x) <= 1e-9 && std::abs(p.y - y) <= 1e-6 * std::abs(y)) {
        return true;
      }
    }
    return false;
  };
  std::ifstream data(dir / "recycling.dat");
  int rows = 0;
  for (std::string line; std::getline(data, line);) {
    std::istringstream fields(line);
    std::string scene;
    double distance = 0, narrowphase = 0, step = 0, kept = 0;
    if (!(fields >> scene >> distance >> narrowphase >> step >> kept)) continue;  // not a point
    ++rows;
    EXPECT_TRUE(drawn(distance, narrowphase)) << scene << " at " << distance << " mm: narrow phase";
    EXPECT_TRUE(drawn(distance, step)) << scene << " at " << distance << " mm: step";
    EXPECT_TRUE(drawn(distance, kept)) << scene << " at " << distance << " mm: kept error";
  }
  EXPECT_EQ(rows, 3) << "the quick sweep's three distances";
  if (!HasFailure()) std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace dyop::scenes
