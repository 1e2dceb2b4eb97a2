// `dyop bench`: run time against error, printed, and optionally written as JSON and a report.
#include <fstream>
#include <iostream>
#include <memory>
#include <string>

#include "commands.hpp"
#include "report/bench_report.hpp"

namespace dyop::cli {
namespace {

struct BenchArgs {
  bool quick = false;
  std::string json;
  std::string out;
};

int run(const BenchArgs& args) {
  report::BenchOptions options;
  options.quick = args.quick;
  const std::vector<report::BenchRecord> records = report::run_bench(options, std::cerr);
  report::write_table(records, std::cout);
  if (!args.json.empty()) {
    if (args.json == "-") {
      report::write_json(records, std::cout);
    } else {
      std::ofstream file(args.json);
      report::write_json(records, file);
      if (!file) {
        std::cerr << "dyop bench: cannot write '" << args.json << "'\n";
        return exit_io_error;
      }
    }
  }
  if (!args.out.empty()) {
    const std::vector<std::string> problems = report::write_outputs(records, args.out);
    for (const std::string& p : problems) std::cerr << "dyop bench: " << p << '\n';
    std::cerr << "dyop bench: report in " << args.out << "/report.md\n";
    if (!problems.empty() && problems.front().rfind("cannot", 0) == 0) return exit_io_error;
  }
  return 0;
}

}  // namespace

void add_bench_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<BenchArgs>();
  CLI::App* cmd = app.add_subcommand(
      "bench", "Run time against error of every method, with ratios to Box2D's narrow phase");
  cmd->add_flag("--quick", args->quick, "Fewer timed passes (5 instead of 21)");
  cmd->add_option("--json", args->json, "Write the records as JSON to FILE, or '-' for stdout");
  cmd->add_option("--out", args->out, "Write report.md, bench.csv, bench.json and the chart here");
  cmd->callback([args, &exit_code] { exit_code = run(*args); });
}

}  // namespace dyop::cli
