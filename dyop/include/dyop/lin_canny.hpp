#pragma once
/// \file
/// `lin_canny`: closest-feature tracking (Lin & Canny 1991; V-Clip, Mirtich 1998), the paper's
/// baseline. All arithmetic is in the pair's local frame (A's first vertex subtracted first).
///
/// Feature walk: the state is a feature pair (vertex–vertex, vertex–edge, edge–edge), starting
/// cold from vertex 0 of A and vertex 0 of B (CCW order). Each state tests each feature's closest
/// point against the other feature's Voronoi region; a violated region names the neighbouring
/// feature to step to. In 2D V-Clip's edge–edge clipping reduces to "the two edges cross, or their
/// closest points include an end of one of them", so an edge–edge state either detects the
/// overlap or moves to that end. A vertex behind an edge's line is either inside the other
/// triangle (overlap) or outside another of its edges, which becomes the new feature (Mirtich's
/// escape from a local minimum). The walk ends at the pair whose closest points lie in each
/// other's regions: that proves the pair apart, and the distance is exact (vertex–edge distances
/// are taken along the edge's unit normal, as `sat` takes them). The walk also ends when it finds
/// the triangles meeting: a vertex inside the other triangle, two edges crossing, or a final
/// distance within the touching band (`touching_tolerance` times the larger triangle's size).
///
/// Depth walk: Lin–Canny has no depth of its own. The six candidate axes (A's edge normals and B's
/// negated ones, the edge normals of the Minkowski difference A − B) sorted by angle form a cycle.
/// The walk starts from the least overlap among the axes of the edges that bound the meeting
/// feature pair and, when warm, the cached depth axis (alone, a cached axis could strand a pair
/// that merely touches in a positive local minimum), and moves to the neighbour with the smaller
/// overlap while the overlap strictly decreases. It stops at a local minimum of overlap, which can
/// be larger than the true (global) depth that `sat` finds (never smaller: it is one of the same
/// six overlaps); the error is reported by the benchmarks, not hidden. The status of a meeting
/// pair is that local minimum classified against the touching band.
///
/// Cycling guard: a visited set (one bit per feature pair, 36 in all) stops the feature walk when
/// a state repeats, as rounding at near-ties (nearly parallel edges) can make it do; the depth
/// walk cannot repeat an axis (its overlap strictly decreases). When the guard trips, the least
/// distance seen (a true distance between points of A and B) is the answer if its direction
/// separates the triangles by more than the touching band; otherwise the pair is treated as
/// meeting and the depth walk decides. `iterations` counts the feature pairs visited plus the
/// axes evaluated, at most 36 + 6 ≤ `lin_canny_max_steps`.
///
/// Levels: `Level::Overlap` stops as soon as the status is known (a proven separation, or a vertex
/// deeper than the touching band inside the other triangle). A separated pair's manifold
/// (`Level::Manifold`, within `margin`) is clipped on the face of the final feature pair best
/// aligned with the normal; a meeting pair's on the face of the depth walk's axis.
///
/// Temporal coherence: pass a caller-owned `LinCannyCache` (one per pair, kept between frames);
/// the next query starts from the feature pair the last one ended on, and its depth walk also
/// tries the last depth axis. No heap is used. Conventions: `dyop/result.hpp`.

#include <cstdint>

#include "dyop/result.hpp"
#include "dyop/triangle.hpp"

namespace dyop {

/// The last feature pair of one triangle pair, for a warm start. Default-constructed: cold.
struct LinCannyCache {
  bool valid = false;                            ///< false: start cold
  Feature::Type type_a = Feature::Type::Vertex;  ///< last feature of A (CCW index below)
  Feature::Type type_b = Feature::Type::Vertex;  ///< last feature of B (CCW index below)
  std::uint8_t index_a = 0;  ///< CCW index in A (not the caller's: a cache is opaque state)
  std::uint8_t index_b = 0;  ///< CCW index in B
  /// A start for the next depth walk: 0..2 A's edges, 3..5 B's edges (CCW). The last depth walk's
  /// axis; after a query that ended apart, the final pair's face best aligned with the normal.
  std::uint8_t depth_axis = 0;
};

/// Bound on `iterations` and on the feature walk's loop. Why: with the visited-state guard the
/// feature walk visits at most 6 × 6 feature pairs and the depth walk evaluates at most 6 axes,
/// 42 steps in all; twice the feature pairs is a generous bound that never cuts a walk short.
constexpr int lin_canny_max_steps = 72;

/// Closest features / local-minimum depth of `a` and `b`; `cache` may be nullptr (cold start).
template <class T>
Result<T> lin_canny(const Triangle<T>& a, const Triangle<T>& b, const Query<T>& query = {},
                    LinCannyCache* cache = nullptr);

/// \cond EXPLICIT_INSTANTIATIONS
extern template Result<float> lin_canny(const Triangle<float>&, const Triangle<float>&,
                                        const Query<float>&, LinCannyCache*);
extern template Result<double> lin_canny(const Triangle<double>&, const Triangle<double>&,
                                         const Query<double>&, LinCannyCache*);
/// \endcond

}  // namespace dyop
