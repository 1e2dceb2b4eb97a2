#include "program/pairs_command.hpp"

#include <algorithm>
#include <array>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "program/commands.hpp"
#include "program/pair_csv.hpp"
#include "report/format.hpp"
#include "report/output.hpp"
#include "workloads/batch_arrays.hpp"

namespace dyop::cli {
namespace {

// The CSV line in columns for the table: fields split on commas outside the quoted message.
void write_table_line(std::ostream& out, const std::string& method, const std::string& csv) {
  std::string cells[8];
  int k = 0;
  for (std::size_t i = 0; i < csv.size(); ++i) {
    if (k == 7) {
      cells[7] = csv.substr(i);
      break;
    }
    if (csv[i] == ',') {
      ++k;
    } else {
      cells[k] += csv[i];
    }
  }
  auto shorten = [](const std::string& s) {  // 9 digits are plenty for reading
    if (s.empty() || s.find_first_of("0123456789") == std::string::npos) return s;
    // strtod, not stod: stod throws on a subnormal (ERANGE), which is a valid answer here.
    return report::fmt("%.9g", std::strtod(s.c_str(), nullptr));
  };
  out << report::table_line("%5s  %-10s  %-6s  %7s  %16s  %16s  %16s  %16s  ", cells[0].c_str(),
                            method.c_str(), cells[1].c_str(), cells[2].c_str(),
                            shorten(cells[3]).c_str(), shorten(cells[4]).c_str(),
                            shorten(cells[5]).c_str(), shorten(cells[6]).c_str())
      << cells[7] << '\n';
}

// The batch kernel's answers (Level::Depth) for every data line of `lines` whose triangles are
// valid in precision T, all in one call, in line order; nothing for the other lines, and for every
// line when the kernel cannot run (`error`).
template <class T>
std::vector<std::optional<Result<double>>> batch_answers(const std::vector<PairLine>& lines,
                                                         BatchKernel kernel, BatchError& error) {
  std::vector<std::size_t> rows;  // the lines the kernel answers
  for (std::size_t k = 0; k < lines.size(); ++k) {
    if (lines[k].kind == PairLine::Kind::Data &&
        make_pair_triangles<T>(lines[k].values).message.empty()) {
      rows.push_back(k);
    }
  }
  workloads::BatchArrays<T> arrays(rows.size(), [&](std::size_t k, int side, int i) {
    const std::array<double, pair_fields>& v = lines[rows[k]].values;
    return Vec2<T>(static_cast<T>(v[6 * side + 2 * i]), static_cast<T>(v[6 * side + 2 * i + 1]));
  });
  std::vector<std::optional<Result<double>>> out(lines.size());
  error = penetrate_batch(arrays.pairs(), Level::Depth, arrays.out(), kernel);
  if (error != BatchError::None) return out;
  for (std::size_t k = 0; k < rows.size(); ++k) {
    Result<double> r;
    r.status = arrays.status[k];
    r.separation = arrays.separation[k];
    r.depth = r.status == Status::Separated ? 0.0 : std::max(0.0, -r.separation);
    r.normal = Vec2<double>(arrays.normal_x[k], arrays.normal_y[k]);
    out[rows[k]] = r;
  }
  return out;
}

}  // namespace

PairsSummary run_pairs(const PairsOptions& options, std::istream& in, std::ostream& out) {
  PairsSummary summary;
  const bool several = options.methods.size() > 1;
  if (options.table) {
    out << report::table_line("%5s  %-10s  %-6s  %7s  %16s  %16s  %16s  %16s  %s\n", "row",
                              "method", "status", "overlap", "depth", "separation", "nx", "ny",
                              "message");
  } else {
    out << (several ? "method," : "") << pair_csv_header() << '\n';
  }
  auto emit = [&](const PairMethod& method, const std::string& csv, bool ok) {
    ++summary.rows;
    ++(ok ? summary.ok : summary.errors);
    if (options.table) {
      write_table_line(out, method.name, csv);
    } else {
      out << (several ? method.name + "," : std::string()) << csv << '\n';
    }
  };

  // Every line first: the batch kernel answers the whole input in one call.
  std::vector<PairLine> lines;
  for (std::string text; std::getline(in, text);) lines.push_back(parse_pair_line(text));
  std::vector<std::optional<Result<double>>> batch[2];  // float, double
  BatchError batch_error[2] = {BatchError::None, BatchError::None};
  if (std::any_of(options.methods.begin(), options.methods.end(),
                  [](const PairMethod& m) { return m.batch(); })) {
    batch[0] = batch_answers<float>(lines, options.batch_kernel, batch_error[0]);
    if (!options.use_float) {
      batch[1] = batch_answers<double>(lines, options.batch_kernel, batch_error[1]);
    }
  }

  for (int row = 1; row <= static_cast<int>(lines.size()); ++row) {
    const PairLine& line = lines[row - 1];
    if (line.kind == PairLine::Kind::Skip) continue;
    if (line.kind == PairLine::Kind::Error) {
      for (const PairMethod& b : options.methods)
        emit(b, format_error_line(row, line.message), false);
      continue;
    }
    // Built once per precision: a float-only method runs in float even in a double run.
    const PairTriangles<double> in_double = make_pair_triangles<double>(line.values);
    const PairTriangles<float> in_float = make_pair_triangles<float>(line.values);
    for (const PairMethod& b : options.methods) {
      const bool use_float = options.use_float || (!b.batch() && b.run_double == nullptr);
      const std::string& message = use_float ? in_float.message : in_double.message;
      if (!message.empty()) {
        emit(b, format_error_line(row, message), false);
        continue;
      }
      if (b.batch()) {
        const int p = use_float ? 0 : 1;
        const std::optional<Result<double>>& r = batch[p][row - 1];
        if (r) {
          emit(b, format_result_line(row, *r), r->status != Status::Invalid);
        } else {
          emit(b, format_error_line(row, describe(batch_error[p])), false);
        }
        continue;
      }
      const Result<double> r = use_float
                                   ? widen(b.run_float(in_float.a.triangle, in_float.b.triangle,
                                                       Query<float>{Level::Depth}, nullptr))
                                   : b.run_double(in_double.a.triangle, in_double.b.triangle,
                                                  Query<double>{Level::Depth}, nullptr);
      emit(b, format_result_line(row, r), r.status != Status::Invalid);
    }
  }
  return summary;
}

// The subcommand: its arguments and file handling around run_pairs.
namespace {

struct PairsArgs {
  std::string method;
  std::string precision = "double";
  std::string input;
  std::string output;
  std::string format = "csv";
  std::string batch_kernel = "auto";
};

// The batch kernel spelt `s` (`name(BatchKernel)`), or nothing.
std::optional<BatchKernel> parse_batch_kernel(const std::string& s) {
  for (BatchKernel k : batch_kernels) {
    if (s == name(k)) return k;
  }
  return std::nullopt;
}

int run(const PairsArgs& args) {
  PairsOptions options;
  const std::optional<adapters::NarrowPhase> chosen =
      adapters::parse_narrow_phase(args.method);  // nothing: "all"
  for (const PairMethod& b : pairs_methods()) {
    if (!chosen || b.method == *chosen) options.methods.push_back(b);
  }
  options.use_float = args.precision == "float";
  options.table = args.format == "table";
  options.batch_kernel = *parse_batch_kernel(args.batch_kernel);  // checked by the option
  if (std::any_of(options.methods.begin(), options.methods.end(),
                  [](const PairMethod& m) { return m.batch(); })) {
    if (!batch_kernel_available(options.batch_kernel)) {
      std::cerr << "dyop pairs: batch kernel " << args.batch_kernel << ": "
                << describe(BatchError::KernelUnavailable) << '\n';
      return exit_usage_error;
    }
    std::cerr << "dyop pairs: batch kernel " << name(batch_kernel_used(options.batch_kernel))
              << '\n';
  }

  std::ifstream in_file;
  if (!args.input.empty() && args.input != "-") {
    in_file.open(args.input);
    if (!in_file) {
      std::cerr << "dyop pairs: cannot open input file '" << args.input << "'\n";
      return exit_io_error;
    }
  }
  report::Output output(args.output.empty() ? "-" : args.output, std::cout);
  if (const std::optional<report::Problem> p = output.open_problem()) {
    std::cerr << "dyop pairs: " << p->message << '\n';
    return exit_code_for({*p});
  }
  std::istream& in = in_file.is_open() ? static_cast<std::istream&>(in_file) : std::cin;
  const PairsSummary s = run_pairs(options, in, output.stream());
  const std::optional<report::Problem> written = output.close();
  if (in.bad() || written) {
    std::cerr << "dyop pairs: input/output error\n";
    return exit_io_error;
  }
  std::cerr << "dyop pairs: rows " << s.rows << ", ok " << s.ok << ", errors " << s.errors << '\n';
  return exit_success;
}

}  // namespace

void add_pairs_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<PairsArgs>();
  std::vector<std::string> methods{"all"};
  for (const PairMethod& b : pairs_methods()) methods.push_back(b.name);
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
  std::vector<std::string> kernels;
  for (BatchKernel k : batch_kernels) kernels.push_back(name(k));
  cmd->add_option("--batch-kernel", args->batch_kernel,
                  "The batch method's kernel: auto (the fastest here), portable, avx2 or avx512; "
                  "every kernel gives the same bits")
      ->check(CLI::IsMember(kernels))
      ->capture_default_str();
  cmd->callback([args, &exit_code] { exit_code = run(*args); });
}

}  // namespace dyop::cli
