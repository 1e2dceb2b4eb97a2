#pragma once
/// \file
/// Charts for the reports: gnuplot (Debian `gnuplot-nox`) run as an external program on a script
/// that the caller writes, producing SVG. Reports that cannot chart still write their tables.

#include <string>

namespace dyop::report {

/// What became of a chart.
struct ChartResult {
  bool ok = false;      ///< the SVG was written
  std::string message;  ///< why not, when `!ok` (gnuplot missing, gnuplot's error)
};

/// Runs gnuplot on `script` (which sets its own terminal and output). `script_path` is where the
/// script is kept next to the chart, so that a reader can re-run or adapt it.
ChartResult run_gnuplot(const std::string& script, const std::string& script_path);

}  // namespace dyop::report
