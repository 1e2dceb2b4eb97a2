#include <cmath>

#include "dyop/box2d.hpp"

namespace dyop::box2d {
namespace {

// b2PolygonShape::Set welds a vertex to an earlier one closer than 0.5·b2_linearSlop; the same
// float expression here, so that the verdict is Box2D's own.
bool welded(const b2Vec2& p, const b2Vec2& q) {
  constexpr float weld = 0.5f * b2_linearSlop;
  return b2DistanceSquared(p, q) < weld * weld;
}

TriangleShape failure(ShapeError e, TriangleError t = TriangleError::None) {
  TriangleShape out;
  out.error = e;
  out.triangle_error = t;
  out.message = e == ShapeError::Triangle ? describe(t) : describe(e);
  return out;
}

}  // namespace

const char* describe(ShapeError e) {
  switch (e) {
    case ShapeError::None:
      return "valid triangle";
    case ShapeError::Triangle:
      return "not a valid triangle (see triangle_error)";
    case ShapeError::VerticesTooClose:
      return "two vertices closer than 0.5 * b2_linearSlop (Box2D would weld them and assert)";
    case ShapeError::AreaTooSmall:
      return "area below dyop::box2d::min_triangle_area (Box2D's centroid would assert)";
    case ShapeError::TooLarge:
      return "a coordinate beyond dyop::box2d::max_triangle_coordinate (Box2D's inertia would "
             "overflow float)";
  }
  return "unknown shape error";
}

TriangleShape make_triangle(const b2Vec2& p0, const b2Vec2& p1, const b2Vec2& p2) {
  const TriangleOrError<float> t = Triangle<float>::make(
      Vec2<float>(p0.x, p0.y), Vec2<float>(p1.x, p1.y), Vec2<float>(p2.x, p2.y));
  if (!t.ok()) return failure(ShapeError::Triangle, t.error);
  for (const b2Vec2& p : {p0, p1, p2}) {
    if (!(std::abs(p.x) <= max_triangle_coordinate && std::abs(p.y) <= max_triangle_coordinate)) {
      return failure(ShapeError::TooLarge);
    }
  }
  if (welded(p0, p1) || welded(p1, p2) || welded(p2, p0)) {
    return failure(ShapeError::VerticesTooClose);
  }
  // In double from the float inputs: the area itself, not another rounding of it.
  const double twice_area =
      (double(p1.x) - p0.x) * (double(p2.y) - p0.y) - (double(p1.y) - p0.y) * (double(p2.x) - p0.x);
  if (!(0.5 * std::abs(twice_area) > min_triangle_area)) return failure(ShapeError::AreaTooSmall);

  TriangleShape out;
  const b2Vec2 points[3] = {p0, p1, p2};
  out.shape.Set(points, 3);
  out.message = describe(ShapeError::None);
  return out;
}

}  // namespace dyop::box2d
