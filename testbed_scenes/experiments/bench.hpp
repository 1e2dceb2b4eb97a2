#pragma once
/// \file
/// `dyop bench`'s experiment: run time against error for every narrow phase, input class, query
/// level and precision, with every time also given as a ratio to Box2D's `b2CollidePolygons`
/// measured in the same run.
///
/// Error is measured against the exact rational reference (`exact_reference/exact_reference.hpp`)
/// on the pairs exactly as the precision sees them (float runs get float-rounded input), at
/// `Level::Depth`: |depth − exact depth| relative to the pair's size (the diagonal of the union
/// of both bounding boxes). The same error figures stand on every level's record of a narrow phase.

#include <iosfwd>
#include <vector>

#include "adapters/narrow_phase.hpp"
#include "dyop/result.hpp"
#include "workloads/input_classes.hpp"
#include "workloads/precision.hpp"

namespace dyop::experiments {

struct BenchOptions {
  bool quick = false;  ///< fewer timed passes of ≥ 20 ms (5 instead of 21)
  int pairs = 8192;    ///< distinct pairs per class whose answers are checked against exact ones
  /// Distinct pairs per class timed (seeded alike: the checked pairs are its first ones). More
  /// than a branch predictor learns: one AMD EPYC (AVX-512) host learned the outcomes of a method's
  /// branches over a repeated set of 8192 random pairs and timed `dyop` Depth at 23 ns where
  /// 131,072 pairs gave 38.5 ns (b2CollidePolygons unchanged), which hid what a Zen 3 host showed.
  int timing_pairs = 131072;
};

/// One line of the report.
struct BenchRecord {
  adapters::NarrowPhase method;  ///< what ran (`adapters::name`: "batch", "lin-canny-warm", ...)
  workloads::InputClass cls = workloads::InputClass::General;    ///< the pairs' class
  Level level = Level::Depth;                                    ///< the query level timed
  workloads::Precision precision = workloads::Precision::Float;  ///< the scalar it ran in
  int pairs = 0;               ///< pairs checked (`BenchOptions::pairs`)
  int timed_pairs = 0;         ///< pairs timed (`BenchOptions::timing_pairs`)
  double ns_per_pair = 0;      ///< median over the timed passes
  double ratio_vs_box2d = 0;   ///< ns_per_pair / box2d's (same class, float, manifold)
  double err_max = 0;          ///< max |depth error| / pair size
  double err_mean = 0;         ///< mean of the same
  double err_p99 = 0;          ///< 99th percentile of the same
  double exact_fraction = 0;   ///< fraction of pairs with |depth error| / size ≤ 1e-9
  double normal_err_max = 0;   ///< max angle (rad) to sat's normal on pairs both call penetrating
  double normal_err_mean = 0;  ///< mean of the same
  int misclassified = 0;       ///< penetrating vs not, against the exact sign, outside the band
  int invalid = 0;             ///< pairs it answered Invalid (left out of the errors)
};

/// Runs everything; one progress line per narrow phase and class on `progress`.
std::vector<BenchRecord> run_bench(const BenchOptions& options, std::ostream& progress);

}  // namespace dyop::experiments
