// `dyop view`: the command (one scene under two runners, written as a viewer page) and its
// registration.
#include "program/view_command.hpp"

#include <array>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <ostream>
#include <string>
#include <system_error>
#include <vector>

#include "experiments/ground_comparison.hpp"
#include "experiments/lockstep_recording.hpp"
#include "experiments/terrain_runs.hpp"
#include "program/commands.hpp"
#include "report/format.hpp"
#include "report/output.hpp"
#include "report/viewer_page.hpp"
#include "scenes/runner.hpp"
#include "scenes/scene.hpp"

namespace dyop::cli {

using namespace dyop::scenes;

namespace {

// Makes the page's directory; the problem when it cannot.
std::optional<report::Problem> make_parent(const std::string& path) {
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  std::error_code error;
  if (!parent.empty()) std::filesystem::create_directories(parent, error);
  if (error) return report::not_written(path, error.message());
  return std::nullopt;
}

void write_summary(const experiments::LockstepRecording& r, const std::string& page,
                   std::uintmax_t bytes, std::ostream& out) {
  out << "view " << r.scene << ", seed " << r.seed << ", " << r.steps << " steps, "
      << r.bodies.size() << " bodies; at the last step:\n";
  for (int k = 0; k < 2; ++k) {
    const experiments::ViewFrame& f = r.frames[k].back();
    int marked = 0;
    for (const experiments::ViewContact& c : f.contacts) {
      marked += c.mark != experiments::EdgeMark::None;
    }
    const box2d::Config& config = r.configs[k];
    std::string settings;  // a plug-in runner's (Box2D's own contact has none)
    if (r.runners[k]) {
      settings = " (skips " + skip_argument(config) + ", internal-edge rule " +
                 (config.internal_edges ? "on" : "off");
      if (config.recycle_distance > 0) {
        settings += ", recycling within " + report::fmt("%g", config.recycle_distance) + " m";
      }
      settings += ")";
    }
    out << "  " << (k == 0 ? "A " : "B ") << name(r.runners[k]) << settings << ": " << f.touching
        << " contacts, " << f.agreeing << " agree with " << name(r.runners[1 - k]) << ", " << marked
        << " differ from b2CollidePolygons, largest penetration "
        << report::fmt("%.2f", f.max_penetration * 1000) << " mm\n";
  }
  out << "page: " << page << " (" << bytes << " bytes)\n";
}

}  // namespace

int run_view_command(const ViewCommand& c, std::ostream& out, std::ostream& err) {
  const SceneInfo* info = find_scene(c.scene);
  const std::optional<experiments::GroundLevel> level =
      experiments::ground_level_of_recording(c.scene);
  const bool craters =
      c.scene == experiments::terrain_recording_name && experiments::terrain_available();
  if (info == nullptr && !level && !craters) {
    err << "dyop view: unknown scene '" << c.scene << "'\n";
    return exit_usage_error;
  }
  if (c.runners.size() != 2) {
    err << "dyop view: give two runners (--runner A --runner B), not " << c.runners.size() << '\n';
    return exit_usage_error;
  }
  std::array<Runner, 2> runners;
  for (int k = 0; k < 2; ++k) {
    const std::optional<Runner> r = parse_runner(c.runners[k]);
    if (!r) {
      err << "dyop view: unknown runner '" << c.runners[k] << "'\n";
      return exit_usage_error;
    }
    runners[k] = *r;
  }
  if (c.skips.empty() || c.skips.size() > 2 || c.internal_edges.empty() ||
      c.internal_edges.size() > 2 || c.recycle.size() > 2) {
    err << "dyop view: --skip, --internal-edges and --recycle take one setting for both "
           "runners, or two\n";
    return exit_usage_error;
  }
  std::array<box2d::Config, 2> configs;
  for (int k = 0; k < 2; ++k) {
    const ParsedSkips skips = parse_skips(c.skips[std::size_t(k) % c.skips.size()]);
    const std::string& edges = c.internal_edges[std::size_t(k) % c.internal_edges.size()];
    if (!skips.ok() || (edges != "on" && edges != "off")) {
      err << "dyop view: "
          << (skips.ok() ? "--internal-edges takes on or off, not '" + edges + "'"
                         : "--skip: " + skips.error)
          << '\n';
      return exit_usage_error;
    }
    configs[k] = skips.config;
    configs[k].internal_edges = edges == "on";
    if (!c.recycle.empty()) {
      const float recycle = c.recycle[std::size_t(k) % c.recycle.size()];
      if (!(recycle >= 0 && std::isfinite(recycle))) {
        err << "dyop view: --recycle takes a distance in metres, at least 0\n";
        return exit_usage_error;
      }
      configs[k].recycle_distance = recycle;
    }
  }
  if (c.steps && *c.steps < 1) {
    err << "dyop view: --steps must be at least 1\n";
    return exit_usage_error;
  }
  const std::string page = c.out.empty() ? "reports/view/" + c.scene + ".html" : c.out;
  if (page == "-" && c.json == "-") {
    err << "dyop view: the page and --json cannot both go to standard output\n";
    return exit_usage_error;
  }
  // Opened before the scene runs, so that an unwritable path fails at once.
  if (page != "-") {
    if (const std::optional<report::Problem> p = make_parent(page)) {
      err << "dyop view: " << p->message << '\n';
      return exit_code_for({*p});
    }
  }
  std::optional<report::Output> json;
  report::Output html(page, out);
  if (!c.json.empty()) json.emplace(c.json, out);
  for (const report::Output* o : {&html, json ? &*json : nullptr}) {
    if (o == nullptr) continue;
    if (const std::optional<report::Problem> p = o->open_problem()) {
      err << "dyop view: " << p->message << '\n';
      return exit_code_for({*p});
    }
  }
  std::ostream& summary = page == "-" || c.json == "-" ? err : out;

  experiments::LockstepRecording recording;
  try {
    recording =
        craters ? experiments::record_terrain_craters(
                      runners, c.steps.value_or(experiments::TerrainTiming{}.crater_steps), configs,
                      c.seed)
        : level
            ? experiments::record_ground(
                  *level, runners, c.steps.value_or(experiments::ground_recording_steps), configs)
            : experiments::record_lockstep(c.scene, runners, c.steps.value_or(info->default_steps),
                                           c.seed, configs);
    report::write_viewer_page(recording, html.stream());
  } catch (const std::exception& e) {
    err << "dyop view: " << c.scene << " could not run: " << e.what() << '\n';
    return exit_io_error;
  }
  if (json) report::write_json_document(report::viewer_summary(recording), json->stream());
  std::vector<report::Problem> problems;
  for (report::Output* o : {&html, json ? &*json : nullptr}) {
    if (o == nullptr) continue;
    if (std::optional<report::Problem> p = o->close()) problems.push_back(std::move(*p));
  }
  std::error_code size_error;
  const std::uintmax_t bytes = page == "-" ? 0 : std::filesystem::file_size(page, size_error);
  write_summary(recording, page, size_error ? 0 : bytes, summary);
  if (!out) problems.push_back(report::not_written("-", "standard output failed"));
  for (const report::Problem& p : problems) err << "dyop view: " << p.message << '\n';
  return exit_code_for(problems);
}

void add_view_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<ViewCommand>();
  auto steps = std::make_shared<int>(0);
  std::vector<std::string> names;
  for (const SceneInfo& s : scene_catalog()) names.push_back(s.name);
  for (const experiments::GroundLevel level : experiments::ground_levels) {
    if (experiments::builders_available(level)) {
      names.push_back(experiments::ground_recording_name(level));
    }
  }
  if (experiments::terrain_available()) names.push_back(experiments::terrain_recording_name);
  CLI::App* cmd = app.add_subcommand(
      "view",
      "Record one scene under two runners and write one self-contained HTML page that plays "
      "them back side by side or overlaid, with their contacts (open it in a browser)");
  cmd->add_option("name", args->scene,
                  "Scene, or a level of the grounds comparison (grounds-LEVEL: A the level as "
                  "Box2D's chains, B through the plug-in's builders), or terrain-craters (the "
                  "terrain section's craters dug under a crowd, 600 steps by default)")
      ->required()
      ->check(CLI::IsMember(names));
  cmd->add_option("--runner,-r", args->runners,
                  "The two runners, A then B (give it twice): a backend of the plug-in, or "
                  "box2d-own (the plug-in not installed)")
      ->capture_default_str()
      ->expected(2)
      ->check(CLI::IsMember(runner_names(true)));
  CLI::Option* steps_option =
      cmd->add_option("--steps", *steps, "Steps to record (default: the scene's own)")
          ->check(CLI::Range(1, 10000000));
  cmd->add_option("--seed", args->seed, "Seed of the scene")->capture_default_str();
  cmd->add_option("--skip", args->skips,
                  skip_help() + "\n(once: both runners; twice: A's, then B's)")
      ->capture_default_str()
      ->expected(1, 2)
      ->check(CLI::Validator([](std::string& text) { return parse_skips(text).error; },
                             "all|none|LIST"));
  cmd->add_option("--internal-edges", args->internal_edges,
                  "The plug-in's internal-edge rule (off: Box2D's fixture-by-fixture contacts); "
                  "once: both runners; twice: A's, then B's")
      ->capture_default_str()
      ->expected(1, 2)
      ->check(CLI::IsMember({"on", "off"}));
  cmd->add_option("--recycle", args->recycle,
                  "Keep a contact's manifold while its pair moved less than this (metres; 0: off; "
                  "default: the plug-in's default, " +
                      report::fmt("%g", box2d::Config{}.recycle_distance) +
                      "); once: both runners; twice: A's, then B's")
      ->expected(1, 2);
  cmd->add_option("--out,-o", args->out, "The page (default: reports/view/SCENE.html)");
  cmd->add_option("--json", args->json,
                  "Write the per-step counts the page shows as JSON to FILE, or '-'");
  cmd->callback([args, steps, steps_option, &exit_code] {
    if (steps_option->count() > 0) args->steps = *steps;
    exit_code = run_view_command(*args, std::cout, std::cerr);
  });
}

}  // namespace dyop::cli
