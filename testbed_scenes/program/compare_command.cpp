// `dyop compare`: the command (the run is scenes/compare and report/compare_section's sections,
// the report report/compare_report) and its registration.
#include "program/compare_command.hpp"

#include <fstream>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "dyop/box2d.hpp"
#include "program/commands.hpp"
#include "report/compare_report.hpp"
#include "report/compare_section.hpp"
#include "report/compare_summary.hpp"
#include "report/compare_tables.hpp"
#include "report/format.hpp"
#include "report/report_directory.hpp"
#include "scenes/runner.hpp"
#include "scenes/scene.hpp"

namespace dyop::cli {

// The command is about scenes throughout; their names read better unqualified.
using namespace dyop::scenes;
using namespace dyop::experiments;
using namespace dyop::report;

int run_compare_command(const CompareOptions& options, std::ostream& out, std::ostream& err) {
  // Fail before the long run if the report cannot be written (appending leaves a report there).
  const ReportDirectory dir(options.out_dir);
  if (!dir.created() || !std::ofstream(dir.path("report.md"), std::ios::app)) {
    const Problem p = dir.created() ? not_written(dir.path("report.md")) : dir.problems().front();
    err << "dyop compare: " << p.message << '\n';
    return exit_code_for({p});
  }
  Comparison comparison;
  try {
    comparison = run_comparison(options, err);
  } catch (const std::exception& e) {
    err << "dyop compare: " << e.what() << '\n';
    return exit_io_error;
  }
  for (const std::string& line : summary_lines(comparison)) out << line << '\n';
  out << '\n';
  write_compare_table(comparison.main, out);
  for (const auto& section : comparison.sections) {
    if (section->measured()) section->write_tables(out);
  }
  const std::vector<Problem> problems = write_report(comparison);
  for (const Problem& p : problems) {
    err << "dyop compare: " << (p.kind == ProblemKind::ChartNotDrawn ? "warning: " : "")
        << p.message << '\n';
  }
  out << "\nreport: " << options.out_dir << "/report.md (run took "
      << fmt("%.1f", comparison.seconds) << " s)\n";
  return exit_code_for(problems);
}

void add_compare_command(CLI::App& app, int& exit_code) {
  auto options = std::make_shared<experiments::CompareOptions>();
  auto steps = std::make_shared<int>(0);
  std::vector<std::string> names;
  for (const scenes::SceneInfo& s : scenes::scene_catalog()) names.push_back(s.name);
  CLI::App* cmd = app.add_subcommand(
      "compare",
      "Run every scene under every backend, and the skip section (pyramid, rain, tumbler, mixed "
      "with every skip off and on); print the tables and write a report (Markdown, CSV, SVG "
      "charts with gnuplot, scene snapshots)");
  cmd->add_flag("--quick", options->quick,
                "Short runs: 5 s of simulated time per Box2D scene (2 to 2.5 s for rain, "
                "rain-tall, tumbler and crowd), the main table under dyop and box2d, the in-world "
                "section under dyop, and without --section the skip, threads and recycling "
                "sections left out");
  cmd->add_option("--out", options->out_dir, "Report directory")->capture_default_str();
  CLI::Option* steps_option =
      cmd->add_option("--steps", *steps, "Steps of every scene (default: the catalogue's)")
          ->check(CLI::Range(1, 10000000));
  cmd->add_option("--seed", options->seed, "Seed of every scene")->capture_default_str();
  cmd->add_option("--scene", options->scenes, "Only these scenes (repeatable)")
      ->check(CLI::IsMember(names));
  cmd->add_option("--section", options->sections,
                  "Only these sections after the main table (repeatable; default: all)")
      ->check(CLI::IsMember(report::compare_section_names()));
  auto backends = std::make_shared<std::vector<std::string>>();
  cmd->add_option("--backend", *backends,
                  "Only these backends in the main table and the in-world section (repeatable; "
                  "default: every backend, with --quick dyop and box2d, and dyop in the in-world "
                  "section)")
      ->check(CLI::IsMember(scenes::runner_names(false)));
  auto skip = std::make_shared<std::string>("all");
  const std::string skip_help =
      scenes::skip_help() +
      "\n(every run of the main table; the skip section sets it against none)";
  cmd->add_option("--skip", *skip, skip_help)
      ->capture_default_str()
      ->check(CLI::Validator([](std::string& text) { return scenes::parse_skips(text).error; },
                             "all|none|LIST"));
  cmd->callback([options, steps, steps_option, backends, skip, &exit_code] {
    if (steps_option->count() > 0) options->steps = *steps;
    options->backends.clear();
    for (const std::string& b : *backends) options->backends.push_back(*box2d::parse_backend(b));
    options->skips = scenes::parse_skips(*skip).config;
    exit_code = run_compare_command(*options, std::cout, std::cerr);
  });
}

}  // namespace dyop::cli
