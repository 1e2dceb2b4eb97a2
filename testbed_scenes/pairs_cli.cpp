// `dyop pairs`: registration of the subcommand and its file handling.
#include <fstream>
#include <iostream>
#include <memory>
#include <string>

#include "commands.hpp"
#include "pairs_command.hpp"

namespace dyop::cli {
namespace {

struct PairsArgs {
  std::string method;
  std::string precision = "double";
  std::string input;
  std::string output;
  std::string format = "csv";
};

int run(const PairsArgs& args) {
  PairsOptions options;
  for (const PairBackend& b : pair_backends()) {
    if (args.method == "all" || args.method == b.name) options.backends.push_back(b);
  }
  options.use_float = args.precision == "float";
  options.table = args.format == "table";

  std::ifstream in_file;
  if (!args.input.empty() && args.input != "-") {
    in_file.open(args.input);
    if (!in_file) {
      std::cerr << "dyop pairs: cannot open input file '" << args.input << "'\n";
      return exit_io_error;
    }
  }
  std::ofstream out_file;
  if (!args.output.empty() && args.output != "-") {
    out_file.open(args.output);
    if (!out_file) {
      std::cerr << "dyop pairs: cannot open output file '" << args.output << "'\n";
      return exit_io_error;
    }
  }
  std::istream& in = in_file.is_open() ? static_cast<std::istream&>(in_file) : std::cin;
  std::ostream& out = out_file.is_open() ? static_cast<std::ostream&>(out_file) : std::cout;
  const PairsSummary s = run_pairs(options, in, out);
  out.flush();
  if (in.bad() || !out) {
    std::cerr << "dyop pairs: input/output error\n";
    return exit_io_error;
  }
  std::cerr << "dyop pairs: rows " << s.rows << ", ok " << s.ok << ", errors " << s.errors << '\n';
  return 0;
}

}  // namespace

void add_pairs_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<PairsArgs>();
  std::vector<std::string> methods{"all"};
  for (const PairBackend& b : pair_backends()) methods.push_back(b.name);
  CLI::App* cmd = app.add_subcommand(
      "pairs",
      "Penetration depth of triangle pairs read as CSV (ax,ay,bx,by,cx,cy,px,py,qx,qy,rx,ry)");
  cmd->add_option("--method,-m", args->method, "Method, or 'all'")
      ->required()
      ->check(CLI::IsMember(methods));
  cmd->add_option("--precision", args->precision, "Scalar type")
      ->check(CLI::IsMember({"double", "float"}))
      ->capture_default_str();
  cmd->add_option("--input,-i", args->input, "Input CSV file (default: standard input)");
  cmd->add_option("--output,-o", args->output, "Output file (default: standard output)");
  cmd->add_option("--format", args->format, "csv: the contract; table: aligned columns to read")
      ->check(CLI::IsMember({"csv", "table"}))
      ->capture_default_str();
  cmd->callback([args, &exit_code] { exit_code = run(*args); });
}

}  // namespace dyop::cli
