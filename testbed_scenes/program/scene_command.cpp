// `dyop scene`: the command (one scene under one runner, its summary, JSON and SVG) and its
// registration.
#include "program/scene_command.hpp"

#include <cmath>
#include <iostream>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "program/commands.hpp"
#include "report/output.hpp"
#include "report/svg.hpp"
#include "report/metrics_io.hpp"
#include "scenes/runner.hpp"
#include "scenes/scene.hpp"

namespace dyop::cli {

// The command is about scenes throughout; their names read better unqualified.
using namespace dyop::scenes;

void write_summary(const SceneMetrics& m, std::ostream& out) {
  const auto flags = out.flags();
  const auto precision = out.precision(4);
  out << "scene " << m.scene << " / " << name(m.runner) << ", seed " << m.seed << ": " << m.steps
      << " steps, " << m.bodies << " bodies, " << m.triangles << " triangles\n"
      << "  narrow phase: " << m.triangle_pairs << " triangle pairs, " << m.narrowphase_ns_per_pair
      << " ns per pair (" << m.narrowphase_ms_total << " ms); step median " << m.step_ms_median
      << " ms\n"
      << "  time of impact: " << m.toi_swept << " contacts swept (" << m.solve_toi_ms_total
      << " ms)\n"
      << "  penetration (exact): max " << m.max_penetration << " m, mean " << m.mean_penetration
      << " m; depth error vs exact: max " << m.pd_error_max << " m, mean " << m.pd_error_mean
      << " m, misclassified " << m.misclassified << ", invalid " << m.invalid << '\n'
      << "  kinetic energy " << m.kinetic_energy_final << " J";
  if (m.top_displacement) out << ", top displacement " << *m.top_displacement << " m";
  if (m.fallbacks) out << ", fallbacks to Box2D " << *m.fallbacks;
  out << (m.nan_detected ? ", NaN DETECTED" : ", no NaN") << ", hash " << report::hash_hex(m.hash)
      << '\n';
  if (m.slide) {
    out << "  sliding bodies: largest |vy| " << m.slide->max_vertical_speed << " m/s, |w| "
        << m.slide->max_angular_speed << " rad/s, smallest travel " << 100 * m.slide->min_travel
        << " % of speed x time";
    if (m.top_displacement) out << "; resting box jitter " << *m.top_displacement << " m";
    out << '\n';
    for (const SliderFigures& s : m.slide->sliders) {
      out << "    " << s.body << " on " << s.ground << (s.rolling ? " (rolling)" : "") << ": |vy| "
          << s.max_vertical_speed << " m/s, |w| " << s.max_angular_speed << " rad/s, travel "
          << 100 * s.travel << " %\n";
    }
  }
  if (m.manifold_errors) {
    const ManifoldErrors& e = *m.manifold_errors;
    out << "  manifolds the solver got: against a fresh answer (" << e.touching
        << " touching pairs) separation off by at most " << e.kept_max << " m, " << e.stale
        << " stale; against exact (" << e.checked << " penetrating) depth error max " << e.depth_max
        << " m, normal error max " << e.normal_max << " m\n";
  }
  if (m.skip_config && m.skips) {
    out << "  skips " << skip_argument(*m.skip_config) << ": of "
        << m.plugin_evaluations.value_or(0) << " evaluations, skipped";
    for (int s = 0; s < box2d::skip_count; ++s) {
      out << (s ? ", " : " ") << box2d::name(static_cast<box2d::Skip>(s)) << ' ' << (*m.skips)[s];
    }
    out << '\n';
    if (!m.skip_config->internal_edges) out << "  internal edges: off (ghost collisions kept)\n";
    if (m.skip_config->recycle_distance > 0) {
      out << "  recycling within " << m.skip_config->recycle_distance << " m: kept "
          << m.recycled.value_or(0) << " manifolds of " << m.plugin_evaluations.value_or(0)
          << " evaluations\n";
    }
  } else {
    out << (!m.runner ? "  skips: none apply (the plug-in is not installed)\n"
                      : "  skips: none apply (no Box2D world)\n");
  }
  out.precision(precision);
  out.flags(flags);
}

int run_scene_command(const SceneCommand& c, std::ostream& out, std::ostream& err) {
  const SceneInfo* info = find_scene(c.scene);
  const std::optional<Runner> runner = parse_runner(c.runner);
  if (info == nullptr || !runner) {
    err << "dyop scene: unknown "
        << (info == nullptr ? "scene '" + c.scene + "'" : "runner '" + c.runner + "'") << '\n';
    return exit_usage_error;
  }
  if (!*runner && std::string(info->name) == "paper") {
    err << "dyop scene: paper has no Box2D world: " << box2d_own << " runs only Box2D scenes\n";
    return exit_usage_error;
  }
  ParsedSkips skips = parse_skips(c.skip);
  if (!skips.ok()) {
    err << "dyop scene: --skip: " << skips.error << '\n';
    return exit_usage_error;
  }
  if (c.recycle) {
    if (!(*c.recycle >= 0 && std::isfinite(*c.recycle))) {
      err << "dyop scene: --recycle takes a distance in metres, at least 0\n";
      return exit_usage_error;
    }
    skips.config.recycle_distance = *c.recycle;
  }
  if (c.internal_edges != "on" && c.internal_edges != "off") {
    err << "dyop scene: --internal-edges takes on or off, not '" << c.internal_edges << "'\n";
    return exit_usage_error;
  }
  skips.config.internal_edges = c.internal_edges == "on";
  if (c.json == "-" && c.svg == "-") {
    err << "dyop scene: --json and --svg cannot both go to standard output\n";
    return exit_usage_error;
  }
  if (c.steps && *c.steps < 1) {
    err << "dyop scene: --steps must be at least 1\n";
    return exit_usage_error;
  }
  const bool rain = c.scene == "rain" || c.scene == "rain-tall";
  if (c.falling && (!rain || *c.falling < 1)) {
    err << "dyop scene: --falling takes a number of triangles (at least 1), for rain and "
           "rain-tall only\n";
    return exit_usage_error;
  }
  // Opened before the scene runs, so that an unwritable path fails at once.
  std::optional<report::Output> json, svg;
  if (!c.json.empty()) json.emplace(c.json, out);
  if (!c.svg.empty()) svg.emplace(c.svg, out);
  for (const std::optional<report::Output>* o : {&json, &svg}) {
    if (!*o) continue;
    if (const std::optional<report::Problem> p = (*o)->open_problem()) {
      err << "dyop scene: " << p->message << '\n';
      return exit_code_for({*p});
    }
  }
  std::ostream& summary = c.json == "-" || c.svg == "-" ? err : out;

  SceneMetrics m;
  Drawing final_state;
  try {
    const std::unique_ptr<Scene> scene = c.falling
                                             ? make_rain(*c.falling, *runner, c.seed, skips.config)
                                             : make_scene(c.scene, *runner, c.seed, skips.config);
    if (c.check_manifolds) scene->check_manifolds();
    if (c.spawn_far) scene->spawn_far_away();
    for (int i = c.steps.value_or(info->default_steps); i > 0; --i) scene->step();
    if (!c.svg.empty()) final_state = scene->drawing();
    m = scene->metrics();
  } catch (const std::exception& e) {
    err << "dyop scene: " << c.scene << " / " << c.runner << " could not run: " << e.what() << '\n';
    return exit_io_error;
  }
  write_summary(m, summary);
  if (json) report::write_json(m, json->stream());
  if (svg) report::write_svg(final_state, svg->stream());
  std::vector<report::Problem> problems;
  for (std::optional<report::Output>* o : {&json, &svg}) {
    if (!*o) continue;
    if (std::optional<report::Problem> p = (*o)->close()) problems.push_back(std::move(*p));
  }
  if (!out) problems.push_back(report::not_written("-", "standard output failed"));
  for (const report::Problem& p : problems) err << "dyop scene: " << p.message << '\n';
  return exit_code_for(problems);
}

void add_scene_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<SceneCommand>();
  auto steps = std::make_shared<int>(0);
  auto falling = std::make_shared<int>(0);
  std::vector<std::string> names;
  std::string list;
  for (const scenes::SceneInfo& s : scenes::scene_catalog()) {
    names.push_back(s.name);
    list += std::string("\n  ") + s.name + ": " + s.description;
  }
  CLI::App* cmd = app.add_subcommand(
      "scene", "Run one headless scene under one narrow phase and measure it. Scenes:" + list);
  cmd->add_option("name", args->scene, "Scene")->required()->check(CLI::IsMember(names));
  cmd->add_option("--runner,-r", args->runner,
                  "What answers the polygon pairs: a backend of the plug-in (box2d: Box2D's "
                  "b2CollidePolygons through the plug-in), or box2d-own: the plug-in not installed")
      ->required()
      ->check(CLI::IsMember(scenes::runner_names(true)));
  CLI::Option* steps_option =
      cmd->add_option("--steps", *steps, "Steps to run (default: the scene's own)")
          ->check(CLI::Range(1, 10000000));
  cmd->add_option("--seed", args->seed, "Seed of the scene")->capture_default_str();
  cmd->add_option("--skip", args->skip, scenes::skip_help())
      ->capture_default_str()
      ->check(CLI::Validator([](std::string& text) { return scenes::parse_skips(text).error; },
                             "all|none|LIST"));
  auto recycle = std::make_shared<float>(0.0f);
  CLI::Option* recycle_option = cmd->add_option(
      "--recycle", *recycle,
      "Keep a contact's manifold while its pair moved less than this (metres; 0: off; default: "
      "the plug-in's default, " +
          std::to_string(box2d::Config{}.recycle_distance) + ")");
  cmd->add_option("--internal-edges", args->internal_edges,
                  "The plug-in's internal-edge rule: on (the default) or off")
      ->capture_default_str()
      ->check(CLI::IsMember({"on", "off"}));
  cmd->add_flag("--check-manifolds", args->check_manifolds,
                "Check every manifold the solver gets against the exact answer (slows the narrow "
                "phase: for accuracy, not timing)");
  cmd->add_flag("--spawn-far", args->spawn_far,
                "Make a body 1.4 km away before every other step and destroy it before the next "
                "(a world that spawns elsewhere: its fixture count moves at every step)");
  cmd->add_option("--json", args->json, "Write the figures as one JSON object to FILE, or '-'");
  cmd->add_option("--svg", args->svg, "Draw the final state as SVG to FILE, or '-'");
  CLI::Option* falling_option = cmd->add_option(
      "--falling", *falling,
      "rain and rain-tall only: this many falling triangles (the rain scaling's sizes)");
  cmd->callback(
      [args, steps, steps_option, falling, falling_option, recycle, recycle_option, &exit_code] {
        if (steps_option->count() > 0) args->steps = *steps;
        if (recycle_option->count() > 0) args->recycle = *recycle;
        if (falling_option->count() > 0) args->falling = *falling;
        exit_code = run_scene_command(*args, std::cout, std::cerr);
      });
}

}  // namespace dyop::cli
