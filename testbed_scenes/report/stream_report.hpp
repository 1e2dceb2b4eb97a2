#pragma once
/// \file
/// The "Contact streams" section of `dyop bench`: per scene, the recorded stream's size and
/// every runner's time per call, its ratio to `b2CollidePolygons` (box2d-own) in the same run and
/// its agreement with it (`experiments/contact_stream.hpp`).

#include <string>
#include <vector>

#include "report/records.hpp"
#include "report/report_directory.hpp"
#include "experiments/contact_stream.hpp"

namespace dyop::report {

/// The records, column by column, one per scene and runner (the aligned table printed by `dyop
/// bench`, the CSV, the Markdown table): `world%` is the calls' share of the world's
/// evaluations, `count!=` and `face!=` the calls that disagree with `b2CollidePolygons` on the
/// point count and on the reference face.
Records stream_records(const std::vector<experiments::StreamResult>& results);

/// Writes `streams.csv` and the chart `streams.svg` in `dir` (gnuplot: ratio to box2d-own per
/// scene, one bar per backend) and returns the report's Markdown section. Problems go to
/// `dir.problems()`.
std::string write_stream_outputs(const std::vector<experiments::StreamResult>& results,
                                 ReportDirectory& dir);

}  // namespace dyop::report
