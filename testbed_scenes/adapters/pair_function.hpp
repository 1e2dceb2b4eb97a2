#pragma once
/// \file
/// One pair through any narrow phase (`adapters/narrow_phase.hpp`) that can answer single pairs
/// in this build: the library's per-pair methods through the registry's entry points, and Box2D's
/// `b2CollidePolygons` (float, in builds with Box2D) through `box2d::collide_triangles`, Box2D's
/// answer under the library's conventions. Every tool that runs narrow phases pair by pair
/// (`dyop pairs`, `dyop stress`, the scenes' depth checks, the paper experiment) calls them
/// through this.

#include "adapters/narrow_phase.hpp"
#include "dyop/method.hpp"

namespace dyop::adapters {

/// The entry point of `p` for single pairs in precision T, or nullptr when this build cannot run
/// it so: the batch kernel (many pairs per call), Box2D in double or without Box2D. Box2D's
/// answer is its manifold's deepest point with `Level::Contact`'s fields, whatever the query
/// asks, and it keeps no warm-start state. Whether to warm-start is the caller's (it keeps the
/// `PairState`).
template <class T>
PairFunction<T> pair_function(const NarrowPhase& p);

/// True when `pair_function<T>(p)` is not nullptr.
template <class T>
bool runs_pairs(const NarrowPhase& p) {
  return pair_function<T>(p) != nullptr;
}

extern template PairFunction<float> pair_function<float>(const NarrowPhase&);
extern template PairFunction<double> pair_function<double>(const NarrowPhase&);

}  // namespace dyop::adapters
