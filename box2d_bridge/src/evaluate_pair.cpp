#include "evaluate_pair.hpp"

#include <algorithm>
#include <cmath>

#include "backend.hpp"
#include "stats.hpp"
#include "triangle_manifold.hpp"

namespace dyop::box2d {
namespace detail {
namespace {

using Shapes = ContactMemory::Shapes;

Vec2<float> vec(const b2Vec2& v) { return {v.x, v.y}; }

// Distance from the shape's centroid to its farthest vertex (body frame).
float bounding_radius(const b2PolygonShape& shape) {
  float sq = 0;
  for (int i = 0; i < shape.m_count; ++i) {
    sq = std::max(sq, (shape.m_vertices[i] - shape.m_centroid).LengthSquared());
  }
  return std::sqrt(sq);
}

bool valid_triangle(const b2PolygonShape& shape) {
  return Triangle<float>::make(vec(shape.m_vertices[0]), vec(shape.m_vertices[1]),
                               vec(shape.m_vertices[2]))
      .ok();
}

// What the pair is, decided once: the shapes of a fixture never change.
void look_at_shapes(const b2PolygonShape& a, const b2PolygonShape& b, ContactMemory& memory) {
  if (a.m_count != 3 || b.m_count != 3) {
    memory.shapes = Shapes::Polygons;
    return;
  }
  memory.shapes = valid_triangle(a) && valid_triangle(b) ? Shapes::Triangles
                                                         : Shapes::InvalidTriangles;
  memory.radius_a = bounding_radius(a);
  memory.radius_b = bounding_radius(b);
}

// The shape's triangle placed by the rotation (c, s) and the translation `p` (Box2D's CCW
// vertices and its own unit normals); the default is the shape's own body frame.
Triangle<float> placed(const b2PolygonShape& shape, float c = 1, float s = 0,
                       const b2Vec2& p = b2Vec2_zero) {
  const std::array<Vec2<float>, 3> v = {vec(shape.m_vertices[0]), vec(shape.m_vertices[1]),
                                        vec(shape.m_vertices[2])};
  const std::array<Vec2<float>, 3> n = {vec(shape.m_normals[0]), vec(shape.m_normals[1]),
                                        vec(shape.m_normals[2])};
  return Triangle<float>::from_validated(v, n, c, s, vec(p));
}

// Separation of the pair along face `face` (0..2: A's edge, 3..5: B's), with the other
// triangle's full support: a lower bound on the pair's distance, computed in the face's frame.
float face_separation(int face, const b2PolygonShape& a, const b2PolygonShape& b,
                      const b2Transform& b_in_a) {
  const bool on_a = face < 3;
  const b2PolygonShape& own = on_a ? a : b;
  const b2PolygonShape& other = on_a ? b : a;
  const int e = on_a ? face : face - 3;
  // The other triangle's vertices in the face's body frame.
  auto other_vertex = [&](int k) {
    return on_a ? b2Mul(b_in_a, other.m_vertices[k]) : b2MulT(b_in_a, other.m_vertices[k]);
  };
  float least = b2Dot(own.m_normals[e], other_vertex(0) - own.m_vertices[e]);
  for (int k = 1; k < 3; ++k) {
    least = std::min(least, b2Dot(own.m_normals[e], other_vertex(k) - own.m_vertices[e]));
  }
  return least;
}

// True when the bounding circles are farther apart than `far` (compared squared: no root).
bool circles_apart(const b2PolygonShape& a, const b2PolygonShape& b, const b2Transform& b_in_a,
                   const ContactMemory& memory, float far) {
  const float reach_sum = memory.radius_a + memory.radius_b + far;
  return (b2Mul(b_in_a, b.m_centroid) - a.m_centroid).LengthSquared() > reach_sum * reach_sum;
}

}  // namespace

void evaluate_pair(b2Manifold* manifold, Backend backend, const Config& config,
                   const b2PolygonShape& a, const b2Transform& xf_a, const b2PolygonShape& b,
                   const b2Transform& xf_b, ContactMemory& memory) {
  Stats& count = counters();
  if (memory.shapes == Shapes::Unchecked) look_at_shapes(a, b, memory);
  if (memory.shapes == Shapes::Polygons) {
    ++count.polygon_pairs;
    b2CollidePolygons(manifold, &a, xf_a, &b, xf_b);
    return;
  }
  ++count.triangle_pairs[static_cast<int>(backend)];

  const b2Transform b_in_a = b2MulT(xf_a, xf_b);
  const float far = reach(a.m_radius + b.m_radius);
  auto skip = [&](Skip why) {
    manifold->pointCount = 0;
    ++count.skipped[static_cast<int>(why)];
  };
  if (config.bounds_early_out && circles_apart(a, b, b_in_a, memory, far)) {
    return skip(Skip::Bounds);
  }
  const std::optional<Method> method = method_of(backend);
  if (config.warm_axis && method && memory.last_face >= 0 &&
      face_separation(memory.last_face, a, b, b_in_a) > far) {
    return skip(Skip::WarmAxis);
  }

  // Backend::Box2D has no library method: Box2D's own code is its answer, not a fallback. A
  // method that cannot answer falls back so that the world goes on, and is counted.
  bool answered = false;
  if (method && memory.shapes == Shapes::Triangles) {
    LinCannyCache cold;
    answered = triangle_manifold(*method, placed(a), placed(b, b_in_a.q.c, b_in_a.q.s, b_in_a.p),
                                 a, b, b_in_a,
                                 config.lin_canny_cache ? &memory.lin_canny : &cold, manifold,
                                 &memory.last_face);
  }
  if (!answered) {
    if (method) ++count.fallbacks;
    b2CollidePolygons(manifold, &a, xf_a, &b, xf_b);
  }
  if (manifold->pointCount > 0) ++count.manifolds;
}

}  // namespace detail

void collide_polygons(b2Manifold* manifold, Backend backend, const b2PolygonShape& shape_a,
                      const b2Transform& xf_a, const b2PolygonShape& shape_b,
                      const b2Transform& xf_b, ContactMemory* memory, const Config& config) {
  ContactMemory cold;
  detail::evaluate_pair(manifold, backend, config, shape_a, xf_a, shape_b, xf_b,
                        memory ? *memory : cold);
}

}  // namespace dyop::box2d
