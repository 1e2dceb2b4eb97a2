#pragma once
// Internal: the plug-in's evaluation of a pair beyond two triangles — two polygons, one of more
// than 3 vertices, or a polygon and a circle — for a world's contact and for `collide_polygons`
// alike. Every backend but `Box2D` answers them with the exact solver (`dyop::collide`), with the
// internal-edge rule; `Backend::Box2D` and `Config::triangles_only` with Box2D's own functions.

#include <box2d/b2_circle_shape.h>
#include <box2d/b2_collision.h>
#include <box2d/b2_polygon_shape.h>

#include "dyop/box2d.hpp"
#include "found_masks.hpp"
#include "installation.hpp"
#include "polygon_pair.hpp"
#include "recycling.hpp"

namespace dyop::box2d::detail {

class TriangleContact;

// True for a pair whose shapes were looked at and found to be beyond two triangles.
inline bool beyond_triangles(const ContactMemory& memory) {
  return memory.shapes >= ContactMemory::Shapes::Polygons;
}

// True when `Polygon<float>` accepts the shape's vertices (Box2D's hull may keep vertices that are
// collinear within rounding, or a sliver).
bool valid_polygon(const b2PolygonShape& shape);

// Distance from the shape's centroid to its farthest vertex (body frame).
float bounding_radius(const b2PolygonShape& shape);

// Two polygons, one of more than 3 vertices (`ContactMemory::Shapes::Polygons` or
// `InvalidPolygons`), under an install: keep, skip or answer, as for triangle pairs. `contact`:
// the world's contact (its masks' record in `masks`, its kept pose in `recycling`), nullptr for
// `collide_polygons` (the masks as the caller set them in `memory`; nothing kept).
void evaluate_polygons(b2Manifold* manifold, const Setting& setting, const PolygonPair& pair,
                       ContactMemory& memory, const TriangleContact* contact, FoundMasks* masks,
                       ManifoldRecycling* recycling);

// Polygon `a` (fixture A) and circle `b` (fixture B), in Box2D's registry order; uninstalled:
// Box2D's own `b2CollidePolygonAndCircle`, uncounted. The rest as above.
void evaluate_polygon_circle(b2Manifold* manifold, const Setting& setting, const b2PolygonShape& a,
                             const b2Transform& xf_a, const b2CircleShape& b,
                             const b2Transform& xf_b, ContactMemory& memory,
                             const TriangleContact* contact, FoundMasks* masks,
                             ManifoldRecycling* recycling);

}  // namespace dyop::box2d::detail
