#pragma once
// Internal: a `b2PolygonShape` or a `b2EdgeShape` read by the exact solver in place
// (`dyop::detail::collide_polygons`, `collide_polygon_circle`), without building a `Polygon` or a
// `Segment`.

#include <box2d/b2_edge_shape.h>
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

// A `b2EdgeShape` in its body frame as the solver reads a segment (`Segment`), in place: vertex 0
// `m_vertex1`, vertex 1 `m_vertex2`, normal 0 the front as Box2D computes its edge normal
// (normalised by the reciprocal of the length), normal 1 its opposite. `size_bound` as
// `InPlace`'s.
class EdgeInPlace {
 public:
  EdgeInPlace(const b2EdgeShape& edge, float size_bound) : edge_(edge), size_bound_(size_bound) {
    b2Vec2 along = edge.m_vertex2 - edge.m_vertex1;
    length_ = along.Normalize();
    front_ = {along.y, -along.x};
  }
  static constexpr int count() { return 2; }
  Vec2<float> vertex(int i) const {
    const b2Vec2& v = i == 0 ? edge_.m_vertex1 : edge_.m_vertex2;
    return {v.x, v.y};
  }
  Vec2<float> normal(int i) const { return i == 0 ? front_ : Vec2<float>(-front_); }
  static constexpr int next(int i) { return 1 - i; }
  float size() const { return length_; }
  float size_bound() const { return size_bound_; }
  static constexpr int input_vertex(int i) { return i; }
  static constexpr int input_edge(int i) { return i; }

 private:
  const b2EdgeShape& edge_;
  float size_bound_;
  float length_;
  Vec2<float> front_;
};

}  // namespace dyop::box2d::detail
