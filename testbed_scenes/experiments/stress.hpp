#pragma once
/// \file
/// `dyop stress`'s experiment: numerical stability on hostile input, as figures per narrow
/// phase, input category and precision.
///
/// Every figure is measured against the exact rational reference
/// (`exact_reference/exact_reference.hpp`) on the pairs exactly as the precision sees them (float
/// runs get float-rounded input):
/// - error: |separation − exact separation| / pair size (separation is −depth when penetrating,
///   the distance when apart; size is the diagonal of the union of both bounding boxes);
/// - misclassified: the status is not the exact one (Penetrating below −band, Separated above
///   +band) where the exact separation is outside the band 4·`touching_tolerance`·size;
/// - invariance: a pair moved (translated; turned about its centre), reordered (A's vertices
///   rotated, B's winding reversed) or swapped (B, A) must change the separation as the exact
///   reference's changes (moved inputs are rounded again, which moves the exact answer too),
///   within `workloads::exact_bound` · size; a violation is a pair where it does not.

#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

#include "experiments/stress_answers.hpp"
#include "workloads/input_classes.hpp"

namespace dyop::experiments {

struct StressOptions {
  int pairs = 5000;           ///< pairs per category and precision
  std::uint64_t seed = 2027;  ///< the same seed gives the same pairs and figures
  bool run_double = true;     ///< measure the double instantiation
  bool run_float = true;      ///< measure the float instantiation (and Box2D)
};

/// `p` promises the exact answer (error within `workloads::exact_bound`, no misclassification): the
/// registry's `Accuracy::Exact` rows (sat, dyop and the batch kernel, sat's arithmetic).
bool promises_exact(const adapters::NarrowPhase& p);

/// `p` promises invariance under motion, reordering and swapping: the registry's invariant rows
/// (`MethodInfo::invariant`: sat, dyop, epa, batch).
/// dyop-fast's pivot comes from axis-aligned boxes, dyop-paper's eq. 8 divides by a distance
/// from the origin, and Lin–Canny ends in a local minimum that depends on where its walk starts:
/// their violations are figures, not failures.
bool promises_invariance(const adapters::NarrowPhase& p);

/// The invariance checks, in the order of `StressRecord::invariance`.
enum class Invariance : std::uint8_t { Translation, Rotation, Reorder, Swap };
inline constexpr int invariance_count = 4;
/// "translation", "rotation", "reorder", "swap".
const char* name(Invariance i);

/// One narrow phase on one category in one precision.
struct StressRecord {
  adapters::NarrowPhase method;  ///< what ran; every run is cold (`adapters::name`)
  workloads::InputClass cls = workloads::InputClass::General;     ///< the category
  workloads::Precision precision = workloads::Precision::Double;  ///< the scalar it ran in
  int pairs = 0;                                                  ///< pairs generated
  /// Pairs with a triangle that `Triangle<T>::make` rejects (degenerate, too large, ...): each
  /// gets a clear error and is not run; not a failure.
  int rejected = 0;
  /// dyop-paper only: its documented `Invalid` (vertical edge, P at the origin, slope overflow).
  int invalid_by_design = 0;
  /// Failures: a valid pair answered `Invalid` (other than by design), or a batch row whose
  /// verdict differs from `Triangle<T>::make`'s (a lost or wrongly kept row).
  int invalid = 0;
  int nonfinite = 0;      ///< answers (any variant, any level run) with a NaN or inf field
  int misclassified = 0;  ///< see the file comment
  double err_max = 0;     ///< max error / size over the answered pairs
  double err_p99 = 0;     ///< 99th percentile of the same
  int invariance[invariance_count] = {0, 0, 0, 0};  ///< violations per `Invariance`
  /// The pair of the largest error as a `dyop pairs` CSV line (empty when none was answered).
  std::string worst_pair;
};

/// Runs every narrow phase on every category in the precisions asked for; one progress line per
/// precision and category on `progress`.
std::vector<StressRecord> run_stress(const StressOptions& options, std::ostream& progress);

/// The promises `records` break (`promises_exact`, `promises_invariance`, no `invalid` anywhere,
/// and no non-finite answer from the library: Box2D's own NaNs are figures, not promises), one
/// sentence each; empty when all hold.
std::vector<std::string> broken_promises(const std::vector<StressRecord>& records);

}  // namespace dyop::experiments
