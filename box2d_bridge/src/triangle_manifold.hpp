#pragma once
// Internal: a library method's manifold for two Box2D triangles, in Box2D's manifold contract.

#include <box2d/b2_collision.h>
#include <box2d/b2_polygon_shape.h>

#include <cstdint>

#include "dyop/method.hpp"

namespace dyop::box2d::detail {

// Fills `out` with method `m`'s manifold for triangles `ta` (A's, in A's body frame) and `tb`
// (B's, moved into A's body frame by `b_in_a`), whose polygons are `a` and `b`. `face` gets the
// face the method judged the pair on (0..2 A's edges, 3..5 B's), also when no point is kept.
// Returns false, leaving `out` untouched, when the method answers `Status::Invalid`.
bool triangle_manifold(Method m, const Triangle<float>& ta, const Triangle<float>& tb,
                       const b2PolygonShape& a, const b2PolygonShape& b,
                       const b2Transform& b_in_a, LinCannyCache* cache, b2Manifold* out,
                       std::int8_t* face);

}  // namespace dyop::box2d::detail
