#pragma once
// Internal: a library method's manifold for two Box2D triangles, in Box2D's manifold contract.

#include <box2d/b2_collision.h>
#include <box2d/b2_polygon_shape.h>

#include <cstdint>

#include "dyop/box2d.hpp"
#include "dyop/method.hpp"

namespace dyop::box2d::detail {

// Two triangle shapes of a contact, everything in A's body frame: `ta` is A's triangle, `tb` B's
// moved by `b_in_a` (B's body frame given in A's); `a` and `b` are the shapes they were made from,
// in Box2D's vertex order, so a method's features are Box2D's indices.
struct PlacedPair {
  const Triangle<float>& ta;
  const Triangle<float>& tb;
  const b2PolygonShape& a;
  const b2PolygonShape& b;
  const b2Transform& b_in_a;
};

// What a method made of the pair.
struct TriangleManifold {
  // False when the method answered `Status::Invalid`: nothing else is set, and the caller falls
  // back to Box2D's own answer.
  bool answered = false;
  // The face the method judged the pair on (0..2 A's edges, 3..5 B's), also when the manifold
  // has no point: the warm-started face of the next evaluation.
  std::int8_t face = -1;
  // Box2D's manifold: `pointCount` always; the rest only when it has points.
  b2Manifold manifold;
};

// Method `m`'s manifold for `pair`, with the skins as margin and Box2D's face hysteresis;
// `cache` is the warm-start state of methods that keep one (nullptr: cold); `inactive_edges` and
// `flat_vertices` as in `Query` (Box2D's vertex order, A's bits then B's). Inline, with the
// contact's evaluation: the result is then built where it is used (callgrind, 150 steps, Collide:
// pyramid 76.7 M -> 75.7 M instructions, rain 165.5 M -> 164.3 M, against an out-of-line function
// writing through output pointers).
inline TriangleManifold triangle_manifold(Method m, const PlacedPair& pair, LinCannyCache* cache,
                                          std::uint8_t inactive_edges = 0,
                                          std::uint8_t flat_vertices = 0) {
  Query<float> query;
  query.inactive_edges = inactive_edges;
  query.flat_vertices = flat_vertices;
  query.level = Level::Manifold;
  query.margin = pair.a.m_radius + pair.b.m_radius;  // the skins: speculative, as Box2D's
  query.face_hysteresis = face_hysteresis;
  query.apart = Apart::Gap;  // beyond the skins a manifold is empty: no distance is needed
  const Result<float> r = penetrate(m, pair.ta, pair.tb, query, cache);
  TriangleManifold out;
  if (r.status == Status::Invalid) return out;

  const Manifold<float>& mf = r.manifold;
  out.answered = true;
  out.face = static_cast<std::int8_t>(mf.reference_edge + (mf.reference_is_a ? 0 : 3));
  b2Manifold& bm = out.manifold;
  bm.pointCount = mf.point_count;
  if (mf.point_count == 0) return out;

  // The reference face in its own body's frame, from the polygon's own data (not the method's
  // recomputed normal): the solver then sees exactly the plane Box2D would have given it.
  const b2PolygonShape& ref = mf.reference_is_a ? pair.a : pair.b;
  const int e1 = mf.reference_edge;
  const int e2 = e1 + 1 < ref.m_count ? e1 + 1 : 0;
  bm.type = mf.reference_is_a ? b2Manifold::e_faceA : b2Manifold::e_faceB;
  bm.localNormal = ref.m_normals[e1];
  bm.localPoint = 0.5f * (ref.m_vertices[e1] + ref.m_vertices[e2]);
  for (int i = 0; i < mf.point_count; ++i) {
    // Points lie on the incident triangle, computed in A's frame: B's points go back to B's frame.
    const b2Vec2 p(mf.points[i].point.x(), mf.points[i].point.y());
    b2ManifoldPoint& mp = bm.points[i];
    mp.localPoint = mf.reference_is_a ? b2MulT(pair.b_in_a, p) : p;
    mp.normalImpulse = 0;
    mp.tangentImpulse = 0;
    mp.id.key = mf.points[i].key;
  }
  return out;
}


}  // namespace dyop::box2d::detail
