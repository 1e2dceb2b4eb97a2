#include "box2d_reference/box2d_pair_set.hpp"

namespace dyop::workloads {
namespace {

void to_shape(const Triangle<float>& t, b2PolygonShape& shape, b2Transform& xf) {
  const Vec2<float> c = (t.vertex(0) + t.vertex(1) + t.vertex(2)) / 3.0f;
  shape.m_count = 3;
  shape.m_radius = 0;
  shape.m_centroid.SetZero();
  for (int i = 0; i < 3; ++i) {
    shape.m_vertices[i].Set(t.vertex(i).x() - c.x(), t.vertex(i).y() - c.y());
    shape.m_normals[i].Set(t.normal(i).x(), t.normal(i).y());
  }
  xf.Set(b2Vec2(c.x(), c.y()), 0);
}

}  // namespace

Box2DPairSet make_box2d_pair_set(const PairSet<float>& set) {
  Box2DPairSet out;
  out.shape_a.resize(set.size());
  out.shape_b.resize(set.size());
  out.xf_a.resize(set.size());
  out.xf_b.resize(set.size());
  for (std::size_t i = 0; i < set.size(); ++i) {
    to_shape(set.a[i], out.shape_a[i], out.xf_a[i]);
    to_shape(set.b[i], out.shape_b[i], out.xf_b[i]);
  }
  return out;
}

}  // namespace dyop::workloads
