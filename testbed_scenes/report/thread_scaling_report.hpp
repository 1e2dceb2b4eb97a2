#pragma once
/// \file
/// The thread-scaling runs (`scenes/thread_scaling.hpp`) as `dyop bench` reports them: an aligned
/// table, a CSV and a Markdown section, each naming the machine.

#include <ostream>
#include <string>
#include <vector>

#include "report/report_directory.hpp"
#include "scenes/thread_scaling.hpp"

namespace dyop::report {

/// The aligned table printed by `dyop bench`, under a line naming the machine and the scene.
void write_thread_scaling_table(const std::vector<scenes::ThreadScalingRecord>& records,
                                const std::string& scene, std::ostream& out);

/// The CSV (header and one line per record).
void write_thread_scaling_csv(const std::vector<scenes::ThreadScalingRecord>& records,
                              std::ostream& out);

/// The report's Markdown section (a `##` heading, what is measured, the table).
std::string thread_scaling_markdown(const std::vector<scenes::ThreadScalingRecord>& records,
                                    const std::string& scene);

/// Writes `threads.csv` in `dir` and returns `thread_scaling_markdown`.
std::string write_thread_scaling_outputs(const std::vector<scenes::ThreadScalingRecord>& records,
                                         const std::string& scene, ReportDirectory& dir);

}  // namespace dyop::report
