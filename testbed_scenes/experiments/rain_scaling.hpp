#pragma once
/// \file
/// How the narrow phase scales with the world: the `rain` scene with 100, 300, 1000 and 3000
/// falling triangles under every backend, its step time and its narrow-phase time (the scaling
/// section of `dyop bench`).
///
/// Times come from the scenes' own measurements (`SceneMetrics`): the median wall time of a step
/// and Box2D's `GetProfile().collide` (contact updates), both over steps 2..N. Each size is run
/// once per backend with the same seed, so every backend meets the same falling triangles, and
/// each backend's run is preceded by a run of Box2D's own contact with the plug-in not installed
/// (`box2d-own`, `experiments/in_world.hpp`): the backend's `ratio_vs_own` and `step_ratio_vs_own`
/// come from that pair of runs, alternating in one process. One `box2d-own` record per size
/// carries the median of its runs.

#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

#include "scenes/runner.hpp"

namespace dyop::experiments {

struct ScalingOptions {
  std::vector<int> sizes = {100, 300, 1000, 3000};  ///< falling triangles per run
  /// Steps per run (1/60 s each), at least 2. 240 (4 s): the 3000-triangle grid, 57 m tall,
  /// has just landed.
  int steps = 240;
  std::uint64_t seed = 1;
};

/// One run: a runner on `rain` with `falling` triangles.
struct ScalingRecord {
  scenes::Runner runner;      ///< a backend, or Box2D's own contact (plug-in not installed)
  int falling = 0;            ///< falling triangles
  int triangles = 0;          ///< every triangle fixture, the bin's included
  int steps = 0;              ///< steps run
  double step_ms_median = 0;  ///< scenes::median wall time of a step (ms)
  double narrowphase_ms_per_step = 0;  ///< Box2D's collide time per measured step (ms)
  double narrowphase_ns_per_pair = 0;  ///< the same per contact update (ns)
  double pairs_per_step = 0;           ///< triangle contact updates per measured step
  double ratio_vs_box2d = 0;           ///< narrowphase_ms_per_step / box2d's at the same size
  /// Narrow-phase time (`b2Profile::collide`, steps 2..N) over that of the Box2D's-own run just
  /// before it, same size (1 for box2d-own).
  double ratio_vs_own = 0;
  /// Whole-step time (`b2World::Step`, steps 2..N) over that of the same Box2D's-own run.
  double step_ratio_vs_own = 0;
  double pd_error_max = 0;      ///< largest |depth − exact depth| of an evaluated pair (m)
  std::uint64_t fallbacks = 0;  ///< pairs the backend left to Box2D (0 expected)
  bool nan_detected = false;    ///< a non-finite state or figure
};

/// Runs every backend at every size, each after a run of Box2D's own contact; one progress line
/// per backend on `progress`. Throws
/// `std::invalid_argument` for a size below 1 or steps below 2.
std::vector<ScalingRecord> run_rain_scaling(const ScalingOptions& options, std::ostream& progress);

}  // namespace dyop::experiments
