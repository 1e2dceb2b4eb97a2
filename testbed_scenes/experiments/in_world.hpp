#pragma once
/// \file
/// The plug-in in the world, against Box2D's own contact: what a user who adds the two lines
/// feels. A scene runs under Box2D's own contact (the plug-in not installed, `box2d_own`) and under
/// a backend alternately (own, backend, own, backend, ...) in one process, with the same seed and
/// steps, so that the shared machine's drifts fall on both sides alike. Each side's figure is the
/// median over its repetitions of:
/// - narrow phase: `b2Profile::collide` summed over steps 2..N (`narrowphase_ms_total`: Box2D's
///   contact updates, the broad-phase overlap test and the plug-in's or Box2D's manifold);
/// - step: `b2World::Step`'s wall time summed over the same steps (`step_ms_total`: also the
///   solver and the time-of-impact pass, which pays for the contacts' size).
/// The two worlds evolve alike but not bit for bit (the backends round differently), so the
/// contact updates of each side are given too.

#include <cstdint>
#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

#include "scenes/metrics.hpp"
#include "scenes/scene.hpp"

namespace dyop::experiments {

/// One side of an in-world comparison: medians over the repetitions.
struct InWorldSide {
  double narrowphase_ms = 0;          ///< `b2Profile::collide` over steps 2..N (ms)
  double step_ms = 0;                 ///< `b2World::Step` over steps 2..N (ms)
  double solve_toi_ms = 0;            ///< `b2World::SolveTOI` over steps 2..N (ms)
  double step_ms_median = 0;          ///< scenes::median wall time of one step (ms)
  std::uint64_t contact_updates = 0;  ///< contact updates in steps 2..N (first repetition)
  std::uint64_t toi_swept = 0;  ///< contacts `SolveTOI` swept in steps 2..N (first repetition)
  /// The plug-in's side, first repetition, the whole run: contacts made, and its evaluations kept
  /// (`recycled`), skipped and answered afresh (`box2d::Stats`); 0 for Box2D's own.
  std::uint64_t contacts_made = 0;
  std::uint64_t kept = 0;      ///< see `contacts_made`
  std::uint64_t skipped = 0;   ///< see `contacts_made`
  std::uint64_t answered = 0;  ///< see `contacts_made`
};

/// A backend against Box2D's own contact in one scene.
struct InWorldRatio {
  std::string scene;  ///< catalogue name, or `rain-<n>` for a scaling size
  box2d::Backend backend = box2d::Backend::Dyop;  ///< the plug-in's side
  int steps = 0;                                  ///< steps of every run
  int repetitions = 0;                            ///< runs of each side
  InWorldSide own;                                ///< Box2D's own contact (`box2d_own`)
  InWorldSide plugin;                             ///< the backend through the plug-in
  /// The plug-in's narrow-phase time over Box2D's own (< 1: the plug-in is faster).
  double narrowphase_ratio() const { return plugin.narrowphase_ms / own.narrowphase_ms; }
  /// The plug-in's step time over Box2D's own.
  double step_ratio() const { return plugin.step_ms / own.step_ms; }
  /// The plug-in's time-of-impact time over Box2D's own.
  double solve_toi_ratio() const { return plugin.solve_toi_ms / own.solve_toi_ms; }
};

/// Runs of each side: 2 quick, 3 full.
int in_world_repetitions(bool quick);

/// Runs `run(runner)` alternately for Box2D's own contact and `backend`, `repetitions` times each
/// (own first), and returns the medians (and, through `plugin_runs`, the plug-in's runs). `run`
/// builds, steps and measures one world (e.g. a catalogue scene or a scaling size) and must give
/// every call the same seed and steps. Throws `std::invalid_argument` for `repetitions` < 1, and
/// what `run` throws.
InWorldRatio measure_in_world(const std::string& scene, box2d::Backend backend, int repetitions,
                              const std::function<scenes::SceneMetrics(const scenes::Runner&)>& run,
                              std::vector<scenes::SceneMetrics>* plugin_runs = nullptr);

}  // namespace dyop::experiments
