#pragma once
/// \file
/// One pair through any method of the registry (`dyop/method.hpp`) that can answer single pairs
/// in this build: the library's per-pair methods through their own entry points, and Box2D's
/// `b2CollidePolygons` (float, in builds with Box2D) through `box2d::collide_triangles`, Box2D's
/// answer under the library's conventions. Every tool that runs methods pair by pair (`dyop
/// pairs`, `dyop stress`, the scenes' depth checks, the paper experiment) calls them through this.

#include "dyop/method.hpp"

namespace dyop::adapters {

/// The entry point of `m` for single pairs in precision T, or nullptr when this build cannot run
/// it so: `Batch` (many pairs per call), `Box2D` in double or without Box2D. Box2D's answer is
/// its manifold's deepest point with `Level::Contact`'s fields, whatever the query asks, and it
/// keeps no warm-start state.
template <class T>
PairFunction<T> pair_function(Method m);

/// True when `pair_function<T>(m)` is not nullptr.
template <class T>
bool runs_pairs(Method m) {
  return pair_function<T>(m) != nullptr;
}

extern template PairFunction<float> pair_function<float>(Method);
extern template PairFunction<double> pair_function<double>(Method);

}  // namespace dyop::adapters
