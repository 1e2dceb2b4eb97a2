#pragma once
/// \file
/// Debug drawing through Box2D's `b2Draw`: the edges of a world's polygons, edges and chains as the
/// internal-edge rule sees them (`Config::internal_edges`), and the contacts' manifold points.
/// Call them after `b2World::DebugDraw`, with the same `b2Draw`, between steps:
///
///     world.DebugDraw();
///     dyop::box2d::draw_internal_edges(world, draw);
///     dyop::box2d::draw_contacts(world, draw);
///
/// Both draw whatever `b2Draw::GetFlags()` says; they only read the world.

#include <box2d/b2_draw.h>
#include <box2d/b2_world.h>

namespace dyop::box2d {

/// The colours and sizes `draw_internal_edges` and `draw_contacts` draw with.
struct DrawStyle {
  b2Color outline{0.3f, 0.9f, 0.4f};   ///< an edge the rule may push along: the level's outline
  b2Color internal{0.4f, 0.4f, 0.5f};  ///< an internal edge: no body is ever pushed along it
  b2Color closed{0.9f, 0.3f, 0.3f};    ///< a closed vertex: no body is ever pushed into it
  b2Color point{1.0f, 0.9f, 0.2f};     ///< a manifold point of a touching contact
  b2Color normal{1.0f, 0.5f, 0.1f};    ///< a touching contact's normal, from each point
  float point_size = 5;                ///< pixels, as `b2Draw::DrawPoint` takes it
  float normal_length = 0.3f;          ///< metres
};

/// Draws the edges of the world's polygon fixtures (triangles, boxes, up to 8 vertices), edge
/// fixtures and chains' segments, world frame, as the internal-edge rule sees them: a polygon's
/// internal edge in `style.internal`, every other edge (an edge's or a chain's segment is met on
/// its face) in `style.outline`, and a point at each closed vertex (an edge's end closed from
/// either side). The masks are the contacts' own: a fixture's fixed edge data
/// (`fix_internal_edges`), else found now (`polygon_internal_edges`, `edge_internal_edges`: about
/// 2 µs a fixture; fix a large level's edge data to draw it every frame). They are drawn whether or
/// not the plug-in is installed: what the rule does once it is. Circles and sensors are not drawn.
void draw_internal_edges(const b2World& world, b2Draw& draw, const DrawStyle& style = {});

/// Draws each touching contact of the world (sensors have none): its manifold points in world
/// coordinates (`b2Contact::GetWorldManifold`) and the normal from each, from fixture A to B.
/// A pair the internal-edge rule answers with no contact is not touching and is not drawn.
void draw_contacts(const b2World& world, b2Draw& draw, const DrawStyle& style = {});

}  // namespace dyop::box2d
