#include "box2d_reference/collide_triangles.hpp"

#include <box2d/b2_collision.h>
#include <box2d/b2_distance.h>
#include <box2d/b2_polygon_shape.h>

#include <algorithm>
#include <cmath>

namespace dyop::box2d {
namespace {

Vec2<float> to_vec(const b2Vec2& v) { return {v.x, v.y}; }

// A triangle as a Box2D body holds it: vertices about the centroid (the body's centre of mass),
// placed by a translation, so that Box2D's world-frame arithmetic meets the same rounding as in a
// simulation. The shape's data is set directly, CCW as Box2D requires: b2PolygonShape::Set would
// weld the vertices of triangles smaller than 2.5 mm, which the library accepts.
struct Body {
  b2PolygonShape shape;
  b2Transform xf;
};

Body as_body(const Triangle<float>& t) {
  const Vec2<float> c = (t.vertex(0) + t.vertex(1) + t.vertex(2)) / 3.0f;
  Body body;
  body.shape.m_radius = 0;  // pure geometry: no skin, no speculative points
  body.shape.m_count = 3;
  for (int i = 0; i < 3; ++i) {
    const Vec2<float> v = t.vertex(i) - c;
    body.shape.m_vertices[i].Set(v.x(), v.y());
    body.shape.m_normals[i].Set(t.normal(i).x(), t.normal(i).y());
  }
  body.xf.Set(b2Vec2(c.x(), c.y()), 0.0f);
  return body;
}

// Box2D's float arithmetic has no guard against overflow or 0/0 (b2Distance squares lengths and
// divides by simplex areas): a non-finite answer is reported as no answer (a default `Result`:
// Invalid, no reason of the library's), never passed on as a status (a NaN distance compares
// false and would read as Touching). None seen on valid input:
// 1.4 million random valid pairs, sizes 1e-12..1e18, offsets up to max_coordinate.
Result<float> checked(Result<float> r) {
  const bool finite = std::isfinite(r.separation) && std::isfinite(r.depth) &&
                      r.normal.allFinite() && r.witness_a.allFinite() && r.witness_b.allFinite();
  if (finite) return r;
  return Result<float>{};
}

}  // namespace

Result<float> collide_triangles(const Triangle<float>& a, const Triangle<float>& b) {
  const Body body_a = as_body(a);
  const Body body_b = as_body(b);
  const float band = touching_tolerance<float>() * std::max(a.size(), b.size());
  Result<float> r;

  b2Manifold manifold;
  b2CollidePolygons(&manifold, &body_a.shape, body_a.xf, &body_b.shape, body_b.xf);
  if (manifold.pointCount == 0) {
    b2DistanceInput input;
    input.proxyA.Set(&body_a.shape, 0);
    input.proxyB.Set(&body_b.shape, 0);
    input.transformA = body_a.xf;
    input.transformB = body_b.xf;
    input.useRadii = false;
    b2SimplexCache cache;
    cache.count = 0;
    b2DistanceOutput output;
    b2Distance(&output, &cache, &input);
    r.status = output.distance > band ? Status::Separated : Status::Touching;
    r.separation = output.distance;
    r.witness_a = to_vec(output.pointA);
    r.witness_b = to_vec(output.pointB);
    const Vec2<float> gap = r.witness_b - r.witness_a;
    if (gap.squaredNorm() > 0) r.normal = gap.normalized();
    r.iterations = output.iterations;
    return checked(r);
  }

  // The deepest point; with no skins its world point is halfway between the clipped point and
  // its projection on the reference face, `separation` apart along the normal.
  b2WorldManifold world;
  world.Initialize(&manifold, body_a.xf, 0.0f, body_b.xf, 0.0f);
  const int deep = manifold.pointCount == 2 && world.separations[1] < world.separations[0] ? 1 : 0;
  const float s = world.separations[deep];
  r.status = s < -band ? Status::Penetrating : Status::Touching;
  r.separation = s;
  r.depth = std::max(0.0f, -s);
  r.normal = to_vec(world.normal);
  const Vec2<float> half = 0.5f * s * r.normal;
  r.witness_a = to_vec(world.points[deep]) - half;
  r.witness_b = to_vec(world.points[deep]) + half;
  return checked(r);
}

}  // namespace dyop::box2d
