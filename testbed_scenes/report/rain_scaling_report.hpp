#pragma once
/// \file
/// The rain scene's scaling runs (`scenes/rain_scaling.hpp`) as `dyop bench` reports them: an
/// aligned table, a CSV, a chart and a Markdown section.

#include <ostream>
#include <string>
#include <vector>

#include "scenes/rain_scaling.hpp"

namespace dyop::scenes {

/// The aligned table printed by `dyop bench`.
void write_scaling_table(const std::vector<ScalingRecord>& records, std::ostream& out);

/// The CSV (header and one line per record).
void write_scaling_csv(const std::vector<ScalingRecord>& records, std::ostream& out);

/// Writes `dir/scaling.csv` and the chart `dir/rain_scaling.svg` (gnuplot, log–log: narrow-phase
/// and step time per step against falling triangles, one line per backend) and returns the
/// report's Markdown section (table and chart). Problems are appended to `problems`.
std::string write_scaling_outputs(const std::vector<ScalingRecord>& records,
                                  const std::string& dir, std::vector<std::string>& problems);

}  // namespace dyop::scenes
