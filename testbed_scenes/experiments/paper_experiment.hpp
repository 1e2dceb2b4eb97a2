#pragma once
/// \file
/// The paper's experiment (its Figure 7) over the `paper` scene's triangles and paths
/// (`scenes/paper.hpp`): every method timed over the same steps, in float, at `Level::Depth`
/// with `Apart::Gap`, and its errors against the exact rational reference.

#include <array>
#include <cstdint>
#include <vector>

#include "adapters/narrow_phase.hpp"
#include "scenes/paper.hpp"

namespace dyop::experiments::paper {

using scenes::paper::experiment_steps;
using scenes::paper::type_count;

/// The narrow phases of the experiment, in registry order (`dyop/method.hpp`): every row that
/// answers single pairs in float (`adapters::pair_function`), Lin–Canny both cold and
/// warm-started (a state per pair kept from step to step, as the Box2D plug-in keeps one per
/// contact); then Box2D's `b2CollidePolygons` through `box2d::collide_triangles`.
std::vector<adapters::NarrowPhase> experiment_methods();

/// One method's figures. Times are medians over the repetitions, in microseconds for the whole
/// run (all steps), as the paper gives milliseconds "for all 90 simulation steps".
struct MethodFigures {
  adapters::NarrowPhase method;  ///< the method, cold or warm, or Box2D's
  /// Per type: the time of every bounding-box-overlapping pair the type is in, over all steps
  /// (each pair counts for both its types, as each triangle is tested against the others).
  std::array<double, type_count> us_per_type{};
  double us_total = 0;      ///< every bounding-box-overlapping pair once, over all steps
  double us_all_pairs = 0;  ///< all 45 pairs every step, no broad phase (the literal n-body)
  double ns_per_pair = 0;   ///< `us_total` per pair tested
  double error_max = 0;     ///< max |depth − exact depth| over the pairs tested
  double error_mean = 0;    ///< mean of the same over the pairs penetrating by either account
  std::uint64_t misclassified = 0;  ///< as `SceneMetrics::misclassified`
  std::uint64_t invalid = 0;        ///< pairs answered `Invalid` (dyop-paper: vertical edges)
};

/// The whole experiment.
struct Experiment {
  std::uint64_t seed = 0;
  int steps = experiment_steps;
  int repetitions = 0;                  ///< timed repetitions; each figure is their median
  std::uint64_t pairs_tested = 0;       ///< (pair, step) samples whose bounding boxes overlap
  std::uint64_t pairs_penetrating = 0;  ///< of those, exactly penetrating
  std::array<std::uint64_t, type_count> pairs_per_type{};  ///< samples each type is in
  std::vector<MethodFigures> methods;                      ///< in `experiment_methods()` order
};

/// Runs the experiment: `repetitions` timed passes of every method (interleaved, so that the
/// machine's drifts fall on all of them alike), then one untimed pass for the errors.
Experiment run_experiment(std::uint64_t seed, int steps, int repetitions);

}  // namespace dyop::experiments::paper
