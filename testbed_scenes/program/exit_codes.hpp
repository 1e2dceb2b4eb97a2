#pragma once
/// \file
/// The exit codes of the `dyop` program, the same for every subcommand.

namespace dyop::cli {

/// Success (`dyop pairs`: bad data lines are reported in the output, not in the exit code).
constexpr int exit_success = 0;
/// Usage error: CLI11's own, or a name or argument the command refuses.
constexpr int exit_usage_error = 1;
/// Input/output error: a file cannot be read or written, or a scene could not run.
constexpr int exit_io_error = 2;
/// `dyop stress --check`: a promise of the library was broken (the figures are still written).
constexpr int exit_check_failed = 3;

}  // namespace dyop::cli
