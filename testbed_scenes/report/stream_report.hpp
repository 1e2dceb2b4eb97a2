#pragma once
/// \file
/// The "Contact streams" section of `dyop bench`: per scene, the recorded stream's size and
/// every runner's time per call, its ratio to `b2CollidePolygons` (box2d-own) in the same run and
/// its agreement with it (`scenes/contact_stream.hpp`).

#include <iosfwd>
#include <string>
#include <vector>

#include "scenes/contact_stream.hpp"

namespace dyop::report {

/// The aligned table printed by `dyop bench`: one line per scene and runner; `world%` is the
/// calls' share of the world's evaluations, `count!=` and `face!=` the calls that disagree with
/// `b2CollidePolygons` on the point count and on the reference face.
void write_stream_table(const std::vector<scenes::StreamResult>& results, std::ostream& out);

/// The CSV (header and one line per scene and runner).
void write_stream_csv(const std::vector<scenes::StreamResult>& results, std::ostream& out);

/// Writes `dir/streams.csv` and the chart `dir/streams.svg` (gnuplot: ratio to box2d-own per
/// scene, one bar per backend) and returns the report's Markdown section. Problems are appended
/// to `problems`.
std::string write_stream_outputs(const std::vector<scenes::StreamResult>& results,
                                 const std::string& dir, std::vector<std::string>& problems);

}  // namespace dyop::report
