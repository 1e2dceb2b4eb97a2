#pragma once
/// \file
/// `dyop scene NAME --runner R [--steps N] [--seed S] [--falling N] [--skip all|none|LIST]
/// [--json FILE|-] [--svg FILE|-]`: runs one scene under one runner with the given narrow-phase
/// skips, prints a short summary, and writes the figures as JSON and the final state as SVG. The
/// command line (CLI11, `add_scene_command`) validates names; this checks them again, checks files
/// and runs.

#include <cstdint>
#include <iosfwd>
#include <optional>
#include <string>

#include "scenes/metrics.hpp"

namespace dyop::cli {

struct SceneCommand {
  std::string scene;  ///< a name of `scenes::scene_catalog()`
  /// A backend ("dyop", "dyop-fast", "lin-canny", "sat", "epa", "box2d"), or "box2d-own" (Box2D
  /// scenes: the plug-in not installed): `scenes::parse_runner`
  std::string runner;
  std::optional<int> steps;  ///< none: the scene's default
  /// `rain` and `rain-tall` only: this many falling triangles (`scenes::make_rain`, as the rain
  /// scaling's sizes); none: the scene's own.
  std::optional<int> falling;
  std::uint64_t seed = 0;
  std::string skip = "all";  ///< a `parse_skips` argument; the `paper` scene ignores it
  /// `box2d::Config::recycle_distance` (metres, ≥ 0; 0: off); none: the default config's. The
  /// `paper` scene ignores it.
  std::optional<float> recycle;
  /// `box2d::Config::internal_edges`: "on" (the default config's) or "off". The `paper` scene
  /// ignores it.
  std::string internal_edges = "on";
  /// Check every manifold the solver gets against the exact answer (`Scene::check_manifolds`;
  /// slows the narrow phase).
  bool check_manifolds = false;
  /// Make and destroy a body far from the scene at alternate steps (`Scene::spawn_far_away`):
  /// every step sees the world's count of fixtures move, for both runners.
  bool spawn_far = false;
  std::string json;  ///< empty: none; "-": `out`
  std::string svg;   ///< empty: none; "-": `out`
};

/// Runs the command. Output files are opened before the scene runs, so an unwritable path fails
/// at once. The summary goes to `out`, or to `err` when the JSON or SVG goes to `out`. Returns
/// `exit_success`, `exit_usage_error` (unknown name or skip, both outputs on standard output) or
/// `exit_io_error` (a file cannot be written, or the scene could not run), with the reason on
/// `err`.
int run_scene_command(const SceneCommand& command, std::ostream& out, std::ostream& err);

/// A few readable lines about one run (what `dyop scene` prints).
void write_summary(const scenes::SceneMetrics& m, std::ostream& out);

}  // namespace dyop::cli
