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

// A shape in its body frame as the solver reads a polygon (`detail::collide_polygon_circle`,
// `detail::collide_polygons`), in place: what `Polygon<float>::from_validated` would hold, without
// building it: a `b2PolygonShape`'s own vertices and normals, or a `b2EdgeShape`'s ends and the
// normals of its two sides (`EdgeSides`: a segment as the solver reads one, `Segment`). One type
// for both, so that polygon pairs and edge pairs run one instantiation of the solver. `size_bound`:
// at least its longest edge (metres; `PairPose::size_bound`), so that it is measured only where the
// solver needs it.
class InPlace {
 public:
  InPlace(const b2Vec2* vertices, const b2Vec2* normals, int count, float size_bound)
      : v_(vertices), n_(normals), count_(count), size_bound_(size_bound) {}
  InPlace(const b2PolygonShape& shape, float size_bound)
      : InPlace(shape.m_vertices, shape.m_normals, shape.m_count, size_bound) {}
  int count() const { return count_; }
  Vec2<float> vertex(int i) const { return {v_[i].x, v_[i].y}; }
  Vec2<float> normal(int i) const { return {n_[i].x, n_[i].y}; }
  int next(int i) const { return i + 1 < count_ ? i + 1 : 0; }
  // The longest edge, measured in the body frame on each call.
  float size() const {
    return dyop::detail::validated_size<float>(
        count_, [&](int i) { return vertex(i); }, [&](int i) { return normal(i); });
  }
  float size_bound() const { return size_bound_; }
  // Box2D's vertices are CCW, and an edge's sides run from its first end: the caller's order is
  // the solver's.
  static int input_vertex(int i) { return i; }
  static int input_edge(int i) { return i; }

 private:
  const b2Vec2* v_;
  const b2Vec2* n_;
  int count_;
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
    return rotated(InPlace::vertex(i), xf_.q.c, xf_.q.s) + Vec2<float>(xf_.p.x, xf_.p.y);
  }
  Vec2<float> normal(int i) const { return rotated(InPlace::normal(i), xf_.q.c, xf_.q.s); }

 private:
  const b2Transform& xf_;
};

// A `b2EdgeShape` as the solver reads a segment (`Segment`): its ends `m_vertex1`, `m_vertex2`,
// the normal of its front (Box2D's edge normal: to the right of the first end → the second,
// normalised by the reciprocal of the length, as Box2D does) and of its back.
struct EdgeSides {
  b2Vec2 vertices[2];
  b2Vec2 normals[2];

  explicit EdgeSides(const b2EdgeShape& edge) : vertices{edge.m_vertex1, edge.m_vertex2} {
    b2Vec2 along = edge.m_vertex2 - edge.m_vertex1;
    along.Normalize();
    normals[0] = {along.y, -along.x};
    normals[1] = -normals[0];
  }
  // The segment read in place (`size_bound`: as `InPlace`'s). Reads this object: keep it alive.
  InPlace in_place(float size_bound) const { return InPlace(vertices, normals, 2, size_bound); }
};

}  // namespace dyop::box2d::detail
