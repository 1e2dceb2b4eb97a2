#include "triangle_manifold.hpp"

#include "dyop/box2d.hpp"

namespace dyop::box2d::detail {
namespace {

Vec2<float> to_vec(const b2Vec2& v) { return {v.x, v.y}; }

TriangleOrError<float> triangle_of(const b2Vec2 (&v)[3]) {
  return Triangle<float>::make(to_vec(v[0]), to_vec(v[1]), to_vec(v[2]));
}

}  // namespace

bool triangle_manifold(Method m, const b2PolygonShape& a, const b2PolygonShape& b,
                       const b2Transform& b_in_a, LinCannyCache* cache, b2Manifold* out) {
  // Everything happens in A's body frame: A's vertices as stored, B's moved there. The vertices
  // are given in Box2D's order, so the features the method reports are Box2D's indices.
  const b2Vec2 va[3] = {a.m_vertices[0], a.m_vertices[1], a.m_vertices[2]};
  const b2Vec2 vb[3] = {b2Mul(b_in_a, b.m_vertices[0]), b2Mul(b_in_a, b.m_vertices[1]),
                        b2Mul(b_in_a, b.m_vertices[2])};
  const TriangleOrError<float> ta = triangle_of(va);
  const TriangleOrError<float> tb = triangle_of(vb);
  if (!ta.ok() || !tb.ok()) return false;

  Query<float> query;
  query.level = Level::Manifold;
  query.margin = a.m_radius + b.m_radius;  // the skins: contacts are speculative, as Box2D's
  query.face_hysteresis = face_hysteresis;
  const Result<float> r = penetrate(m, ta.triangle, tb.triangle, query, cache);
  if (r.status == Status::Invalid) return false;

  const Manifold<float>& mf = r.manifold;
  out->pointCount = mf.point_count;
  if (mf.point_count == 0) return true;

  // The reference face in its own body's frame, from the polygon's own data (not the method's
  // recomputed normal): the solver then sees exactly the plane Box2D would have given it.
  const b2PolygonShape& ref = mf.reference_is_a ? a : b;
  const int e1 = mf.reference_edge;
  const int e2 = e1 + 1 < ref.m_count ? e1 + 1 : 0;
  out->type = mf.reference_is_a ? b2Manifold::e_faceA : b2Manifold::e_faceB;
  out->localNormal = ref.m_normals[e1];
  out->localPoint = 0.5f * (ref.m_vertices[e1] + ref.m_vertices[e2]);
  for (int i = 0; i < mf.point_count; ++i) {
    // Points lie on the incident triangle, computed in A's frame: B's points go back to B's frame.
    const b2Vec2 p(mf.points[i].point.x(), mf.points[i].point.y());
    b2ManifoldPoint& mp = out->points[i];
    mp.localPoint = mf.reference_is_a ? b2MulT(b_in_a, p) : p;
    mp.normalImpulse = 0;
    mp.tangentImpulse = 0;
    mp.id.key = mf.points[i].key;
  }
  return true;
}

}  // namespace dyop::box2d::detail
