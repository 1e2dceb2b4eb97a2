#pragma once
/// \file
/// The headless scenes: each a small type that is created for a backend and a seed, stepped, and
/// measured. Equal seeds give equal scenes and equal final states (`SceneMetrics::hash`).
///
/// Box2D scenes (everything but `paper`) install the backend in the Box2D plug-in before their
/// bodies exist and uninstall it when destroyed: Box2D's contact registry is process-wide, so
/// only one such scene may exist at a time. `box2d` is Box2D's own `b2CollidePolygons` routed
/// through the same plug-in (bit-identical to Box2D's own polygon contact, and counted alike).
///
/// Box2D scenes run with a `box2d::Config`, the narrow-phase work they may skip (`--skip`, every
/// skip on by default); with an exact backend it changes the time, never the final state. The
/// `paper` scene has no Box2D world: it accepts a config and ignores it.

#include <cstdint>
#include <memory>
#include <optional>
#include <string_view>
#include <vector>

#include "dyop/box2d.hpp"
#include "scenes/metrics.hpp"
#include "scenes/runner.hpp"
#include "scenes/skips.hpp"
#include "scenes/drawing.hpp"

namespace dyop::scenes {

/// A scene being run.
class Scene {
 public:
  virtual ~Scene() = default;
  /// Advances one step (Box2D scenes: 1/60 s; paper: 1/30 s) and measures it.
  virtual void step() = 0;
  /// The figures so far.
  virtual SceneMetrics metrics() const = 0;
  /// The current state, to draw.
  virtual Drawing drawing() const = 0;
  /// From now on, checks every manifold the solver gets against the exact answer
  /// (`SceneMetrics::manifold_errors`). Box2D scenes; the paper scene has no manifolds and ignores
  /// it. Slows the narrow phase: for accuracy runs, never for timing.
  virtual void check_manifolds() {}
  /// From now on, makes a one-triangle dynamic body far from the scene (`spawn_distance`) before
  /// every other step and destroys it before the next: a world that spawns and despawns elsewhere
  /// (shots, debris, a streamed level), whose count of fixtures moves at every step. Nothing of
  /// the scene touches it, and it is no part of the figures. Box2D scenes; the paper scene ignores
  /// it.
  virtual void spawn_far_away() {}
};

/// Where `Scene::spawn_far_away` makes its body: x = y = this (metres), 1.4 km from the origin,
/// beyond every scene's reach and within float precision's comfort (0.1 mm there).
inline constexpr float spawn_distance = 1000.0f;

/// A scene of the catalogue.
struct SceneInfo {
  const char* name;         ///< "paper", "pyramid", ...
  const char* description;  ///< one line: what is in it
  int default_steps;        ///< `dyop scene` without `--steps`, and `dyop compare` (full)
  int quick_steps;          ///< the quick replays: 5 s, everything dropped has landed (the tests)
  /// `dyop compare --quick` (the main command's run, kept within 30 s on two cores): the quick
  /// steps, fewer for the heaviest scenes (their piles formed, not settled).
  int compare_quick_steps;
};

/// Every scene, in the order the reports list them.
const std::vector<SceneInfo>& scene_catalog();

/// The scene called `name`, or nullptr.
const SceneInfo* find_scene(std::string_view name);

/// Creates scene `name` for `runner` and `seed`, with the skips `skips` (Box2D scenes; ignored by
/// Box2D's own contact). Throws `std::invalid_argument` for an unknown name, and for the `paper`
/// scene (no Box2D world) with Box2D's own contact.
std::unique_ptr<Scene> make_scene(std::string_view name, const Runner& runner, std::uint64_t seed,
                                  const box2d::Config& skips = box2d::Config::all());

/// Falling triangles in the catalogue's `rain`.
inline constexpr int rain_triangles = 500;

/// Triangles of the `rain-tall` scene: falling from 2 m to 40 m, they reach the bin fast, and
/// Box2D's time-of-impact pass (`b2World::SolveTOI`) does much of the work.
inline constexpr int tall_rain_triangles = 1500;

/// `rain` with `falling` triangles (≥ 1) instead of `rain_triangles`, for scaling runs: the same
/// 1 m grid with at least 22 columns and about as many columns as rows, in a bin as wide. Throws
/// as `make_scene`, and `std::invalid_argument` for `falling` < 1.
std::unique_ptr<Scene> make_rain(int falling, const Runner& runner, std::uint64_t seed,
                                 const box2d::Config& skips = box2d::Config::all());

/// Creates, runs `steps` steps, and returns the figures (and the final state when `final_state`
/// is given).
SceneMetrics run_scene(std::string_view name, const Runner& runner, int steps, std::uint64_t seed,
                       const box2d::Config& skips = box2d::Config::all(),
                       Drawing* final_state = nullptr);

}  // namespace dyop::scenes
