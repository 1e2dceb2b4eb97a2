#pragma once
// Internal: the internal-edge masks of a world's triangle fixture (`Config::internal_edges`),
// found from the fixtures as they are now: the triangles near it that share edges with it (its
// body's, and for a static body every static body's), looked up in the world's own broad phase.
// Nothing is kept outside the contacts: no table that a deleted world could leave behind, a
// reused address could fool, or another thread could share.

#include <box2d/b2_body.h>
#include <box2d/b2_fixture.h>

#include "dyop/convex_pair.hpp"
#include "dyop/result.hpp"

namespace dyop::box2d::detail {

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

}  // namespace dyop::box2d::detail
