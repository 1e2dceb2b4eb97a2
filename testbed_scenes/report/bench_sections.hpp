#pragma once
/// \file
/// The sections of `dyop bench` beyond its main table, each the records of one experiment as one
/// description of their columns (`report/records.hpp`: the aligned table printed by `dyop bench`,
/// the CSV, the Markdown table), plus the section's chart and Markdown. Each `write_*_outputs`
/// writes the section's files in `dir` (what could not be written goes to `dir.problems()`) and
/// returns its part of `report.md`. One source file each: `rain_scaling_report.cpp`,
/// `stream_report.cpp`, `thread_scaling_report.cpp`.

#include <ostream>
#include <string>
#include <vector>

#include "experiments/contact_stream.hpp"
#include "experiments/rain_scaling.hpp"
#include "experiments/thread_scaling.hpp"
#include "report/records.hpp"
#include "report/report_directory.hpp"

namespace dyop::report {

/// The rain scene's scaling runs (`experiments/rain_scaling.hpp`), one record per runner and
/// size.
Records scaling_records(const std::vector<experiments::ScalingRecord>& records);

/// `scaling.csv` and the chart `rain_scaling.svg` (gnuplot, log–log: narrow-phase and step time
/// per step against falling triangles, one line per runner).
std::string write_scaling_outputs(const std::vector<experiments::ScalingRecord>& records,
                                  ReportDirectory& dir);

/// The contact streams (`experiments/contact_stream.hpp`): per scene, the recorded stream's size
/// and every runner's time per call, its ratio to `b2CollidePolygons` (box2d-own) in the same run
/// and its agreement with it: `world%` is the calls' share of the world's evaluations, `count!=`
/// and `face!=` the calls that disagree with `b2CollidePolygons` on the point count and on the
/// reference face.
Records stream_records(const std::vector<experiments::StreamResult>& results);

/// `streams.csv` and the chart `streams.svg` (gnuplot: ratio to box2d-own per scene, one bar per
/// backend).
std::string write_stream_outputs(const std::vector<experiments::StreamResult>& results,
                                 ReportDirectory& dir);

/// Worlds on threads (`experiments/thread_scaling.hpp`), one record per runner and thread count;
/// also a section of `dyop compare`.
Records thread_scaling_records(const std::vector<experiments::ThreadScalingRecord>& records);

/// The aligned table under a line naming the scene and the machine.
void write_thread_scaling_table(const std::vector<experiments::ThreadScalingRecord>& records,
                                const std::string& scene, std::ostream& out);

/// The section's Markdown (a `##` heading, what is measured and on which machine, the table).
std::string thread_scaling_markdown(const std::vector<experiments::ThreadScalingRecord>& records,
                                    const std::string& scene);

/// `threads.csv`; returns `thread_scaling_markdown`.
std::string write_thread_scaling_outputs(
    const std::vector<experiments::ThreadScalingRecord>& records, const std::string& scene,
    ReportDirectory& dir);

}  // namespace dyop::report
