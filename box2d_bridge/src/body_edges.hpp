#pragma once
// Internal: which edges of a body's triangle fixtures are internal to the body (shared with
// another of its triangles), and which of their vertices are closed: no other triangle may push
// there (`Config::internal_edges`). Kept per body in a side table outside the contacts, built
// when a contact of the body first asks and rebuilt when the body's fixtures have changed.

#include <box2d/b2_body.h>
#include <box2d/b2_fixture.h>

#include <cstdint>

namespace dyop::box2d::detail {

// One triangle's masks in Box2D's vertex order (edge i from m_vertices[i] to [i + 1]).
struct TriangleEdges {
  std::uint8_t inactive_edges = 0;  // bit i: edge i shared with another triangle of the body
  std::uint8_t flat_vertices = 0;   // bit i: vertex i closed (see Query::flat_vertices)
};

// The masks of `fixture`'s triangle (zero for any other shape), from its body's index, built or
// rebuilt here when the body's fixtures are not those it was built from.
TriangleEdges triangle_edges(const b2Fixture& fixture);

// Changes whenever any body's index is built again or dropped (never 0, wrapping after 255): a
// contact whose masks were taken at another generation takes them again, so live contacts follow
// fixtures added to or destroyed on their bodies.
inline std::uint8_t index_generation_now = 1;
inline std::uint8_t index_generation() { return index_generation_now; }

// Drops `body`'s index (a contact of it was destroyed between steps: a fixture of it or the body
// itself is going, or it changed type or was disabled).
void forget_body(const b2Body& body);

// Drops every body's index (`uninstall`): bodies may be freed from then on without the plug-in.
void forget_bodies();

// Bodies indexed now (for tests and the cost figures).
int indexed_bodies();

}  // namespace dyop::box2d::detail
