#pragma once
/// \file
/// `lin_canny`: closest-feature tracking (Lin & Canny 1991; V-Clip, Mirtich 1998), the paper's
/// baseline.
///
/// Apart: the state is a feature pair (vertex–vertex, vertex–edge, edge–edge). Each feature is
/// tested against the other's Voronoi region; a violated region names the neighbouring feature to
/// step to, and the walk ends at the pair whose closest points lie in each other's regions: the
/// exact distance. Penetrating: Lin–Canny has no depth of its own; from the feature pair where the
/// walk detected the overlap, the depth walk moves over the Minkowski-difference edges (A's edge
/// normals and B's negated ones) to neighbouring axes while the overlap decreases, and stops at a
/// local minimum of overlap. That local minimum can be larger than the true (global) depth; the
/// error is reported by the benchmarks, not hidden. Both walks are bounded (`lin_canny_max_steps`)
/// and a visited-state guard stops cycling. `iterations` counts the steps of both walks.
///
/// Temporal coherence: pass a caller-owned `LinCannyCache` (one per pair, kept between frames);
/// the next query starts from the feature pair the last one ended on. No heap is used.
/// Conventions: `dyop/result.hpp`.

#include <cstdint>

#include "dyop/result.hpp"
#include "dyop/triangle.hpp"

namespace dyop {

/// The last feature pair of one triangle pair, for a warm start. Default-constructed: cold.
struct LinCannyCache {
  bool valid = false;          ///< false: start cold
  Feature::Type type_a = Feature::Type::Vertex;  ///< last feature of A (CCW index below)
  Feature::Type type_b = Feature::Type::Vertex;  ///< last feature of B (CCW index below)
  std::uint8_t index_a = 0;    ///< CCW index in A (not the caller's: a cache is opaque state)
  std::uint8_t index_b = 0;    ///< CCW index in B
  std::uint8_t depth_axis = 0; ///< last axis of the depth walk: 0..2 A's edges, 3..5 B's edges
};

/// Upper bound on the steps of one walk. Why: a feature walk on two triangles visits at most
/// 6 × 6 feature pairs, and the depth walk at most 6 axes; twice that is a generous guard.
constexpr int lin_canny_max_steps = 72;

/// Closest features / local-minimum depth of `a` and `b`; `cache` may be nullptr (cold start).
template <class T>
Result<T> lin_canny(const Triangle<T>& a, const Triangle<T>& b, const Query<T>& query = {},
                    LinCannyCache* cache = nullptr);

extern template Result<float> lin_canny(const Triangle<float>&, const Triangle<float>&,
                                        const Query<float>&, LinCannyCache*);
extern template Result<double> lin_canny(const Triangle<double>&, const Triangle<double>&,
                                         const Query<double>&, LinCannyCache*);

}  // namespace dyop
