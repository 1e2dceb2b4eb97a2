// The `dyop` command-line program: subcommands over the solver, the Box2D bridge and the scenes.
#include "program/commands.hpp"

int main(int argc, char** argv) {
  CLI::App app{"DyOP-PD: penetration depth and contacts of 2D triangles"};
  app.require_subcommand(1);
  int exit_code = dyop::cli::exit_success;
  dyop::cli::add_pairs_command(app, exit_code);
  dyop::cli::add_bench_command(app, exit_code);
  dyop::cli::add_stress_command(app, exit_code);
#ifdef DYOP_WITH_BOX2D
  dyop::cli::add_scene_command(app, exit_code);
  dyop::cli::add_compare_command(app, exit_code);
  dyop::cli::add_view_command(app, exit_code);
#endif
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version exit 0; every other parse failure is a usage error.
    return app.exit(e) == 0 ? dyop::cli::exit_success : dyop::cli::exit_usage_error;
  }
  return exit_code;
}
