#include <array>
#include <cfloat>
#include <cmath>

#include "dyop/box2d.hpp"
#include "dyop/box2d_release.hpp"

// Box2D 2.4.2 declares this struct (b2_collision.h) and takes it in `b2PolygonShape::Set`; under
// 2.4.1 the declaration names a type that is never defined nor used.
struct b2Hull;

namespace dyop::box2d {
namespace {

// b2PolygonShape::Set welds a vertex to an earlier one closer than 0.5·b2_linearSlop; the same
// float expression here, so that the verdict is Box2D's own.
bool welded(const b2Vec2& p, const b2Vec2& q) {
  constexpr float weld = 0.5f * b2_linearSlop;
  return b2DistanceSquared(p, q) < weld * weld;
}

// Box2D 2.4.1's Set wraps the hull of the points as a gift in float: from the point of greatest
// x (of those, the lowest y) it walks to the point that leaves the others on its left, until it is
// back. On three points that Triangle<float>::make accepts this always closes after three, counter-
// clockwise: the float cross products it decides with err by a few FLT_EPSILON times the product
// of the edges, and the triangle's twice area exceeds degenerate_tolerance<float>()
// (64·FLT_EPSILON) times its longest edge squared, so they cannot take the wrong sign (a search
// over a million random triangles just above the tolerance found Box2D's order equal to this rule
// every time).
static_assert(degenerate_tolerance<float>() >= 16 * FLT_EPSILON,
              "the rule below needs Triangle<float>::make's flatness margin over float rounding");

// The three points in Box2D 2.4.1's order: the rightmost first (of two, the lower), then
// counter-clockwise, as `twice_area` (the orientation of p0, p1, p2 in double) tells.
std::array<b2Vec2, 3> box2d_241_order(const b2Vec2& p0, const b2Vec2& p1, const b2Vec2& p2,
                                      double twice_area) {
  const std::array<b2Vec2, 3> ccw =
      twice_area > 0 ? std::array<b2Vec2, 3>{p0, p1, p2} : std::array<b2Vec2, 3>{p0, p2, p1};
  int first = 0;
  for (int i = 1; i < 3; ++i) {
    const b2Vec2& p = ccw[i];
    if (p.x > ccw[first].x || (p.x == ccw[first].x && p.y < ccw[first].y)) first = i;
  }
  return {ccw[first], ccw[(first + 1) % 3], ccw[(first + 2) % 3]};
}

// 2.4.1: Box2D's own Set (of the points in that order, which it keeps). 2.4.2: Set(const
// b2Hull&) of the points in that order: it copies them and computes the normals and the centroid
// with 2.4.1's code, without its quickhull's welding within 4·b2_linearSlop and refusal of points
// within 2·b2_linearSlop of their neighbours' line. Both give the same bits.
template <class Hull = b2Hull>
void set_triangle(b2PolygonShape& shape, const std::array<b2Vec2, 3>& order) {
  if constexpr (box2d_release == Box2DRelease::V2_4_2) {
    Hull hull;
    for (int i = 0; i < 3; ++i) hull.points[i] = order[i];
    hull.count = 3;
    shape.Set(hull);
  } else {
    shape.Set(order.data(), 3);
  }
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
  set_triangle(out.shape, box2d_241_order(p0, p1, p2, twice_area));
  out.message = describe(ShapeError::None);
  return out;
}

}  // namespace dyop::box2d
