// The `dyop` command-line program: subcommands over the solver, the Box2D bridge and the scenes.
#include <CLI/CLI.hpp>

#include <fstream>
#include <iostream>
#include <string>

#include "pairs_command.hpp"

namespace {

// Exit codes: 0 success (bad data lines are reported in the output, not in the exit code),
// 1 usage error (CLI11's own), 2 input/output error.
constexpr int kIoError = 2;

int pairs_main(const std::string& method, const std::string& precision, const std::string& input,
               const std::string& output, const std::string& format) {
  using namespace dyop::cli;
  PairsOptions options;
  for (const PairBackend& b : pair_backends()) {
    if (method == "all" || method == b.name) options.backends.push_back(b);
  }
  options.use_float = precision == "float";
  options.table = format == "table";

  std::ifstream in_file;
  if (!input.empty() && input != "-") {
    in_file.open(input);
    if (!in_file) {
      std::cerr << "dyop pairs: cannot open input file '" << input << "'\n";
      return kIoError;
    }
  }
  std::ofstream out_file;
  if (!output.empty() && output != "-") {
    out_file.open(output);
    if (!out_file) {
      std::cerr << "dyop pairs: cannot open output file '" << output << "'\n";
      return kIoError;
    }
  }
  std::istream& in = in_file.is_open() ? static_cast<std::istream&>(in_file) : std::cin;
  std::ostream& out = out_file.is_open() ? static_cast<std::ostream&>(out_file) : std::cout;
  const PairsSummary s = run_pairs(options, in, out);
  out.flush();
  if (in.bad() || !out) {
    std::cerr << "dyop pairs: input/output error\n";
    return kIoError;
  }
  std::cerr << "dyop pairs: rows " << s.rows << ", ok " << s.ok << ", errors " << s.errors << '\n';
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"DyOP-PD: penetration depth and contacts of 2D triangles"};
  app.require_subcommand(1);

  std::vector<std::string> methods{"all"};
  for (const auto& b : dyop::cli::pair_backends()) methods.push_back(b.name);
  std::string method;
  std::string precision = "double";
  std::string input;
  std::string output;
  std::string format = "csv";
  CLI::App* pairs = app.add_subcommand(
      "pairs", "Penetration depth of triangle pairs read as CSV (ax,ay,bx,by,cx,cy,px,py,qx,qy,rx,ry)");
  pairs->add_option("--method,-m", method, "Method, or 'all'")
      ->required()
      ->check(CLI::IsMember(methods));
  pairs->add_option("--precision", precision, "Scalar type")
      ->check(CLI::IsMember({"double", "float"}))
      ->capture_default_str();
  pairs->add_option("--input,-i", input, "Input CSV file (default: standard input)");
  pairs->add_option("--output,-o", output, "Output file (default: standard output)");
  pairs->add_option("--format", format, "csv: the contract; table: aligned columns to read")
      ->check(CLI::IsMember({"csv", "table"}))
      ->capture_default_str();

  CLI11_PARSE(app, argc, argv);
  if (pairs->parsed()) return pairs_main(method, precision, input, output, format);
  return 0;
}
