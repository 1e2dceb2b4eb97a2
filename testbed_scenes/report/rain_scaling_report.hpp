#pragma once
/// \file
/// The rain scene's scaling runs (`experiments/rain_scaling.hpp`) as `dyop bench` reports them:
/// one description of the records (aligned table, CSV, Markdown), a chart and a section.

#include <string>
#include <vector>

#include "report/records.hpp"
#include "report/report_directory.hpp"
#include "experiments/rain_scaling.hpp"

namespace dyop::report {

/// The records, column by column (the aligned table printed by `dyop bench`, the CSV, the
/// Markdown table).
Records scaling_records(const std::vector<experiments::ScalingRecord>& records);

/// Writes `scaling.csv` and the chart `rain_scaling.svg` in `dir` (gnuplot, log–log: narrow-phase
/// and step time per step against falling triangles, one line per backend) and returns the
/// report's Markdown section (table and chart). Problems go to `dir.problems()`.
std::string write_scaling_outputs(const std::vector<experiments::ScalingRecord>& records,
                                  ReportDirectory& dir);

}  // namespace dyop::report
