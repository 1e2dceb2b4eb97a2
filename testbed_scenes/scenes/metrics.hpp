#pragma once
/// \file
/// What a scene run reports (`SceneMetrics`, the keys of `dyop scene --json`) and the tallies
/// that build it.
///
/// Units: metres, seconds (milliseconds and nanoseconds where the name says so), joules for a
/// density of 1 kg/m². Depths are penetration depths of the triangles themselves (their cores,
/// not Box2D's 1 cm skins), ≥ 0.

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "dyop/box2d.hpp"
#include "dyop/result.hpp"
#include "scenes/runner.hpp"
#include "worlds/fnv1a.hpp"

namespace dyop::scenes {

/// One body of the `slide` scene launched along +x over a flat ground, measured over the whole
/// run (from step 1).
struct SliderFigures {
  /// "box" (2 triangle fixtures), "L" (6), "wheel" (16 fanned from its centre)
  std::string body;
  /// Its ground's top: "one-piece" (two large triangles), "diagonal-1m", "diagonal-0.25m" (square
  /// cells split along a diagonal), "fan-0.25m" (cells split in 4 around their centre).
  std::string ground;
  /// Rolls with friction (the wheel: its centre rises and falls from vertex to vertex by
  /// geometry); false: slides frictionless, expected to glide level.
  bool rolling = false;
  double max_vertical_speed = 0;  ///< largest |v_y| of its centre of mass (m/s)
  double max_angular_speed = 0;   ///< largest |ω| (rad/s)
  /// Distance travelled along x over launch speed × time run (a fraction; 1: a frictionless
  /// glide; below 0 when a trip threw it back).
  double travel = 0;
};

/// The `slide` scene's figures. Its resting box (a box at rest across a junction of two cells) is
/// the scene's watched body: its jitter is `SceneMetrics::top_displacement`.
struct SlideFigures {
  /// Largest |v_y| over the sliding (not rolling) bodies (m/s): 0 for a glide.
  double max_vertical_speed = 0;
  double max_angular_speed = 0;        ///< largest |ω| over the same bodies (rad/s): 0 for a glide
  double min_travel = 0;               ///< smallest `travel` over the same bodies (1: a glide)
  std::vector<SliderFigures> sliders;  ///< every slider, rolling ones included
};

/// `sliders` with their sliding ones' largest speeds and smallest travel.
SlideFigures summarize_sliders(std::vector<SliderFigures> sliders);

/// The largest errors of the manifolds a world's solver got, against the exact answer for the
/// same pose (`ManifoldCheck`, which says how each is measured).
struct ManifoldErrors {
  std::uint64_t touching = 0;  ///< touching triangle pairs checked
  /// Largest |deepest separation − the fresh manifold's| over them (m): what keeping costs.
  double kept_max = 0;
  std::uint64_t stale = 0;    ///< of them, with points where the fresh manifold has none
  std::uint64_t checked = 0;  ///< of them, pairs whose cores penetrate exactly
  double depth_max = 0;       ///< largest |deepest separation − exact separation| over those (m)
  double normal_max = 0;      ///< largest overlap along the normal − exact depth over those (m)
};

/// The figures of one scene run under one runner.
struct SceneMetrics {
  std::string scene;  ///< scene name
  /// What answered the pairs: a backend, or nothing for a Box2D scene run with the plug-in not
  /// installed (Box2D's own contact answers every pair; spelt `box2d_own`).
  Runner runner;
  std::uint64_t seed = 0;  ///< the seed the scene was built with
  int steps = 0;           ///< steps run
  int bodies = 0;          ///< bodies (static and kinematic ones included)
  int triangles = 0;       ///< triangle fixtures (paper: the 10 triangles)
  /// Triangle pairs the narrow phase evaluated in the measured steps (Box2D scenes: the
  /// triangle–triangle contacts `b2ContactManager::Collide` updated in steps 2..N; paper: the
  /// pairs whose bounding boxes overlap, every step).
  std::uint64_t triangle_pairs = 0;
  /// Every contact update in the measured steps, whatever the shapes (= `triangle_pairs` but in
  /// `mixed`, where circles, boxes and edges have contacts of their own).
  std::uint64_t contact_updates = 0;
  /// Box2D scenes: contacts `b2World::SolveTOI` sweeps for a time of impact in the measured steps,
  /// touching or not (an awake body against a static or kinematic one, or a bullet: `toi_swept`).
  std::uint64_t toi_swept = 0;
  /// Box2D scenes: pairs the plug-in's contacts evaluated in all (`stats().evaluations()`: every
  /// family), step 1 and the re-evaluations of Box2D's time-of-impact sub-steps included. None
  /// for `paper`.
  std::optional<std::uint64_t> plugin_evaluations;
  /// Box2D scenes: pairs the backend could not answer, answered by Box2D instead (`stats()`);
  /// 0 means every triangle pair was the backend's. None for `paper`.
  std::optional<std::uint64_t> fallbacks;
  /// Box2D scenes: the narrow-phase work the world was allowed to skip (`--skip`). None for
  /// `paper`, which has no Box2D world.
  std::optional<box2d::Config> skip_config;
  /// Box2D scenes: evaluations of every family answered without running the backend, per reason
  /// (index: `static_cast<int>(box2d::Skip)`), over the whole run like `plugin_evaluations`, of
  /// which they are a part (`stats().skipped`). None for `paper`.
  std::optional<std::array<std::uint64_t, box2d::skip_count>> skips;
  /// Box2D scenes: evaluations that kept the contact's manifold
  /// (`box2d::Config::recycle_distance`, in `skip_config`), over the whole run, of
  /// `plugin_evaluations` (`stats().recycled`). None for `paper`.
  std::optional<std::uint64_t> recycled;
  /// Box2D scenes: contacts the plug-in made (`stats().contacts`), over the whole run. None for
  /// `paper`.
  std::optional<std::uint64_t> contacts_made;
  /// Box2D scenes: of `plugin_evaluations`, those answered afresh: neither kept (`recycled`) nor
  /// skipped (`stats().answered()`). None for `paper`.
  std::optional<std::uint64_t> answered;
  double step_ms_median = 0;  ///< median over the steps of the wall time of one step (ms)
  /// Wall time of all the measured steps together (ms): Box2D scenes, `b2World::Step` in steps
  /// 2..N (what a user of the world waits for); paper, the runner's calls.
  double step_ms_total = 0;
  /// Narrow-phase time over the measured steps (ms): Box2D scenes, the sum of
  /// `b2World::GetProfile().collide` (time in `b2ContactManager::Collide`, contact updates);
  /// paper, the time of the runner's calls.
  double narrowphase_ms_total = 0;
  /// Box2D scenes: time in `b2World::SolveTOI` over the same steps (ms, the sum of
  /// `GetProfile().solveTOI`: the time-of-impact pass); 0 for `paper`.
  double solve_toi_ms_total = 0;
  /// `narrowphase_ms_total` per contact update (ns). Box2D scenes: includes Box2D's own per-contact
  /// work around the call (the broad-phase overlap test, manifold bookkeeping, warm-start match).
  double narrowphase_ns_per_pair = 0;
  /// Deepest exact penetration over the touching triangle pairs after each step (m).
  double max_penetration = 0;
  double mean_penetration = 0;  ///< mean of the same over every (pair, step) sample (m)
  /// Largest |backend depth − exact depth| over the pairs the runner evaluated (m).
  double pd_error_max = 0;
  /// Mean of the same over the evaluated pairs that penetrate by either account (m).
  double pd_error_mean = 0;
  /// Evaluated pairs that the runner called penetrating while exactly apart by more than the
  /// touching band, or not penetrating while exactly deeper than it.
  std::uint64_t misclassified = 0;
  std::uint64_t invalid = 0;        ///< evaluated pairs the runner answered `Invalid`
  double kinetic_energy_final = 0;  ///< Σ ½mv² + ½Iω² of the moving bodies after the last step (J)
  /// Scenes that should stand (pyramids, stacks): largest distance of a top body from where it
  /// was after the first second (`settle_steps`), over the rest of the run (m); `slide`: the
  /// resting box's jitter likewise. None for the other scenes and for runs of less than a
  /// second.
  std::optional<double> top_displacement;
  /// Scene `slide`: its sliders' figures. None for the other scenes.
  std::optional<SlideFigures> slide;
  /// Box2D scenes run with `Scene::check_manifolds`: the manifolds' errors. None otherwise.
  std::optional<ManifoldErrors> manifold_errors;
  bool nan_detected = false;  ///< a non-finite body state or figure appeared
  std::uint64_t hash = 0;     ///< FNV-1a of the final body states: equal seeds, equal hashes
};

/// Backend depths against exact ones, pair by pair.
class ErrorTally {
 public:
  /// One evaluated pair: the runner's answer (`depth` ≥ 0, as `Result::depth`), the exact signed
  /// separation, and the touching band (length) inside which either classification is right.
  void add(Status status, double depth, double exact_separation, double band);
  double max() const { return max_; }
  double mean() const { return overlapping_ > 0 ? sum_ / static_cast<double>(overlapping_) : 0; }
  std::uint64_t misclassified() const { return misclassified_; }
  std::uint64_t invalid() const { return invalid_; }
  std::uint64_t evaluated() const { return evaluated_; }

 private:
  double max_ = 0;
  double sum_ = 0;
  std::uint64_t overlapping_ = 0;
  std::uint64_t misclassified_ = 0;
  std::uint64_t invalid_ = 0;
  std::uint64_t evaluated_ = 0;
};

/// Exact penetration depths of touching pairs, sample by sample.
class PenetrationTally {
 public:
  void add(double depth);
  double max() const { return max_; }
  double mean() const { return count_ > 0 ? sum_ / static_cast<double>(count_) : 0; }
  std::uint64_t count() const { return count_; }

 private:
  double max_ = 0;
  double sum_ = 0;
  std::uint64_t count_ = 0;
};

/// Writes a run's accuracy figures into `m`: penetration (max, mean) and the backend's depth
/// errors (max, mean, misclassified, invalid).
void add_accuracy(const ErrorTally& errors, const PenetrationTally& penetration, SceneMetrics& m);

/// The hash of a scene's final state (`SceneMetrics::hash`), also the paper scene's.
using worlds::Fnv1a;

/// True when every floating-point figure of `m` is finite.
bool all_finite(const SceneMetrics& m);

/// The median of `v` (the mean of the two middle values for an even count); 0 when empty.
double median(std::vector<double> v);

}  // namespace dyop::scenes
