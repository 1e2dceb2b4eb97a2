#pragma once
/// \file
/// Exact penetration depth, distance and contact manifold of a convex polygon against a convex
/// polygon (3 to 8 vertices each) or against a circle, and of a segment (a Box2D edge) against
/// either: the pairs beyond two triangles, answered exactly as `sat` answers triangles (DyOP-PD
/// stays the method for triangle pairs).
///
/// Algorithm: the Minkowski difference of two convex polygons has as edge normals exactly A's edge
/// normals and B's negated ones, so the depth is the least overlap `max_A(u·a) − min_B(u·b)` over
/// those axes, and a pair apart is at the least of the vertex–segment distances. A circle of
/// radius r and centre c against a polygon P: separation = signed distance of c from P − r (inside
/// P: minus the least distance of c to an edge line). A segment is the polygon of its two sides
/// (`Segment`): the bare segment, of no thickness, so its axes are its normal both ways. Computed
/// in a frame centred on A's first vertex, so accuracy is relative to the shapes' size, not to
/// their distance from the origin. Conventions (normal from A to B, signed separation, the status,
/// levels, `Apart`, the manifold and its keys): `dyop/result.hpp`; shapes and caller's order:
/// `dyop/polygon.hpp`.

#include <cstdint>
#include <limits>

#include "dyop/polygon.hpp"
#include "dyop/result.hpp"

namespace dyop {

/// The internal-edge rule's masks of one shape (`InternalEdges` for a pair of triangles), bits in
/// the caller's order: bit i is edge i (from vertex i to i + 1) or vertex i. Meaning as there:
/// an internal edge's normal is no direction the body's outline allows; no axis of the other shape
/// whose deepest vertex is a closed vertex is allowed, but for an outline edge at it lying flat on
/// the axis's face (for a circle: no push along a closed vertex's normals).
struct ShapeMasks {
  std::uint8_t edges = 0;            ///< edges internal to their body
  std::uint8_t closed_vertices = 0;  ///< vertices where the outline allows only other axes
  /// True when any edge or vertex is marked: only then can the rule change an answer.
  constexpr bool any() const { return (edges | closed_vertices) != 0; }
};

/// True when `x` and `y` mark the same edges and vertices.
constexpr bool operator==(ShapeMasks x, ShapeMasks y) {
  return x.edges == y.edges && x.closed_vertices == y.closed_vertices;
}

/// A query of a convex pair: `Query`'s fields (same meanings and defaults) with one mask per
/// shape.
template <class T>
struct ConvexQuery {
  Level level = Level::Depth;  ///< what to compute
  /// Manifold only: points kept while their separation is at most this (length units; Box2D
  /// passes the sum of the skins). Default 0.
  T margin = 0;
  /// Manifold only, two polygons: B's face is the reference only when its separation exceeds A's
  /// best by more than this (length units; Box2D: 0.1·linearSlop). Default 0.
  T face_hysteresis = 0;
  /// Level ≥ Depth: the distance of a pair found apart, or only a gap that proves it (`Apart`).
  Apart apart = Apart::Distance;
  /// A's internal-edge masks (see `ShapeMasks`, `Query::internal_edges`). Default: none.
  ShapeMasks masks_a{};
  /// B's internal-edge masks; ignored for a circle. Default: none.
  ShapeMasks masks_b{};
  /// Level::Manifold only: false leaves the Contact level's fields at their defaults.
  bool witnesses = true;
  /// Manifold only: `Manifold::lead` is looked for up to this (length units); a lead at least
  /// this comes back +infinity. Default +infinity: always the lead.
  T lead_reach = std::numeric_limits<T>::infinity();
};

/// Exact answer for two convex polygons at `query.level` (any vertex counts, triangles included).
/// With masks, as `Query::internal_edges` says for triangles: the status (and a pair apart) over
/// every axis; otherwise depth, normal and reference face from the least usable axis.
template <class T>
Result<T> collide(const Polygon<T>& a, const Polygon<T>& b, const ConvexQuery<T>& query = {});

/// Exact answer for polygon `a` and circle `b` at `query.level`. Features of the circle: vertex 0
/// (its centre). Contact level: `witness_b` is the circle's point deepest toward A (centre minus
/// radius along `normal`), `witness_a` the polygon's point nearest the centre (penetrating: its
/// projection on the face). Manifold: at most one point, that of `witness_b`, key 0 (Box2D's
/// circle contacts carry one id), on A's face `reference_edge`: the face the centre lies farthest
/// beyond (for a centre nearest a vertex, `normal` points from that vertex to the centre). With
/// `masks_a`, a push along an internal edge's normal or a closed vertex's is replaced by the least
/// push along an allowed edge normal the circle reaches; none: the manifold is empty.
template <class T>
Result<T> collide(const Polygon<T>& a, const Circle<T>& b, const ConvexQuery<T>& query = {});

/// Exact answer for segment `a` (A, as Box2D orders an edge and a polygon) and polygon `b` at
/// `query.level`: as for two polygons, the segment's sides being its two edges (`Segment`).
/// `masks_a` are the segment's: edge bit 1 set keeps every push off its back (a one-sided edge),
/// vertex bits 0 and 1 close its ends where a neighbour continues it flat or reflex.
template <class T>
Result<T> collide(const Segment<T>& a, const Polygon<T>& b, const ConvexQuery<T>& query = {});

/// Exact answer for segment `a` and circle `b` at `query.level`: as for a polygon and a circle,
/// the face the centre lies on being the side (the front on the segment's line itself).
template <class T>
Result<T> collide(const Segment<T>& a, const Circle<T>& b, const ConvexQuery<T>& query = {});

/// \cond EXPLICIT_INSTANTIATIONS
extern template Result<float> collide(const Segment<float>&, const Polygon<float>&,
                                      const ConvexQuery<float>&);
extern template Result<double> collide(const Segment<double>&, const Polygon<double>&,
                                       const ConvexQuery<double>&);
extern template Result<float> collide(const Segment<float>&, const Circle<float>&,
                                      const ConvexQuery<float>&);
extern template Result<double> collide(const Segment<double>&, const Circle<double>&,
                                       const ConvexQuery<double>&);
extern template Result<float> collide(const Polygon<float>&, const Polygon<float>&,
                                      const ConvexQuery<float>&);
extern template Result<double> collide(const Polygon<double>&, const Polygon<double>&,
                                       const ConvexQuery<double>&);
extern template Result<float> collide(const Polygon<float>&, const Circle<float>&,
                                      const ConvexQuery<float>&);
extern template Result<double> collide(const Polygon<double>&, const Circle<double>&,
                                       const ConvexQuery<double>&);
/// \endcond

}  // namespace dyop
