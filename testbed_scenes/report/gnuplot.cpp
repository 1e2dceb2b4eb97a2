#include "report/gnuplot.hpp"

#include <cstdlib>
#include <fstream>

#include "report/format.hpp"

namespace dyop::report {
namespace {

// `text` as one word of the shell, single-quoted ('\'' stands for one quote inside).
std::string shell_quote(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

template <class Values>
void write_line(std::ostream& out, const std::string& label, const Values& values) {
  out << label;
  for (double v : values) out << ' ' << (std::isfinite(v) ? fmt("%.6g", v) : "NaN");
  out << '\n';
}

}  // namespace

std::string gnuplot_quote(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("''") : std::string(1, c);
  return out + "'";
}

std::optional<Problem> run_gnuplot(const std::string& script, const std::string& script_path) {
  {
    std::ofstream file(script_path);
    file << script;
    if (!file) return not_written(script_path);
  }
  if (std::system("command -v gnuplot >/dev/null 2>&1") != 0) {
    return Problem{
        ProblemKind::ChartNotDrawn,
        "gnuplot not found (Debian package gnuplot-nox): chart skipped, script kept at " +
            script_path};
  }
  const std::string command = "gnuplot " + shell_quote(script_path) + " 2>&1";
  if (std::system(command.c_str()) != 0) {
    return Problem{ProblemKind::ChartNotDrawn, "gnuplot failed on " + script_path};
  }
  return std::nullopt;
}

void write_data_line(std::ostream& out, const std::string& label,
                     std::initializer_list<double> values) {
  write_line(out, label, values);
}

void write_data_line(std::ostream& out, const std::string& label,
                     const std::vector<double>& values) {
  write_line(out, label, values);
}

}  // namespace dyop::report
