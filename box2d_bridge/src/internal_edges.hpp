#pragma once
// Internal: the internal-edge masks of a world's triangle fixture (`Config::internal_edges`),
// found from the fixtures as they are now: the fixture's body's other triangles near it, looked
// up in the world's own broad phase. Nothing is kept outside the contacts: no table that a
// deleted world could leave behind, a reused address could fool, or another thread could share.

#include <box2d/b2_fixture.h>

#include "dyop/result.hpp"

namespace dyop::box2d::detail {

// The masks of `fixture`'s triangle in Box2D's vertex order, bits 0..2 (edge i from
// m_vertices[i] to [i + 1]); empty for any other shape and for a fixture alone on its body.
// An edge is internal when another triangle fixture of the same body has the same two vertices
// (body frame, bit for bit, either order). A vertex is closed when both of its edges are
// internal, or when one is and the body's outline (the edges of one triangle only) is flat or
// reflex there. Every triangle sharing one of its vertices overlaps its broad-phase box, so the
// world's broad phase finds them all; cost: one query of that box.
InternalEdges triangle_internal_edges(const b2Fixture& fixture);

}  // namespace dyop::box2d::detail
