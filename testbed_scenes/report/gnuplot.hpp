#pragma once
/// \file
/// Charts for the reports: gnuplot (Debian `gnuplot-nox`) run as an external program on a script,
/// producing SVG, and the data files the scripts read. Every chart is drawn through
/// `ReportDirectory::chart` (`report/report_directory.hpp`), which quotes every path it names.

#include <initializer_list>
#include <limits>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "report/problem.hpp"

namespace dyop::report {

/// `text` as a gnuplot single-quoted string ('' stands for one quote inside).
std::string gnuplot_quote(const std::string& text);

/// Writes `script` to `script_path` (kept next to the chart, so that a reader can re-run or adapt
/// it) and runs gnuplot on it; the problem when the chart was not drawn (the script could not be
/// written: `NotWritten`; gnuplot missing or failing: `ChartNotDrawn`).
std::optional<Problem> run_gnuplot(const std::string& script, const std::string& script_path);

/// A missing figure in a chart's data file (written "NaN", gnuplot's missing value); in a table,
/// a figure not measured.
inline constexpr double missing_figure = std::numeric_limits<double>::quiet_NaN();

/// One line of a chart's data file: `label`, then each value with six significant digits, space
/// separated; a non-finite value is written "NaN", gnuplot's missing value.
void write_data_line(std::ostream& out, const std::string& label,
                     std::initializer_list<double> values);
/// The same with the values of a row of a table.
void write_data_line(std::ostream& out, const std::string& label,
                     const std::vector<double>& values);

}  // namespace dyop::report
