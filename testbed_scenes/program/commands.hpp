#pragma once
// The subcommands of the `dyop` program: each <name>_command.cpp registers its own with CLI11;
// its callback runs the command and stores the process exit code (`program/exit_codes.hpp`).

#include <CLI/CLI.hpp>

#include "program/exit_codes.hpp"

namespace dyop::cli {

void add_pairs_command(CLI::App& app, int& exit_code);
void add_bench_command(CLI::App& app, int& exit_code);
void add_stress_command(CLI::App& app, int& exit_code);
/// Built with Box2D only (DYOP_WITH_BOX2D).
void add_scene_command(CLI::App& app, int& exit_code);
void add_compare_command(CLI::App& app, int& exit_code);
void add_view_command(CLI::App& app, int& exit_code);

}  // namespace dyop::cli
