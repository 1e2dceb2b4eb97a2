#pragma once
/// \file
/// `dyop stress`'s convex part: the exact solver (`dyop::collide`) on the pairs beyond two
/// triangles — polygon–polygon (3 to 8 vertices, `SetAsBox` boxes among them), polygon–circle,
/// segment–polygon and segment–circle (a Box2D edge against either) —
/// per input class (`workloads/convex_classes.hpp`) and precision, against the exact rational
/// reference, with the figures of `experiments/stress.hpp`: error / pair size, misclassified
/// status outside the band 4·`touching_tolerance`·size, NaN/inf, and the winding check (A's and
/// B's vertices given in the other order must give the same separation within `exact_bound`).

#include <iosfwd>
#include <string>
#include <vector>

#include "experiments/stress.hpp"
#include "workloads/convex_classes.hpp"

namespace dyop::experiments {

/// The pair families beyond two triangles.
enum class ConvexFamily : std::uint8_t { Polygons, PolygonCircle, SegmentPolygon, SegmentCircle };

/// "polygon-polygon", "polygon-circle", "segment-polygon", "segment-circle".
const char* name(ConvexFamily f);

/// One family on one class in one precision.
struct ConvexStressRecord {
  ConvexFamily family = ConvexFamily::Polygons;                      ///< what was paired
  workloads::ConvexClass cls = workloads::ConvexClass::Overlapping;  ///< the class
  workloads::Precision precision = workloads::Precision::Double;     ///< the scalar it ran in
  int pairs = 0;                                                     ///< pairs generated (valid)
  int nonfinite = 0;      ///< answers at any level with a NaN or inf field
  int misclassified = 0;  ///< status not the exact sign's outside the band
  double err_max = 0;     ///< max |separation − exact| / size
  double err_p99 = 0;     ///< 99th percentile of the same
  int winding = 0;        ///< pairs whose separation moved beyond `exact_bound` when rewound
};

/// Runs every family on every convex class in the precisions asked for (`options.pairs` pairs
/// each); one progress line per family, class and precision on `progress`.
std::vector<ConvexStressRecord> run_convex_stress(const StressOptions& options,
                                                  std::ostream& progress);

/// The promises `records` break (exact within `exact_bound`, no misclassification, no NaN/inf,
/// winding kept), one line each.
std::vector<std::string> broken_convex_promises(const std::vector<ConvexStressRecord>& records);

}  // namespace dyop::experiments
