#pragma once
/// \file
/// The internal-edge masks the plug-in finds for one polygon or edge fixture of a world
/// (`Config::internal_edges`), as its contacts find them, and the edge data fixed in them: for
/// drawing a level's outline, checking a tile map, and tests.

#include <box2d/b2_fixture.h>
#include <box2d/b2_world.h>

#include <optional>
#include <vector>

#include "dyop/box2d.hpp"
#include "dyop/convex_pair.hpp"
#include "dyop/result.hpp"

namespace dyop::box2d {

/// The masks of `fixture`'s triangle as they are now (bits 0..2 in Box2D's vertex order: edge i
/// runs from `m_vertices[i]` to `[i + 1]`), found from its world's broad phase. Empty for any
/// other shape. What is internal:
/// - The edge group of a fixture is the triangles of its own body and, for a static body, of
///   every static body (dynamic and kinematic bodies keep their edges to themselves); sensors are
///   no part of it.
/// - An edge is internal when the union of the group's edges collinear with it and running the
///   other way covers it wholly: a neighbour's same edge, or a refined neighbour's edges meeting it
///   at T-junctions. Points of two bodies are one point within a tolerance of 16·FLT_EPSILON of
///   their coordinates' magnitude (2 µm per metre from the origin), for the rounding of placing
///   each body's frame. An edge covered only in part stays an outline edge.
/// - A vertex is closed when both of its edges are internal, or when one is (or is covered next to
///   the vertex, as where rectangles of two heights meet under a flat top) and the outline (the
///   uncovered stretches of the group's edges) is flat or reflex there; a vertex lying inside
///   another triangle's edge takes that edge as the outline through it, straight.
InternalEdges triangle_internal_edges(const b2Fixture& fixture);

/// The masks of any polygon fixture (a triangle, a `SetAsBox` box, up to 8 vertices) as they are
/// now, bits 0..count−1 in Box2D's vertex order, by the same rules: its edge group holds the
/// polygons of every vertex count of its body (and, static, of every static body). Empty for a
/// circle, an edge or a chain. For a triangle, `triangle_internal_edges`'s bits.
ShapeMasks polygon_internal_edges(const b2Fixture& fixture);

/// Fixes the edge data of every polygon fixture of `body` (triangles and polygons up to 7
/// vertices) and of every two-sided edge: its masks as `polygon_internal_edges` and
/// `edge_internal_edges` give them now, kept in the fixture (no memory beyond it; a two-sided
/// edge's in its ghost vertices, which Box2D leaves unread). Contacts then read them in O(1) and
/// never look anything up; the fixed triangles of other bodies next to `body`'s get theirs again.
/// Fixed edge data changes only through `fix_internal_edges`, `refresh_internal_edges` and
/// `add_triangles` (`dyop/box2d_mesh.hpp`): after changing a fixed ground by hand (a fixture
/// created or destroyed, a body moved, enabled, disabled or made static or not), refresh where it
/// changed. Call between steps. A disabled body's triangles get empty masks until refreshed.
void fix_internal_edges(b2Body& body);

/// `fix_internal_edges` of every body of `world`.
void fix_internal_edges(b2World& world);

/// Fixes the edge data of `fixtures` (polygon fixtures of `world`; others are passed by) and finds
/// it again for the fixed polygons next to them: for a builder that adds fixtures to a body that
/// has others (a chunk of a tile map). Call between steps.
void fix_internal_edges(b2World& world, const std::vector<b2Fixture*>& fixtures);

/// Finds again the fixed edge data of every fixed triangle whose broad-phase box overlaps `region`
/// (world frame, metres) and returns how many: the refresh after a hand change of a fixed ground.
/// For a body moved by `SetTransform`, refresh where it was and where it is; for one destroyed,
/// disabled or enabled, where it was or is. Call between steps.
int refresh_internal_edges(b2World& world, const b2AABB& region);

/// The fixed edge data of `fixture` (bits 0..2, Box2D's vertex order), or nothing: not a triangle,
/// or never fixed (its contacts then find its masks themselves, as `Config::internal_edges` says).
std::optional<InternalEdges> fixed_internal_edges(const b2Fixture& fixture);

/// The fixed edge data of polygon fixture `fixture` of any vertex count (bits 0..count−1), or
/// nothing: not a polygon, never fixed, or an 8-gon (no slot of its shape is free to hold it: its
/// contacts find its masks, as for a fixture never fixed).
std::optional<ShapeMasks> fixed_polygon_edges(const b2Fixture& fixture);

/// The masks the rule gives the pairs of edge fixture `fixture` (a `b2EdgeShape`, or child `child`
/// of a `b2ChainShape`) with a body on its front (`back` false; the front is to the right of
/// `m_vertex1` → `m_vertex2`) or on its back, in `Segment`'s bits (edge 0 the front, 1 the back,
/// vertices 0 and 1 `m_vertex1` and `m_vertex2`):
/// - one-sided (a chain's edge, `SetOneSided`): from its ghost vertices: its back internal, an end
///   closed where the outline through it is flat (within 1e-3 rad) or concave seen from the front;
///   `back` is ignored;
/// - two-sided: from what its ends meet (its fixed edge data, else found now): the other edges,
///   chains and polygons of its group (its body's, and for a static body every static body's)
///   ending at or passing through each end; nothing when they meet nothing (both sides, as
///   Box2D's), else its other side internal and each end closed where the free space on the
///   body's side spans at most a half-turn (flat or reflex).
/// Empty for any other shape.
ShapeMasks edge_internal_edges(const b2Fixture& fixture, int child = 0, bool back = false);

/// What two-sided edge fixture `fixture`'s ends meet (its fixed edge data, else found now as
/// `edge_internal_edges` finds them): for `ContactMemory::edge_ends`. Empty for any other shape.
EdgeEnds edge_ends(const b2Fixture& fixture);

/// `edge_internal_edges` of two-sided edge fixture `fixture` from its fixed edge data, or nothing:
/// not a two-sided edge, or never fixed.
std::optional<ShapeMasks> fixed_edge_internal_edges(const b2Fixture& fixture, bool back = false);

/// Makes every contact of `world` find its masks again when next needed: O(contacts), for a
/// program that moved static bodies (`SetTransform`) and wants bodies that were farther than the
/// broad phase's margin (0.1 m) from them to see it at once. The plug-in sees every other change
/// itself: fixtures created, destroyed, enabled or disabled anywhere in the world (near a pair at
/// once, through the contacts made or ended with its bodies; farther away once the pair has moved
/// 0.05 m since, before it could reach them), a static
/// body moved or made static or not near a body (through that body's contact with it), and
/// contacts made or ended between steps (see `Config::internal_edges`). Call between steps.
void forget_internal_edges(b2World& world);

/// The masks the rule applies to `contact`'s pair (`Query::internal_edges`: A's bits, then B's),
/// for tests and drawing: the two fixtures' fixed edge data when both have it; else the masks the
/// contact found, or was lent by another contact, under the world as it is now (the same install,
/// fixtures and static frames), which equal `InternalEdges::pair` of the two fixtures'
/// `triangle_internal_edges`. Nothing when it holds none (a contact finds them once its pair first
/// comes within the skins) and for a contact the plug-in did not make.
std::optional<InternalEdges> contact_internal_edges(const b2Contact& contact);

}  // namespace dyop::box2d
