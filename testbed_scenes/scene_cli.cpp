// `dyop scene`: registration of the subcommand; the command itself is scenes/scene_command.
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "commands.hpp"
#include "scenes/scene.hpp"
#include "scenes/scene_command.hpp"

namespace dyop::cli {

void add_scene_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<scenes::SceneCommand>();
  auto steps = std::make_shared<int>(0);
  std::vector<std::string> names, backends;
  std::string list;
  for (const scenes::SceneInfo& s : scenes::scene_catalog()) {
    names.push_back(s.name);
    list += std::string("\n  ") + s.name + ": " + s.description;
  }
  for (box2d::Backend b : box2d::all_backends) backends.push_back(box2d::name(b));
  backends.push_back(scenes::box2d_own);
  CLI::App* cmd = app.add_subcommand(
      "scene", "Run one headless scene under one narrow phase and measure it. Scenes:" + list);
  cmd->add_option("name", args->scene, "Scene")->required()->check(CLI::IsMember(names));
  cmd->add_option("--backend,-b", args->backend,
                  "Narrow phase for triangle pairs (box2d: Box2D's b2CollidePolygons through the "
                  "plug-in; box2d-own: the plug-in not installed)")
      ->required()
      ->check(CLI::IsMember(backends));
  CLI::Option* steps_option =
      cmd->add_option("--steps", *steps, "Steps to run (default: the scene's own)")
          ->check(CLI::Range(1, 10000000));
  cmd->add_option("--seed", args->seed, "Seed of the scene")->capture_default_str();
  cmd->add_option("--skip", args->skip, scenes::skip_help())
      ->capture_default_str()
      ->check(CLI::Validator([](std::string& text) { return scenes::parse_skips(text).error; },
                             "all|none|LIST"));
  cmd->add_option("--json", args->json, "Write the figures as one JSON object to FILE, or '-'");
  cmd->add_option("--svg", args->svg, "Draw the final state as SVG to FILE, or '-'");
  cmd->callback([args, steps, steps_option, &exit_code] {
    if (steps_option->count() > 0) args->steps = *steps;
    exit_code = scenes::run_scene_command(*args, std::cout, std::cerr);
  });
}

}  // namespace dyop::cli
