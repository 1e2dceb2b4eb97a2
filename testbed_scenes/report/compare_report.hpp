#pragma once
/// \file
/// The report directory of `dyop compare` (`scenes/compare.hpp`'s run): `report.md`
/// (`compare_markdown.cpp`), the CSVs behind it (`compare_csv.cpp`), the gnuplot charts
/// (`compare_charts.cpp`) and a snapshot of each scene.

#include <vector>

#include "report/problem.hpp"
#include "scenes/compare.hpp"

namespace dyop::report {

/// Writes the report directory (`run.options.out_dir`, created if needed): the tables, CSVs and
/// snapshots whatever happens to the charts. Returns the problems met (none when all was written
/// and drawn).
std::vector<Problem> write_report(const scenes::CompareRun& run);

}  // namespace dyop::report
