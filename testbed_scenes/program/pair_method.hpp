#pragma once
/// \file
/// What `dyop pairs` can run on a pair of triangles: every narrow phase that answers single pairs
/// in this build (`adapters/pair_function.hpp`): the library's per-pair methods, and Box2D's own
/// `b2CollidePolygons` when built with Box2D.

#include <string>
#include <vector>

#include "adapters/narrow_phase.hpp"
#include "dyop/method.hpp"

namespace dyop::cli {

/// One narrow phase as `dyop pairs` runs it, at `Level::Depth`, cold.
struct PairMethod {
  adapters::NarrowPhase method;  ///< what runs
  std::string name;              ///< its spelling: "dyop", ..., "box2d"
  /// Double-precision run; nullptr when the method runs in float only (box2d).
  PairFunction<double> run_double = nullptr;
  PairFunction<float> run_float = nullptr;  ///< float run
};

/// What `dyop pairs` runs: every narrow phase of this build that answers single pairs, in
/// registry order (`dyop::pair_methods`), then with Box2D its own code.
std::vector<PairMethod> pairs_methods();

/// The result of a float run widened to double (for one output path).
Result<double> widen(const Result<float>& r);

}  // namespace dyop::cli
