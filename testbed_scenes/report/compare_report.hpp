#pragma once
/// \file
/// The report directory of `dyop compare` (`scenes/compare.hpp`'s run): `report.md`, the CSVs
/// behind it (`compare_csv.cpp`), the gnuplot charts (`compare_charts.cpp`) and a snapshot of each
/// scene.

#include <string>
#include <vector>

#include "scenes/compare.hpp"

namespace dyop::scenes {

/// What became of the report.
struct ReportOutcome {
  std::vector<std::string> errors;    ///< files that could not be written (report.md, CSVs, SVGs)
  std::vector<std::string> warnings;  ///< charts not drawn (gnuplot missing or failing)
};

/// Writes the report directory (created if needed): the tables, CSVs and snapshots whatever
/// happens to the charts.
ReportOutcome write_report(const CompareRun& run);

}  // namespace dyop::scenes
