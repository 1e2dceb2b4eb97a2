#pragma once
/// \file
/// What the plug-in costs a pool of environments: N copies of one scene's world stepped at once on
/// N threads (N = 1, 2, 4), with the plug-in's `dyop` backend installed, against the same worlds
/// under Box2D's own contact (the plug-in not installed), runs alternating in one process (the
/// thread-scaling section of `dyop bench`).
///
/// Each run builds its N worlds (untimed), starts N threads that step one world each, and is
/// timed from the threads' start to the last one's end: the wall time a pool waits for. Of the
/// runs of each runner at each N the fastest is kept (the least disturbed by the rest of the
/// machine). More threads than cores share the cores: the figures then show the machine, not the
/// plug-in; the plug-in's part is the ratio.

#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

#include "scenes/runner.hpp"

namespace dyop::experiments {

struct ThreadScalingOptions {
  std::vector<int> threads = {1, 2, 4};  ///< worlds, one per thread, per run
  std::string scene = "rain";            ///< a Box2D scene of the catalogue
  int steps = 600;                       ///< steps of each world per run, at least 1
  int runs = 5;                          ///< runs of each runner at each N, at least 1
  std::uint64_t seed = 0;                ///< every world's seed (the worlds are copies)
};

/// The fastest run of one runner at one N.
struct ThreadScalingRecord {
  scenes::Runner runner;  ///< `Backend::Dyop`, or Box2D's own contact (the plug-in not installed)
  int threads = 0;        ///< worlds stepped at once, one per thread
  int steps = 0;          ///< steps of each world
  double seconds = 0;     ///< wall time from the threads' start to the last one's end
  /// Steps of all worlds per second of wall time (threads × steps / seconds).
  double steps_per_second = 0;
  /// `steps_per_second` over Box2D's own at the same N (1 for box2d-own): above 1, faster.
  double ratio_vs_own = 0;
};

/// Runs Box2D's own contact and `dyop` alternately at every N, `runs` times each; one progress
/// line per N on `progress`. Installs and uninstalls the plug-in between runs (never while a
/// thread steps), and leaves it uninstalled. Throws `std::invalid_argument` for an unknown scene,
/// fewer than 1 step, run or thread.
std::vector<ThreadScalingRecord> run_thread_scaling(const ThreadScalingOptions& options,
                                                    std::ostream& progress);

}  // namespace dyop::experiments
