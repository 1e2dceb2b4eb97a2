#pragma once
/// \file
/// What `dyop bench` times and checks: every narrow phase (`adapters/narrow_phase.hpp`: each
/// method of the registry, Lin–Canny cold and warm-started, the batch kernel, and Box2D's
/// `b2CollidePolygons` in builds with Box2D), run over a prepared pair set: the answers, and the
/// time per pair.

#include <vector>

#include "adapters/narrow_phase.hpp"
#include "dyop/method.hpp"
#include "dyop/result.hpp"
#include "workloads/pair_sets.hpp"

namespace dyop::experiments {

using adapters::NarrowPhase;

/// Every narrow phase `dyop bench` runs: the registry's variants in its order (cold before warm),
/// then Box2D's `b2CollidePolygons` in builds with Box2D.
std::vector<NarrowPhase> bench_phases();

/// Whether `p` runs at `level` in float (`is_float`) or double in this build: its levels and
/// precisions (Box2D: its full manifold, in float, timed at `Manifold` only; the batch kernel:
/// `Overlap` and `Depth`), and Box2D only in builds with Box2D.
bool supports(const NarrowPhase& p, Level level, bool is_float);

/// One pair's answer at `Level::Depth`, for the error figures.
template <class T>
struct Answer {
  Status status = Status::Invalid;
  T separation = 0;
  Vec2<T> normal = Vec2<T>::Zero();
};

/// Every pair's answer of `p` on `set` at `Level::Depth` (Box2D: its manifold's deepest point, as
/// `dyop::box2d::collide_triangles`; a warm variant: after one warm-up frame).
template <class T>
std::vector<Answer<T>> answers(const NarrowPhase& p, const workloads::PairSet<T>& set);

/// Median over `passes` timed passes of the time per pair (ns), at `level`; each pass sweeps the
/// whole set as many times as it takes to last at least 20 ms.
/// Everything a pass needs is prepared before the first one (shapes, caches, arrays).
template <class T>
double time_per_pair(const NarrowPhase& p, const workloads::PairSet<T>& set, Level level,
                     int passes);

}  // namespace dyop::experiments
