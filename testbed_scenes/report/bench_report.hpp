#pragma once
/// \file
/// `dyop bench`'s report: the records of `experiments/bench.hpp` as the aligned table, CSV, JSON,
/// the run-time-against-error chart and `report.md`.

#include <iosfwd>
#include <string>
#include <vector>

#include "experiments/bench.hpp"
#include "report/records.hpp"
#include "report/report_directory.hpp"

namespace dyop::report {

/// The records, column by column: the aligned table printed by `dyop bench`, `bench.csv`,
/// `bench.json` (every field of `BenchRecord`; a non-finite figure is null) and the Markdown
/// table.
Records bench_records(const std::vector<experiments::BenchRecord>& records);

/// `report.md`, `bench.csv`, `bench.json` and the chart `time_vs_error.svg` in `dir` (gnuplot;
/// log–log, one point per method at the Depth level, Pareto front drawn); `sections` (Markdown,
/// e.g. the scaling section) is appended to the report. What was not written is in
/// `dir.problems()`.
void write_outputs(const std::vector<experiments::BenchRecord>& records, ReportDirectory& dir,
                   const std::string& sections = {});

}  // namespace dyop::report
