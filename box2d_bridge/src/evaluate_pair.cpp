#include "evaluate_pair.hpp"

#include <algorithm>
#include <cmath>

#include "triangle_manifold.hpp"

namespace dyop::box2d {
namespace detail {
namespace {

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

// The shape's triangle (Box2D's CCW vertices and its own unit normals) in its body frame, or
// placed by `xf`.
std::array<Vec2<float>, 3> vertices(const b2PolygonShape& shape) {
  return {vec(shape.m_vertices[0]), vec(shape.m_vertices[1]), vec(shape.m_vertices[2])};
}
std::array<Vec2<float>, 3> normals(const b2PolygonShape& shape) {
  return {vec(shape.m_normals[0]), vec(shape.m_normals[1]), vec(shape.m_normals[2])};
}
Triangle<float> placed(const b2PolygonShape& shape) {
  return Triangle<float>::from_validated(vertices(shape), normals(shape));
}
Triangle<float> placed(const b2PolygonShape& shape, const b2Transform& xf) {
  return Triangle<float>::from_validated(vertices(shape), normals(shape), xf.q.c, xf.q.s,
                                         vec(xf.p));
}

}  // namespace

void look_at_shapes(const b2PolygonShape& a, const b2PolygonShape& b, ContactMemory& memory) {
  if (a.m_count != 3 || b.m_count != 3) {
    memory.shapes = ContactMemory::Shapes::Polygons;
    return;
  }
  memory.shapes = valid_triangle(a) && valid_triangle(b)
                      ? ContactMemory::Shapes::Triangles
                      : ContactMemory::Shapes::InvalidTriangles;
  memory.radius_sum = bounding_radius(a) + bounding_radius(b);
}

void full_evaluation(b2Manifold* manifold, std::optional<Method> method, const Config& config,
                     const b2PolygonShape& a, const b2Transform& xf_a, const b2PolygonShape& b,
                     const b2Transform& xf_b, const b2Transform& b_in_a, ContactMemory& memory) {
  // Backend::Box2D has no library method: Box2D's own code is its answer, not a fallback. A
  // method that cannot answer falls back so that the world goes on, and is counted.
  bool answered = false;
  if (method && memory.shapes == ContactMemory::Shapes::Triangles) {
    LinCannyCache cold;
    const Triangle<float> ta = placed(a);
    const Triangle<float> tb = placed(b, b_in_a);
    // The internal-edge rule only where it applies: with no mask the query is the plain one.
    const bool rule = config.internal_edges && info(*method).allowed_directions &&
                      (memory.inactive_edges | memory.flat_vertices) != 0;
    if (rule) ++counters().internal_edge_pairs;
    const TriangleManifold r = triangle_manifold(
        *method, {ta, tb, a, b, b_in_a}, config.lin_canny_cache ? &memory.lin_canny : &cold,
        rule ? memory.inactive_edges : 0, rule ? memory.flat_vertices : 0);
    answered = r.answered;
    if (answered) {
      memory.last_face = r.face;
      *manifold = r.manifold;
    }
  }
  if (!answered) {
    if (method) ++counters().fallbacks;
    b2CollidePolygons(manifold, &a, xf_a, &b, xf_b);
  }
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
