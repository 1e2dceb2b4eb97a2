// `dyop stress`: numerical stability on hostile input, per runner, category and precision.
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "program/commands.hpp"
#include "report/output.hpp"
#include "report/stress_report.hpp"

namespace dyop::cli {
namespace {

struct StressArgs {
  std::string precision = "both";
  std::string json;
  std::string markdown;
  int pairs = experiments::StressOptions{}.pairs;
  std::uint64_t seed = experiments::StressOptions{}.seed;
  bool check = false;
};

int run(const StressArgs& args) {
  if (args.json == "-" && args.markdown == "-") {
    std::cerr << "dyop stress: --json and --markdown cannot both write to standard output\n";
    return exit_usage_error;
  }
  experiments::StressOptions options;
  options.pairs = args.pairs;
  options.seed = args.seed;
  options.run_double = args.precision != "float";
  options.run_float = args.precision != "double";
  const std::vector<experiments::StressRecord> records =
      experiments::run_stress(options, std::cerr);
  const std::vector<experiments::ConvexStressRecord> convex =
      experiments::run_convex_stress(options, std::cerr);
  // Standard output carries one thing: the tables, or what was asked for on "-".
  if (args.json != "-" && args.markdown != "-") {
    report::stress_records(records).write_table(std::cout);
    std::cout << "\nPairs beyond two triangles (dyop::collide, the exact solver):\n";
    report::convex_stress_records(convex).write_table(std::cout);
  }
  std::vector<report::Problem> problems;
  auto write = [&](const std::string& path, auto&& body) {
    if (path.empty()) return;
    if (std::optional<report::Problem> p = report::write_output(path, std::cout, body)) {
      std::cerr << "dyop stress: " << p->message << '\n';
      problems.push_back(*p);
    }
  };
  write(args.json, [&](std::ostream& o) {
    report::write_json_document(report::stress_records(records).json(), o);
  });
  write(args.markdown, [&](std::ostream& o) { report::write_markdown(records, o); });
  std::vector<std::string> broken = experiments::broken_promises(records);
  for (std::string& b : experiments::broken_convex_promises(convex)) broken.push_back(std::move(b));
  for (const std::string& b : broken) std::cerr << "dyop stress: broken promise: " << b << '\n';
  std::cerr << "dyop stress: " << records.size() + convex.size() << " records, "
            << (broken.empty() ? "every promise held"
                               : std::to_string(broken.size()) + " broken promises")
            << '\n';
  if (!problems.empty()) return exit_code_for(problems);
  return args.check && !broken.empty() ? exit_check_failed : exit_success;
}

}  // namespace

void add_stress_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<StressArgs>();
  CLI::App* cmd = app.add_subcommand(
      "stress",
      "Numerical stability on hostile input: error against the exact reference, NaN/inf, "
      "misclassifications and invariance violations per method, category and precision");
  cmd->add_option("--precision", args->precision, "Precision(s) to measure")
      ->check(CLI::IsMember({"double", "float", "both"}))
      ->capture_default_str();
  cmd->add_option("--json", args->json, "Write the records as JSON to FILE, or '-' for stdout");
  cmd->add_option("--markdown", args->markdown,
                  "Write the summary tables (docs/measurements.md) to FILE, or '-' for stdout");
  cmd->add_option("--pairs", args->pairs, "Pairs per category and precision")
      ->check(CLI::Range(1, 1000000))
      ->capture_default_str();
  cmd->add_option("--seed", args->seed, "Seed of the pairs and transformations")
      ->capture_default_str();
  cmd->add_flag("--check", args->check,
                "Exit with status 3 when a promise is broken (exactness of sat, dyop and batch; "
                "invariance of sat, dyop, epa and batch; no NaN/inf from the library, no lost "
                "row)");
  cmd->callback([args, &exit_code] { exit_code = run(*args); });
}

}  // namespace dyop::cli
