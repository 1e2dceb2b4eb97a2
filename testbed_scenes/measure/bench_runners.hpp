#pragma once
/// \file
/// What `dyop bench` times and checks: every method of the library, Lin–Canny cold and
/// warm-started, Box2D's `b2CollidePolygons` and the batch kernel, run over a prepared pair set.

#include <vector>

#include "dyop/result.hpp"
#include "workloads/pair_sets.hpp"

namespace dyop::report {

enum class Runner {
  Dyop, DyopFast, DyopPaper, LinCannyCold, LinCannyWarm, Sat, Epa, Box2D, Batch,
};

inline constexpr Runner all_runners[] = {
    Runner::Dyop, Runner::DyopFast, Runner::DyopPaper, Runner::LinCannyCold, Runner::LinCannyWarm,
    Runner::Sat,  Runner::Epa,      Runner::Box2D,     Runner::Batch};

/// "dyop", "dyop-fast", "dyop-paper", "lin-canny", "lin-canny-warm", "sat", "epa", "box2d",
/// "batch".
const char* name(Runner r);

/// Whether `r` runs at `level` in float (`is_float`) or double: Box2D always builds its full
/// manifold, in float, and is timed at `Manifold` only; the batch kernel has `Overlap` and
/// `Depth`; Box2D is absent from builds without Box2D.
bool supports(Runner r, Level level, bool is_float);

/// One pair's answer at `Level::Depth`, for the error figures.
template <class T>
struct Answer {
  Status status = Status::Invalid;
  T separation = 0;
  Vec2<T> normal = Vec2<T>::Zero();
};

/// Every pair's answer of `r` on `set` at `Level::Depth` (Box2D: its manifold's deepest point, as
/// `dyop::box2d::collide_triangles`; warm Lin–Canny: after one warm-up frame).
template <class T>
std::vector<Answer<T>> answers(Runner r, const workloads::PairSet<T>& set);

/// Median over `passes` timed passes of the time per pair (ns), at `level`; each pass sweeps the
/// whole set as many times as it takes to last at least 20 ms.
/// Everything a pass needs is prepared before the first one (shapes, caches, arrays).
template <class T>
double time_per_pair(Runner r, const workloads::PairSet<T>& set, Level level, int passes);

}  // namespace dyop::report
