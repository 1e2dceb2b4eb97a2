#pragma once
/// \file
/// What `dyop pairs` can run on pairs of triangles: every narrow phase that answers single pairs
/// in this build (`adapters/pair_function.hpp`): the library's per-pair methods, and Box2D's own
/// `b2CollidePolygons` when built with Box2D; and the batch kernel over all the input's pairs.

#include <string>
#include <vector>

#include "adapters/narrow_phase.hpp"
#include "dyop/method.hpp"

namespace dyop::cli {

/// One narrow phase as `dyop pairs` runs it, at `Level::Depth`, cold.
struct PairMethod {
  adapters::NarrowPhase method;  ///< what runs
  std::string name;              ///< its spelling: "dyop", ..., "batch", "box2d"
  /// Double-precision run; nullptr when the method runs in float only (box2d) or over many pairs
  /// at once (batch: `batch()`).
  PairFunction<double> run_double = nullptr;
  PairFunction<float> run_float = nullptr;  ///< float run; nullptr for the batch kernel

  /// True for the batch kernel, which answers every pair of the input in one call.
  bool batch() const { return adapters::call_of(method) == adapters::Call::Batch; }
};

/// What `dyop pairs` runs: every narrow phase of this build that answers pairs, in registry order
/// (`dyop::method_table`: the per-pair methods, then the batch kernel), then with Box2D its own
/// code.
std::vector<PairMethod> pairs_methods();

/// The result of a float run widened to double (for one output path).
Result<double> widen(const Result<float>& r);

}  // namespace dyop::cli
