#pragma once
/// \file
/// What `dyop stress` asks of a set of pairs: the answers of a narrow phase
/// (`adapters/narrow_phase.hpp`: the library's per-pair methods, the batch kernel and, in float
/// with Box2D, Box2D's `b2CollidePolygons` through `dyop::box2d::collide_triangles`).

#include <cstdint>
#include <vector>

#include "adapters/narrow_phase.hpp"
#include "dyop/method.hpp"
#include "dyop/result.hpp"
#include "workloads/raw_pair.hpp"

namespace dyop::experiments {

/// Whether `p` runs in this precision in this build: Box2D in float only, and only when built
/// with Box2D; every method of the library in both.
bool stress_runs(const adapters::NarrowPhase& p, bool is_float);

/// One pair's answer at `Level::Depth`, with what the stress figures need of the rest.
struct StressAnswer {
  /// Invalid for a pair whose triangles failed `Triangle<T>::make` (nothing was run), and for a
  /// method's own `Invalid`.
  Status status = Status::Invalid;
  double separation = 0;  ///< signed, valid unless Invalid
  /// Every field the method promises at `Level::Depth` is finite and, for the per-pair methods,
  /// every field of a `Level::Manifold` query of the same pair too (Box2D: the Contact fields of
  /// `collide_triangles`; batch: its separation and normal).
  bool finite = true;
  /// Batch only: the row's validation verdict (`batch_row_error`) differs from
  /// `Triangle<T>::make`'s, or a valid row was answered Invalid: a lost or wrongly kept row.
  bool verdict_mismatch = false;
};

/// The answers of `p` on `pairs` (world coordinates as given, exactly representable in T),
/// one per pair in order. `with_manifold` adds the `Level::Manifold` query to the finiteness
/// check (the per-pair methods; Lin–Canny then runs warm from its Depth query's cache).
template <class T>
std::vector<StressAnswer> stress_answers(const adapters::NarrowPhase& p,
                                         const std::vector<workloads::RawPair>& pairs,
                                         bool with_manifold);

extern template std::vector<StressAnswer> stress_answers<float>(
    const adapters::NarrowPhase&, const std::vector<workloads::RawPair>&, bool);
extern template std::vector<StressAnswer> stress_answers<double>(
    const adapters::NarrowPhase&, const std::vector<workloads::RawPair>&, bool);

}  // namespace dyop::experiments
