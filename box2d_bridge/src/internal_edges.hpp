#pragma once
// Internal: the internal-edge masks of a world's polygon fixture (`Config::internal_edges`), and
// what a two-sided edge's ends meet,
// found from the fixtures as they are now: the triangles near it that share edges with it (its
// body's, and for a static body every static body's), looked up in the world's own broad phase.
// Nothing is kept outside the world's contacts and fixtures (a static polygon's last finding is
// memoised in its own shape: edge_data_memo.hpp): no table that a deleted world could leave
// behind, a reused address could fool, or another thread could share.

#include <box2d/b2_body.h>
#include <box2d/b2_fixture.h>

#include <box2d/b2_polygon_shape.h>

#include <cmath>
#include <cstdint>

#include "dyop/box2d.hpp"
#include "dyop/convex_pair.hpp"
#include "dyop/result.hpp"

namespace dyop::box2d::detail {

// A vertex outline turning by less than this (the sine of the angle between its two outline
// edges) counts as flat. Why: vertices placed on one line by float arithmetic (i · cell) are
// collinear to ~1e-7 relative, and a turn of a thousandth of a radian is no corner: the own
// edge's normal is within that angle of the outline's.
constexpr float flat_outline_sine = 1e-3f;

// True when an outline running along `in` then `out` (the solid on its left, as a CCW polygon's)
// turns left by less than `flat_outline_sine`, or right: flat or reflex, seen from the solid.
inline bool turns_flat_or_reflex(const b2Vec2& in, const b2Vec2& out) {
  return b2Cross(in, out) <= flat_outline_sine * in.Length() * out.Length();
}

// True when triangles of bodies `a` and `b` share edges: the same body, or two static bodies.
// Dynamic and kinematic bodies keep their edges to themselves (they move apart).
inline bool share_edges(const b2Body& a, const b2Body& b) {
  return &a == &b || (a.GetType() == b2_staticBody && b.GetType() == b2_staticBody);
}

// The masks of `fixture`'s triangle in Box2D's vertex order, bits 0..2 (edge i from
// m_vertices[i] to [i + 1]); empty for any other shape and for a non-static fixture alone on its
// body. Its edge group: the triangle fixtures of bodies that share edges with its body
// (`share_edges`), all taken in its body's frame (exactly when two bodies' transforms are equal).
// - An edge is internal when the union of the group's edges collinear with it and running the
//   other way (the other side of the line) covers it wholly, within `coincidence_tolerance`: the
//   same edge of a neighbour, or the edges of a refined neighbour meeting it at T-junctions. An
//   edge covered in part stays an outline edge.
// - The outline is made of the group's edges (and parts of edges) that no opposite edge covers.
//   A vertex is closed when both of its edges are internal, or when one is and the outline through
//   it is flat or reflex: one outline piece in and one out, from the edges that end there or, at a
//   T-junction, from an edge that passes through it (which is straight there).
// Every triangle of the group touching the fixture's triangle overlaps its box, so the world's
// broad phase finds them all; cost: one query of that box (a walk of a small non-static
// body's fixtures instead).
InternalEdges triangle_internal_edges(const b2Fixture& fixture);

// The same for a polygon fixture of any vertex count (bits 0..count−1, Box2D's order); its edge
// group holds polygons of every vertex count. Empty for a circle, edge or chain.
ShapeMasks polygon_internal_edges(const b2Fixture& fixture);

// A vertex of a polygon where edges or chains of its group meet its outline (a two-sided edge
// going on from a tile map's corner, a ramp onto it): the edges split the free space around the
// vertex, and which of the polygon's two edges there bounds a body's part of it depends on where
// the body is (`junction_masks`). The free space is what lies between the polygon's own edge into
// the vertex and its edge out, turning counter-clockwise; the rays from the vertex along the
// group's edges and polygons' edges within it split it. Directions are angles in the polygon's
// body frame (`junction_angle`).
struct Junction {
  static constexpr std::uint8_t none = 0xFF;
  std::uint8_t vertex = none;  // the vertex (Box2D's order); `none`: no junction
  bool closed_in = false;      // the part next to its edge in spans at most a half-turn
  bool closed_out = false;     // the part next to its edge out spans at most a half-turn
  std::int16_t first = 0;      // the first ray met turning from its edge in
  std::int16_t last = 0;       // the last ray met before its edge out
};

// `angle` (radians, [−π, π]) as a `Junction`'s direction, and back.
inline std::int16_t junction_angle(float angle) {
  return static_cast<std::int16_t>(std::lround(angle * (32767 / b2_pi)));
}
inline float junction_angle(std::int16_t code) { return code * (b2_pi / 32767); }

// A polygon fixture's masks and its junction (the first vertex that has one).
struct PolygonEdgeData {
  ShapeMasks masks;
  Junction junction;
};

// `polygon_internal_edges`, and the polygon's junction. A static polygon's is memoised in its
// shape under the fingerprint of what it is found from (edge_data_memo.hpp): a finding with the
// same fingerprint costs the broad-phase query alone.
PolygonEdgeData polygon_edge_data(const b2Fixture& fixture);

// The masks a polygon `p` with junction `j` adds for a body whose centroid is at `other` (p's
// body frame): in the free space next to the polygon's edge into the vertex, up to the first ray,
// its edge out of the vertex is internal; next to its edge out, after the last, its edge in;
// between the two, both. The vertex is closed where the body's part of the free space spans at
// most a half-turn (flat within `flat_outline_sine`, or reflex; between two rays, always).
// Nothing for a body within the polygon's own corner.
ShapeMasks junction_masks(const Junction& j, const b2PolygonShape& p, const b2Vec2& other);

// The masks (`Segment`'s bits) of a two-sided edge for a body on its front (`back` false) or its
// back: nothing when its ends meet nothing (both sides, as Box2D's), else its other side internal
// and its ends closed as seen from the body's side.
inline ShapeMasks side_masks(EdgeEnds ends, bool back) {
  if (ends.neighbours() == 0) return {};
  return {static_cast<std::uint8_t>(back ? 0b01 : 0b10),
          back ? ends.closed_back : ends.closed_front};
}

// What two-sided edge fixture `fixture`'s ends meet now: at each end, the rays along the group's
// edges, chain edges and polygon edges that end at it or pass through it (points one within the
// tolerance of `polygon_internal_edges`); from each side, the first ray met turning from the edge
// toward that side bounds the free space there, and the end is closed when that space spans at
// most a half-turn (flat within `flat_outline_sine`, or reflex), a corner when less
// (`EdgeEnds::corner_cos`). Found with one broad-phase query per end (a walk of a non-static
// body's fixtures).
EdgeEnds edge_ends(const b2Fixture& fixture);

// A body with centroid `c` (the edge's frame) and the two-sided edge `v1` → `v2` with ends `ends`,
// the body on its back (`back`) or front: true when `c` lies on the body's side and beyond the
// other edge of a corner at an end (`EdgeEnds::corner_cos`): that edge faces the body there.
bool beyond_corner(const EdgeEnds& ends, const b2Vec2& v1, const b2Vec2& v2, bool back,
                   const b2Vec2& c);

}  // namespace dyop::box2d::detail
