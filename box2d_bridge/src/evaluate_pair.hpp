#pragma once
// Internal: one evaluation of a polygon pair by the plug-in, with the pair's memory of its last
// evaluation and the skips it allows.
//
// Inline, with the contact's `Evaluate`: most evaluations in a world end in a skip that costs a
// few dozen instructions, and Box2D's own contact answers a pair apart after one face test, so
// every call and every transformed vertex counts. The skip tests rotate one normal into the other
// body's frame instead of moving three vertices.

#include <box2d/b2_collision.h>
#include <box2d/b2_polygon_shape.h>

#include <algorithm>

#include "backend.hpp"
#include "dyop/box2d.hpp"
#include "stats.hpp"

namespace dyop::box2d::detail {

// The first evaluation: what the two shapes are (valid triangles, invalid ones, larger polygons)
// and their bounding radii, kept in `memory` (the shapes of a fixture never change).
void look_at_shapes(const b2PolygonShape& a, const b2PolygonShape& b, ContactMemory& memory);

// The backend's manifold for two valid triangles (`method`), or Box2D's when the method cannot
// answer (counted as a fallback); also Box2D's own code for `Backend::Box2D` (no method).
void full_evaluation(b2Manifold* manifold, std::optional<Method> method, const Config& config,
                     const b2PolygonShape& a, const b2Transform& xf_a, const b2PolygonShape& b,
                     const b2Transform& xf_b, const b2Transform& b_in_a, ContactMemory& memory);

// Separation of the pair along face `face` (0..2: A's edge, 3..5: B's; frames as in
// `b_in_a`, B's body frame given in A's), with the other triangle's whole support: a lower bound
// on the pair's distance. The face's normal is rotated into the other body's frame, so the other
// triangle's vertices are used as the shape holds them.
inline float face_separation(int face, const b2PolygonShape& a, const b2PolygonShape& b,
                             const b2Transform& b_in_a) {
  if (face < 3) {
    const b2Vec2& n = a.m_normals[face];
    const b2Vec2 m = b2MulT(b_in_a.q, n);  // A's normal in B's frame
    const float least = std::min(std::min(b2Dot(m, b.m_vertices[0]), b2Dot(m, b.m_vertices[1])),
                                 b2Dot(m, b.m_vertices[2]));
    return least + b2Dot(n, b_in_a.p - a.m_vertices[face]);
  }
  const int e = face - 3;
  const b2Vec2& n = b.m_normals[e];
  const b2Vec2 m = b2Mul(b_in_a.q, n);  // B's normal in A's frame
  const float least = std::min(std::min(b2Dot(m, a.m_vertices[0]), b2Dot(m, a.m_vertices[1])),
                               b2Dot(m, a.m_vertices[2]));
  return least - b2Dot(m, b_in_a.p) - b2Dot(n, b.m_vertices[e]);
}

// Beyond this separation along any one face normal (metres), for skins summing to `margin`, a
// manifold has no point: the reference face the full evaluation picks separates the pair by at
// least that face's separation minus `face_hysteresis` (it is the best face of A or B, B's only
// when it beats A's by the hysteresis), and every clipped point lies on the incident edge, at
// least as far from the reference line as the nearer of its ends. So a face whose separation
// exceeds margin + face_hysteresis proves the manifold empty, exactly.
inline float face_reach(float margin) { return margin + face_hysteresis; }

// True when the bounding circles are farther apart than `far` (compared squared: no root).
inline bool circles_apart(const b2PolygonShape& a, const b2PolygonShape& b,
                          const b2Transform& b_in_a, const ContactMemory& memory, float far) {
  const float reach_sum = memory.radius_sum + far;
  return (b2Mul(b_in_a, b.m_centroid) - a.m_centroid).LengthSquared() > reach_sum * reach_sum;
}

// The plug-in's answer for one polygon pair with `config`'s skips, counted in `stats`.
inline void evaluate_pair(b2Manifold* manifold, Backend backend, const Config& config,
                          const b2PolygonShape& a, const b2Transform& xf_a,
                          const b2PolygonShape& b, const b2Transform& xf_b,
                          ContactMemory& memory) {
  using Shapes = ContactMemory::Shapes;
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
  const std::optional<Method> method = method_of(backend);
  const bool skip_bounds = config.bounds_early_out && circles_apart(a, b, b_in_a, memory, far);
  if (skip_bounds || (config.warm_axis && method && memory.last_face >= 0 &&
                      face_separation(memory.last_face, a, b, b_in_a) >
                          face_reach(a.m_radius + b.m_radius))) {
    manifold->pointCount = 0;
    ++count.skipped[static_cast<int>(skip_bounds ? Skip::Bounds : Skip::WarmAxis)];
    return;
  }
  full_evaluation(manifold, method, config, a, xf_a, b, xf_b, b_in_a, memory);
  if (manifold->pointCount > 0) ++count.manifolds;
}

}  // namespace dyop::box2d::detail
