#include "workloads/pair_sets.hpp"

#include <cmath>
#include <type_traits>

#include "workloads/stress_classes.hpp"

namespace dyop::workloads {

template <class T>
PairSet<T> make_pair_set(BenchClass c, int count, std::uint64_t seed) {
  PairSet<T> set;
  // The next frame turns B by a thousandth of a radian about its first vertex and moves it by a
  // thousandth of the pair's size: the motion of one step of a simulation.
  const double turn = 1e-3;
  for (const RawPair& p : make_bench_pairs(c, count, seed)) {
    // As T holds them (rounding through stress_classes' guard against a GCC 12 folding bug).
    const RawPair q = std::is_same_v<T, float> ? rounded_to_float(p) : p;
    const BuiltPair<T> now = build<T>(q);
    RawPair moved = q;
    const Vec2<double> pivot = q.b[0];
    const double step = 1e-3 * pair_size(q);
    for (Vec2<double>& v : moved.b) {
      const Vec2<double> d = v - pivot;
      v = pivot + Vec2<double>(std::cos(turn) * d.x() - std::sin(turn) * d.y() + step,
                               std::sin(turn) * d.x() + std::cos(turn) * d.y());
    }
    const BuiltPair<T> next = build<T>(moved);
    if (!now.a.ok() || !now.b.ok() || !next.b.ok()) continue;
    set.raw.push_back(q);
    set.a.push_back(now.a.triangle);
    set.b.push_back(now.b.triangle);
    set.b_next.push_back(next.b.triangle);
  }
  return set;
}

#ifdef DYOP_WITH_BOX2D
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
#endif

template PairSet<float> make_pair_set(BenchClass, int, std::uint64_t);
template PairSet<double> make_pair_set(BenchClass, int, std::uint64_t);

}  // namespace dyop::workloads
