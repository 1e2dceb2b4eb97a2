// `dyop bench`: run time against error, printed, and optionally written as JSON and a report;
// with Box2D, also the rain scene's scaling with the number of triangles.
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "program/commands.hpp"
#include "report/bench_report.hpp"
#include "report/machine.hpp"
#include "report/output.hpp"
#ifdef DYOP_WITH_BOX2D
#include "report/bench_sections.hpp"
#endif

namespace dyop::cli {
namespace {

struct BenchArgs {
  bool quick = false;
  bool no_scaling = false;
  bool no_streams = false;
  bool no_threads = false;
  std::string json;
  std::string out;
};

// Steps of each scaling run: 10 s of simulated time (falling, landing and resting), 4 s quick
// (the tallest grid, 57 m, has just landed).
constexpr int kScalingSteps = 600;
constexpr int kQuickScalingSteps = 240;
// Contact streams: 2 s of simulated time quick (dropped bodies mostly still falling, the resting
// structures already resting) and 3 timed passes, so that the section stays under a minute.
constexpr int kQuickStreamSteps = 120;
constexpr int kQuickStreamPasses = 3;
// Worlds on threads: 10 s of the rain per world (falling, landing, resting: about 0.7 s of wall
// time per world), 5 runs of each runner, about 40 s in all; quick, 2 s and 3 runs (5 s).
constexpr int kThreadSteps = 600;
constexpr int kThreadRuns = 5;
constexpr int kQuickThreadSteps = 120;
constexpr int kQuickThreadRuns = 3;

int run(const BenchArgs& args) {
  experiments::BenchOptions options;
  options.quick = args.quick;
  // With `--json -` standard output carries the JSON alone; the tables go to standard error.
  std::ostream& tables = args.json == "-" ? std::cerr : std::cout;
  const std::vector<experiments::BenchRecord> records = experiments::run_bench(options, std::cerr);
  tables << "Measured on " << report::machine_description() << " ("
         << report::batch_kernel_description() << "):\n";
  report::bench_records(records).write_table(tables);
  std::string sections;  // the report's scaling and streams sections
  // Created before the sections write into it; when it cannot be, its first problem says so.
  std::optional<report::ReportDirectory> dir;
  if (!args.out.empty()) dir.emplace(args.out);
#ifdef DYOP_WITH_BOX2D
  if (!args.no_scaling) {
    experiments::ScalingOptions scaling;
    scaling.steps = args.quick ? kQuickScalingSteps : kScalingSteps;
    const std::vector<experiments::ScalingRecord> rain =
        experiments::run_rain_scaling(scaling, std::cerr);
    tables << '\n';
    report::scaling_records(rain).write_table(tables);
    if (dir && dir->created()) sections = report::write_scaling_outputs(rain, *dir);
  }
  if (!args.no_threads) {
    experiments::ThreadScalingOptions threads;
    threads.steps = args.quick ? kQuickThreadSteps : kThreadSteps;
    threads.runs = args.quick ? kQuickThreadRuns : kThreadRuns;
    const std::vector<experiments::ThreadScalingRecord> pool =
        experiments::run_thread_scaling(threads, std::cerr);
    tables << '\n';
    report::write_thread_scaling_table(pool, threads.scene, tables);
    if (dir && dir->created()) {
      sections += report::write_thread_scaling_outputs(pool, threads.scene, *dir);
    }
  }
  if (!args.no_streams) {
    experiments::StreamOptions streams;
    if (args.quick) {
      streams.steps = kQuickStreamSteps;
      streams.passes = kQuickStreamPasses;
    }
    const std::vector<experiments::StreamResult> results =
        experiments::run_streams(streams, std::cerr);
    tables << '\n';
    report::stream_records(results).write_table(tables);
    if (dir && dir->created()) sections += report::write_stream_outputs(results, *dir);
  }
#endif
  if (!args.json.empty()) {
    const std::optional<report::Problem> problem =
        report::write_output(args.json, std::cout, [&](std::ostream& o) {
          report::write_json_document(report::bench_records(records).json(), o);
        });
    if (problem) {
      std::cerr << "dyop bench: " << problem->message << '\n';
      return exit_code_for({*problem});
    }
  }
  if (dir) {
    report::write_outputs(records, *dir, sections);
    for (const report::Problem& p : dir->problems())
      std::cerr << "dyop bench: " << p.message << '\n';
    std::cerr << "dyop bench: report in " << args.out << "/report.md\n";
    return exit_code_for(dir->problems());
  }
  return exit_success;
}

}  // namespace

void add_bench_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<BenchArgs>();
  CLI::App* cmd = app.add_subcommand(
      "bench", "Run time against error of every method, with ratios to Box2D's narrow phase");
  cmd->add_flag("--quick", args->quick,
                "Fewer timed passes (5 instead of 21), shorter scaling runs (4 s, not 10 s), "
                "worlds on threads (2 s, 3 runs) and contact streams (120 steps, not 600)");
  cmd->add_flag("--no-scaling", args->no_scaling,
                "Skip the rain scene's scaling runs (100 to 3000 triangles per backend)");
  cmd->add_flag("--no-streams", args->no_streams,
                "Skip the contact streams (every Box2D scene's recorded narrow-phase calls, "
                "replayed through every backend)");
  cmd->add_flag("--no-threads", args->no_threads,
                "Skip the worlds on threads (1, 2, 4 copies of the rain on as many threads, "
                "dyop against Box2D's own contact)");
  cmd->add_option("--json", args->json, "Write the records as JSON to FILE, or '-' for stdout");
  cmd->add_option("--out", args->out,
                  "Write report.md, bench.csv, bench.json, scaling.csv, threads.csv, streams.csv "
                  "and the charts here");
  cmd->callback([args, &exit_code] { exit_code = run(*args); });
}

}  // namespace dyop::cli
