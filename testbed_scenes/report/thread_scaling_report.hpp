#pragma once
/// \file
/// The thread-scaling runs (`experiments/thread_scaling.hpp`) as `dyop bench` and `dyop compare`
/// report them: one description of the records (table, CSV, Markdown), each naming the machine.

#include <ostream>
#include <string>
#include <vector>

#include "experiments/thread_scaling.hpp"
#include "report/records.hpp"
#include "report/report_directory.hpp"

namespace dyop::report {

/// The records, column by column.
Records thread_scaling_records(const std::vector<experiments::ThreadScalingRecord>& records);

/// The aligned table printed by `dyop bench` and `dyop compare`, under a line naming the scene
/// and the machine.
void write_thread_scaling_table(const std::vector<experiments::ThreadScalingRecord>& records,
                                const std::string& scene, std::ostream& out);

/// The report's Markdown section (a `##` heading, what is measured, the table).
std::string thread_scaling_markdown(const std::vector<experiments::ThreadScalingRecord>& records,
                                    const std::string& scene);

/// Writes `threads.csv` in `dir` and returns `thread_scaling_markdown`.
std::string write_thread_scaling_outputs(
    const std::vector<experiments::ThreadScalingRecord>& records, const std::string& scene,
    ReportDirectory& dir);

}  // namespace dyop::report
