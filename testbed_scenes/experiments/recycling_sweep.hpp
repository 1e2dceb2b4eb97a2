#pragma once
/// \file
/// Run time against error for manifold recycling (`box2d::Config::recycle_distance`), per scene:
/// - for each distance of `RecyclingSweepOptions::distances` (0: off), the plug-in's `dyop` with
/// that distance
///   against Box2D's own contact (uninstalled), alternating in one process
///   (`measure_in_world`): narrow phase, `SolveTOI` and step; the share of evaluations that kept
///   their manifold; and, in one more run with `Scene::check_manifolds`, what the solver got
///   (`ManifoldErrors`), the deepest exact penetration, the top bodies' drift and the slide's
///   figures;
/// - the floor: `dyop` installed never to recompute
/// (`box2d::measurement::install_never_recompute`),
///   against Box2D's own likewise (its world is physically wrong: only its times count);
/// - Box2D's own contact's accuracy in the same run (its float errors: the yardstick).

#include <cstdint>
#include <functional>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "dyop/box2d.hpp"
#include "experiments/in_world.hpp"
#include "scenes/metrics.hpp"

namespace dyop::experiments {

/// The distances of a full sweep (metres; 0: recycling off).
inline const std::vector<float> recycle_distances = {0.0f, 0.001f, 0.005f, 0.01f, 0.02f, 0.05f};

/// What a sweep row measured.
enum class SweepRow : std::uint8_t {
  Own,     ///< Box2D's own contact: accuracy only (its times are every other row's reference)
  Plugin,  ///< `dyop` at `distance`
  Floor,   ///< `dyop` never recomputing: times only
};

/// One row of a scene's sweep.
struct RecyclingRecord {
  std::string scene;
  SweepRow row = SweepRow::Plugin;
  float distance = 0;  ///< `Plugin`: the recycle distance (m); 0 otherwise
  /// `Plugin`, `Floor`: against Box2D's own contact, alternating (none for `Own`).
  std::optional<InWorldRatio> timing;
  /// `Plugin`: evaluations that kept their manifold over the plug-in's evaluations (first timed
  /// run); 0 otherwise.
  double recycled_share = 0;
  /// `Own`, `Plugin`: the accuracy run's figures (with `manifold_errors`); none for `Floor`.
  std::optional<scenes::SceneMetrics> accuracy;
};

/// What to sweep.
struct RecyclingSweepOptions {
  std::vector<std::string> scenes;                   ///< catalogue names (Box2D scenes)
  std::vector<float> distances = recycle_distances;  ///< metres, each ≥ 0 (0: off)
  /// Steps of every run of a scene (by name).
  std::function<int(const std::string&)> steps;
  int repetitions = 2;  ///< alternating runs of each side
  std::uint64_t seed = 0;
  box2d::Config config;  ///< the skips and internal-edge rule; `recycle_distance` is swept
};

/// Runs the sweep, scene after scene: per scene an `Own` row, one `Plugin` row per distance, and
/// a `Floor` row; one progress line per scene on `progress`. Throws what the scenes throw.
std::vector<RecyclingRecord> run_recycling_sweep(const RecyclingSweepOptions& options,
                                                 std::ostream& progress);

}  // namespace dyop::experiments
