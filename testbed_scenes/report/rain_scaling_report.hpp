#pragma once
/// \file
/// The rain scene's scaling runs (`scenes/rain_scaling.hpp`) as `dyop bench` reports them: an
/// aligned table, a CSV, a chart and a Markdown section.

#include <ostream>
#include <string>
#include <vector>

#include "report/report_directory.hpp"
#include "scenes/rain_scaling.hpp"

namespace dyop::report {

/// The aligned table printed by `dyop bench`.
void write_scaling_table(const std::vector<scenes::ScalingRecord>& records, std::ostream& out);

/// The CSV (header and one line per record).
void write_scaling_csv(const std::vector<scenes::ScalingRecord>& records, std::ostream& out);

/// Writes `scaling.csv` and the chart `rain_scaling.svg` in `dir` (gnuplot, log–log: narrow-phase
/// and step time per step against falling triangles, one line per backend) and returns the
/// report's Markdown section (table and chart). Problems go to `dir.problems()`.
std::string write_scaling_outputs(const std::vector<scenes::ScalingRecord>& records,
                                  ReportDirectory& dir);

}  // namespace dyop::report
