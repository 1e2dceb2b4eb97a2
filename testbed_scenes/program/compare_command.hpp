#pragma once
/// \file
/// `dyop compare [--quick] [--out DIR] [--skip all|none|LIST]`: every scene under every backend
/// (`experiments/compare.hpp`), the tables printed and the report written
/// (`report/compare_report.hpp`).

#include <iosfwd>

#include "experiments/compare.hpp"

namespace dyop::cli {

/// The whole command: checks that the directory is writable first (`exit_io_error` if not), runs,
/// prints the tables to `out` and progress and problems to `err`, writes the report and says
/// where. Returns `exit_success`, or `exit_io_error` when the run or a report file failed.
int run_compare_command(const experiments::CompareOptions& options, std::ostream& out,
                        std::ostream& err);

}  // namespace dyop::cli
