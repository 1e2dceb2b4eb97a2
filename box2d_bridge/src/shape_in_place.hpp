#pragma once
// Internal: a `b2PolygonShape` read by the exact solver in place (`dyop::detail::collide_polygons`,
// `collide_polygon_circle`), without building a `Polygon`.

#include <box2d/b2_math.h>
#include <box2d/b2_polygon_shape.h>

#include "detail/validated_size.hpp"
#include "dyop/vec2.hpp"

namespace dyop::box2d::detail {

// A `b2PolygonShape` in its body frame as the solver reads a polygon
// (`detail::collide_polygon_circle`, `detail::collide_polygons`), in place: what
// `Polygon<float>::from_validated` would hold, without building it. `size_bound`: at least its
// longest edge (metres; `PairPose::size_bound`), so that it is measured only where the solver needs
// it.
class InPlace {
 public:
  InPlace(const b2PolygonShape& shape, float size_bound) : shape_(shape), size_bound_(size_bound) {}
  int count() const { return shape_.m_count; }
  Vec2<float> vertex(int i) const { return {shape_.m_vertices[i].x, shape_.m_vertices[i].y}; }
  Vec2<float> normal(int i) const { return {shape_.m_normals[i].x, shape_.m_normals[i].y}; }
  int next(int i) const { return i + 1 < shape_.m_count ? i + 1 : 0; }
  // The longest edge, measured in the body frame on each call.
  float size() const {
    return dyop::detail::validated_size<float>(
        shape_.m_count, [&](int i) { return vertex(i); }, [&](int i) { return normal(i); });
  }
  float size_bound() const { return size_bound_; }
  // Box2D's vertices are CCW: the caller's order is the solver's.
  static int input_vertex(int i) { return i; }
  static int input_edge(int i) { return i; }

 private:
  const b2PolygonShape& shape_;
  float size_bound_;
};

// A `b2PolygonShape` placed by `xf` (B's body frame in A's) as the solver reads a polygon
// (`detail::collide_polygons`): what `Polygon<float>::from_validated` with the transform would
// hold (its size measured in the body frame), each vertex and normal placed when read (the
// solver's frame reads each once).
class Placed : public InPlace {
 public:
  Placed(const b2PolygonShape& shape, const b2Transform& xf, float size_bound)
      : InPlace(shape, size_bound), xf_(xf) {}
  Vec2<float> vertex(int i) const {
    return turn(InPlace::vertex(i)) + Vec2<float>(xf_.p.x, xf_.p.y);
  }
  Vec2<float> normal(int i) const { return turn(InPlace::normal(i)); }

 private:
  Vec2<float> turn(const Vec2<float>& v) const {
    const float c = xf_.q.c;
    const float s = xf_.q.s;
    return {c * v.x() - s * v.y(), s * v.x() + c * v.y()};
  }
  const b2Transform& xf_;
};

// `P` (`InPlace` or `Placed`) holding a shape of exactly `N` vertices, known to the compiler: the
// solver's loops over vertices and axes then unroll (docs/measurements.md, "Everyday shapes").
template <class P, int N>
class Counted : public P {
 public:
  using P::P;
  static constexpr int count() { return N; }
  static constexpr int next(int i) { return i + 1 < N ? i + 1 : 0; }
};

}  // namespace dyop::box2d::detail
