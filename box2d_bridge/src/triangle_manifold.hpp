#pragma once
// Internal: a library method's manifold for two Box2D triangles, in Box2D's manifold contract.

#include <box2d/b2_collision.h>
#include <box2d/b2_polygon_shape.h>

#include "dyop/method.hpp"

namespace dyop::box2d::detail {

// Fills `out` with method `m`'s manifold for triangles `a` and `b` (3-vertex polygons, each in its
// own body frame) when B's body frame is `b_in_a` in A's. Returns false, leaving `out` untouched,
// when the method cannot answer (a triangle too thin for `Triangle::make`, or `Status::Invalid`).
bool triangle_manifold(Method m, const b2PolygonShape& a, const b2PolygonShape& b,
                       const b2Transform& b_in_a, LinCannyCache* cache, b2Manifold* out);

}  // namespace dyop::box2d::detail
