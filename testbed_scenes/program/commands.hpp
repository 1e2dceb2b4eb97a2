#pragma once
// The subcommands of the `dyop` program: each file registers its own with CLI11; its callback
// runs the command and stores the process exit code.

#include <CLI/CLI.hpp>

namespace dyop::cli {

/// Exit codes: 0 success (bad data lines are reported in the output, not in the exit code),
/// 1 usage error (CLI11's own), 2 input/output error.
constexpr int exit_usage_error = 1;
constexpr int exit_io_error = 2;
/// `dyop stress --check`: a promise of the library was broken (the figures are still written).
constexpr int exit_check_failed = 3;

void add_pairs_command(CLI::App& app, int& exit_code);
void add_bench_command(CLI::App& app, int& exit_code);
void add_stress_command(CLI::App& app, int& exit_code);
#ifdef DYOP_WITH_BOX2D
void add_scene_command(CLI::App& app, int& exit_code);
void add_compare_command(CLI::App& app, int& exit_code);
#endif

}  // namespace dyop::cli
