#pragma once
/// \file
/// The "Contact streams" section of `dyop bench`: per scene, the recorded stream's size and
/// every runner's time per call, its ratio to `b2CollidePolygons` (box2d-own) in the same run and
/// its agreement with it (`scenes/contact_stream.hpp`).

#include <iosfwd>
#include <string>
#include <vector>

#include "report/report_directory.hpp"
#include "scenes/contact_stream.hpp"

namespace dyop::report {

/// The aligned table printed by `dyop bench`: one line per scene and runner; `world%` is the
/// calls' share of the world's evaluations, `count!=` and `face!=` the calls that disagree with
/// `b2CollidePolygons` on the point count and on the reference face.
void write_stream_table(const std::vector<scenes::StreamResult>& results, std::ostream& out);

/// The CSV (header and one line per scene and runner).
void write_stream_csv(const std::vector<scenes::StreamResult>& results, std::ostream& out);

/// Writes `streams.csv` and the chart `streams.svg` in `dir` (gnuplot: ratio to box2d-own per
/// scene, one bar per backend) and returns the report's Markdown section. Problems go to
/// `dir.problems()`.
std::string write_stream_outputs(const std::vector<scenes::StreamResult>& results,
                                 ReportDirectory& dir);

}  // namespace dyop::report
