// `dyop compare`: registration of the subcommand; the command itself is scenes/compare.
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "commands.hpp"
#include "scenes/compare.hpp"
#include "scenes/scene.hpp"

namespace dyop::cli {

void add_compare_command(CLI::App& app, int& exit_code) {
  auto options = std::make_shared<scenes::CompareOptions>();
  auto steps = std::make_shared<int>(0);
  std::vector<std::string> names;
  for (const scenes::SceneInfo& s : scenes::scene_catalog()) names.push_back(s.name);
  CLI::App* cmd = app.add_subcommand(
      "compare",
      "Run every scene under every backend, and the skip section (pyramid, rain, tumbler, mixed "
      "with every skip off and on); print the tables and write a report (Markdown, CSV, SVG "
      "charts with gnuplot, scene snapshots)");
  cmd->add_flag("--quick", options->quick, "Short runs (5 s of simulated time per Box2D scene)");
  cmd->add_option("--out", options->out_dir, "Report directory")->capture_default_str();
  CLI::Option* steps_option =
      cmd->add_option("--steps", *steps, "Steps of every scene (default: the catalogue's)")
          ->check(CLI::Range(1, 10000000));
  cmd->add_option("--seed", options->seed, "Seed of every scene")->capture_default_str();
  cmd->add_option("--scene", options->scenes, "Only these scenes (repeatable)")
      ->check(CLI::IsMember(names));
  auto skip = std::make_shared<std::string>("all");
  const std::string skip_help =
      scenes::skip_help() +
      "\n(every run of the main table; the skip section sets it against none)";
  cmd->add_option("--skip", *skip, skip_help)
      ->capture_default_str()
      ->check(CLI::Validator([](std::string& text) { return scenes::parse_skips(text).error; },
                             "all|none|LIST"));
  cmd->callback([options, steps, steps_option, skip, &exit_code] {
    if (steps_option->count() > 0) options->steps = *steps;
    options->skips = scenes::parse_skips(*skip).config;
    exit_code = scenes::run_compare_command(*options, std::cout, std::cerr);
  });
}

}  // namespace dyop::cli
