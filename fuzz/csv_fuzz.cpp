// libFuzzer target for the pair CSV reader and `dyop pairs`' processing (program/pair_csv.hpp,
// program/pairs_command.hpp): any bytes as the input file, every method, both precisions, CSV
// and table.
//
// What it asserts, besides "no crash, no sanitizer report" (and no Box2D assert: the plug-in's
// `collide_triangles` runs on whatever the reader accepts):
// - one output line per method and input line that is not blank or a comment, in input order,
//   after one header line; the summary counts them;
// - each is `ok` or an `error` with a non-empty message;
// - an `ok` line of a library method has no NaN or inf (Box2D's own answers are measured by
//   `dyop stress`, not promised).
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>

#include "program/pair_csv.hpp"
#include "program/pairs_command.hpp"

namespace dyop::fuzz {
namespace {

[[noreturn]] void fail(const std::string& what, const std::string& line) {
  std::fprintf(stderr, "csv: %s: '%s'\n", what.c_str(), line.c_str());
  std::abort();
}

int data_lines(const std::string& text) {
  std::istringstream in(text);
  int n = 0;
  for (std::string line; std::getline(in, line);) {
    n += cli::parse_pair_line(line).kind != cli::PairLine::Kind::Skip;
  }
  return n;
}

void check_csv(const std::string& text, bool use_float) {
  cli::PairsOptions options;
  options.methods = cli::pairs_methods();
  options.use_float = use_float;
  std::istringstream in(text);
  std::ostringstream out;
  const cli::PairsSummary s = cli::run_pairs(options, in, out);
  const int methods = static_cast<int>(options.methods.size());
  const int expected = data_lines(text) * methods;
  if (s.rows != expected || s.ok + s.errors != s.rows)
    fail("summary does not count every line", "");
  std::istringstream lines(out.str());
  std::string line;
  std::getline(lines, line);
  if (line != std::string("method,") + cli::pair_csv_header()) fail("bad header", line);
  int count = 0;
  int last_row = 0;
  for (; std::getline(lines, line); ++count) {
    const std::size_t c1 = line.find(',');
    const std::size_t c2 = line.find(',', c1 + 1);
    const std::size_t c3 = line.find(',', c2 + 1);
    if (c1 == std::string::npos || c2 == std::string::npos || c3 == std::string::npos) {
      fail("malformed output line", line);
    }
    const std::string method = line.substr(0, c1);
    const int row = std::atoi(line.substr(c1 + 1, c2 - c1 - 1).c_str());
    const std::string status = line.substr(c2 + 1, c3 - c2 - 1);
    if (row < last_row) fail("rows out of input order", line);
    last_row = row;
    if (status == "error") {
      if (line.size() < c3 + 10 || line.find('"', c3) == std::string::npos)
        fail("error without a message", line);
      continue;
    }
    if (status != "ok") fail("status neither ok nor error", line);
    if (method != "box2d" &&
        (line.find("nan") != std::string::npos || line.find("inf") != std::string::npos)) {
      fail("NaN or inf in an ok line", line);
    }
  }
  if (count != expected) fail("an input line was lost or doubled", std::to_string(count));
}

void check_table(const std::string& text) {
  cli::PairsOptions options;
  options.methods = cli::pairs_methods();
  options.table = true;
  std::istringstream in(text);
  std::ostringstream out;
  const cli::PairsSummary s = cli::run_pairs(options, in, out);
  if (s.rows != data_lines(text) * static_cast<int>(options.methods.size())) {
    fail("table summary does not count every line", "");
  }
}

}  // namespace
}  // namespace dyop::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  dyop::fuzz::check_csv(text, false);
  dyop::fuzz::check_csv(text, true);
  dyop::fuzz::check_table(text);
  return 0;
}
