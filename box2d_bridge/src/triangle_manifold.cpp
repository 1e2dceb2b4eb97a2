#include "triangle_manifold.hpp"

#include "dyop/box2d.hpp"

namespace dyop::box2d::detail {

bool triangle_manifold(Method m, const Triangle<float>& ta, const Triangle<float>& tb,
                       const b2PolygonShape& a, const b2PolygonShape& b,
                       const b2Transform& b_in_a, LinCannyCache* cache, b2Manifold* out,
                       std::int8_t* face) {
  // Everything happens in A's body frame. The triangles were made from Box2D's vertices in
  // Box2D's order, so the features the method reports are Box2D's indices.
  Query<float> query;
  query.level = Level::Manifold;
  query.margin = a.m_radius + b.m_radius;  // the skins: contacts are speculative, as Box2D's
  query.face_hysteresis = face_hysteresis;
  query.apart = Apart::Gap;  // beyond the skins a manifold is empty: no distance is needed
  const Result<float> r = penetrate(m, ta, tb, query, cache);
  if (r.status == Status::Invalid) return false;

  const Manifold<float>& mf = r.manifold;
  *face = static_cast<std::int8_t>(mf.reference_edge + (mf.reference_is_a ? 0 : 3));
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
