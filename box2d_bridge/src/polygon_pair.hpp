#pragma once
// Internal: a polygon pair as Box2D hands it to a contact.

#include <box2d/b2_math.h>
#include <box2d/b2_polygon_shape.h>

namespace dyop::box2d::detail {

// The shapes in their body frames and the bodies' transforms.
struct PolygonPair {
  const b2PolygonShape& a;
  const b2Transform& xf_a;
  const b2PolygonShape& b;
  const b2Transform& xf_b;
};

}  // namespace dyop::box2d::detail
