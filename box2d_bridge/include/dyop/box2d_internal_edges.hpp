#pragma once
/// \file
/// The internal-edge masks the plug-in finds for one triangle fixture of a world
/// (`Config::internal_edges`), as its contacts find them: for drawing a level's outline, checking a
/// tile map, and tests.

#include <box2d/b2_fixture.h>
#include <box2d/b2_world.h>

#include <optional>

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
/// - A vertex is closed when both of its edges are internal, or when one is and the outline (the
///   uncovered stretches of the group's edges) is flat or reflex there; a vertex lying inside
///   another triangle's edge takes that edge as the outline through it, straight.
InternalEdges triangle_internal_edges(const b2Fixture& fixture);

/// Makes every contact of `world` find its masks again when next needed: O(contacts), for a
/// program that moved static bodies (`SetTransform`) and wants bodies that were farther than the
/// broad phase's margin (0.1 m) from them to see it at once. The plug-in sees every other change
/// itself: fixtures created, destroyed, enabled or disabled anywhere in the world (near a pair at
/// once, through the contacts made or ended with its bodies; farther away once the pair has moved
/// 0.05 m since, before it could reach them: see `ContactMemory::internal_edges_motion`), a static
/// body moved or made static or not near a body (through that body's contact with it), and
/// contacts made or ended between steps (see `Config::internal_edges`). Call between steps.
void forget_internal_edges(b2World& world);

/// The masks `contact` holds for its pair (`Query::internal_edges`: A's bits, then B's), when it
/// found them, or was lent them by another contact, under the world as it is now (the same
/// install, fixtures and static frames); nothing otherwise (a contact finds them once its pair
/// first comes within the skins), and for a contact the plug-in did not make. What the masks the rule applies are, for tests and for drawing: they equal
/// `InternalEdges::pair` of the two fixtures' `triangle_internal_edges`.
std::optional<InternalEdges> contact_internal_edges(const b2Contact& contact);

}  // namespace dyop::box2d
