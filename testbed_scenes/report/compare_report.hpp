#pragma once
/// \file
/// The report directory of `dyop compare` (`report/compare_section.hpp`'s `Comparison`):
/// `report.md` (`compare_markdown.cpp`), `compare.csv`, the main table's charts
/// (`compare_charts.cpp`), a snapshot of each scene, and every section's files.

#include <vector>

#include "report/compare_section.hpp"
#include "report/problem.hpp"

namespace dyop::report {

/// Writes the report directory (`options.out_dir`, created if needed): the tables, CSVs and
/// snapshots whatever happens to the charts. Returns the problems met (none when all was written
/// and drawn).
std::vector<Problem> write_report(const Comparison& comparison);

}  // namespace dyop::report
