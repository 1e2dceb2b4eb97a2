#pragma once
/// \file
/// What `dyop bench` times and checks: every variant of every row of the method registry
/// (`dyop/method.hpp`; Lin–Canny cold and warm-started, the batch kernel, Box2D's
/// `b2CollidePolygons` in builds with Box2D), run over a prepared pair set.

#include <vector>

#include "dyop/method.hpp"
#include "dyop/result.hpp"
#include "workloads/pair_sets.hpp"

namespace dyop::experiments {

/// Every variant `dyop bench` runs, in registry order (cold before warm).
std::vector<Variant> bench_variants();

/// Whether `v` runs at `level` in float (`is_float`) or double in this build: the levels and
/// precisions of its row (Box2D: its full manifold, in float, timed at `Manifold` only; the batch
/// kernel: `Overlap` and `Depth`), and Box2D only in builds with Box2D.
bool supports(const Variant& v, Level level, bool is_float);

/// One pair's answer at `Level::Depth`, for the error figures.
template <class T>
struct Answer {
  Status status = Status::Invalid;
  T separation = 0;
  Vec2<T> normal = Vec2<T>::Zero();
};

/// Every pair's answer of `v` on `set` at `Level::Depth` (Box2D: its manifold's deepest point, as
/// `dyop::box2d::collide_triangles`; a warm variant: after one warm-up frame).
template <class T>
std::vector<Answer<T>> answers(const Variant& v, const workloads::PairSet<T>& set);

/// Median over `passes` timed passes of the time per pair (ns), at `level`; each pass sweeps the
/// whole set as many times as it takes to last at least 20 ms.
/// Everything a pass needs is prepared before the first one (shapes, caches, arrays).
template <class T>
double time_per_pair(const Variant& v, const workloads::PairSet<T>& set, Level level, int passes);

}  // namespace dyop::experiments
