#pragma once
/// \file
/// The exit codes of the `dyop` program, the same for every subcommand.

#include <vector>

#include "report/problem.hpp"

namespace dyop::cli {

/// Success (`dyop pairs`: bad data lines are reported in the output, not in the exit code).
constexpr int exit_success = 0;
/// Usage error: CLI11's own, or a name or argument the command refuses.
constexpr int exit_usage_error = 1;
/// Input/output error: a file cannot be read or written, or a scene could not run.
constexpr int exit_io_error = 2;
/// `dyop stress --check`: a promise of the library was broken (the figures are still written).
constexpr int exit_check_failed = 3;

/// The exit code for what writing the outputs met: `exit_io_error` when a file or directory was
/// not written, else `exit_success` (a chart gnuplot did not draw is a warning, not a failure).
inline int exit_code_for(const std::vector<report::Problem>& problems) {
  return report::all_written(problems) ? exit_success : exit_io_error;
}

}  // namespace dyop::cli
