#pragma once
// Internal: the plug-in's one evaluation of a polygon pair, for a world's contact and for
// `collide_polygons` alike. What answers (the backend's method, or Box2D's `b2CollidePolygons`,
// called in one place), which skips apply, where the internal-edge masks come from and what is
// counted are decided here and nowhere else.
//
// Inline, with the contact's `Evaluate`: most evaluations in a world end in a skip that costs a
// few dozen instructions, and Box2D's own contact answers a pair apart after one face test, so
// every call and every transformed vertex counts. The skip tests rotate one normal into the other
// body's frame instead of moving three vertices. The method's run is out of line (evaluation.cpp).

#include <box2d/b2_collision.h>
#include <box2d/b2_polygon_shape.h>

#include <algorithm>

#include "dyop/box2d.hpp"
#include "installation.hpp"
#include "recycling.hpp"
#include "stats.hpp"
#include "triangle_contact.hpp"

namespace dyop::box2d::detail {

// A polygon pair as Box2D hands it over: the shapes in their body frames and the bodies'
// transforms.
struct PolygonPair {
  const b2PolygonShape& a;
  const b2Transform& xf_a;
  const b2PolygonShape& b;
  const b2Transform& xf_b;
};

// The first evaluation: what the two shapes are (valid triangles, invalid ones, larger polygons)
// and their bounding radii, kept in `memory` (the shapes of a fixture never change).
void look_at_shapes(const b2PolygonShape& a, const b2PolygonShape& b, ContactMemory& memory);

// The setting's method on two valid triangles (`b_in_a`: B's body frame given in A's), with the
// pair's internal-edge masks when the rule is on: `contact` (a world's contact, whose memory is
// `memory`) finds them when its memory's are not current; nullptr (`collide_polygons`): the
// caller set them in `memory`. True when it answered and `manifold` holds its answer; false when the
// method could not answer (`Status::Invalid`) and Box2D's code must.
bool run_method(b2Manifold* manifold, const Setting& setting, const PolygonPair& pair,
                const b2Transform& b_in_a, ContactMemory& memory, const TriangleContact* contact);

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

// Who answered a pair.
enum class Answer : std::uint8_t {
  Plugin,        // the backend's method, a skip or a kept manifold: `manifold` is written
  Box2DBackend,  // a triangle pair for `Backend::Box2D`: Box2D's code is the backend's answer
  Box2DFallback, // a triangle pair the method could not answer: Box2D's code, counted
  Box2DOther,    // uninstalled, or a larger polygon: Box2D's code, as its own contact
};

// The manifold in `manifold` may stay (`Config::recycle_distance`, or the measurement floor's
// `Setting::never_recompute`): see recycling.hpp. A change of the pair's internal-edge masks
// (their stamp moved, or they were forgotten) recomputes.
inline bool keeps_manifold(const Setting& setting, const PolygonPair& p, const b2Transform& b_in_a,
                           const ContactMemory& memory, const ManifoldRecycling& recycling,
                           const TriangleContact* contact, float margin) {
  if (setting.never_recompute) return recycling.slack > 0 && recycling.epoch == setting.epoch;
  if (!recycling.keeps(b_in_a, p.b.m_centroid, recycle_lever(memory.radius_sum, margin),
                       setting.epoch)) {
    return false;
  }
  return !setting.internal_edges || !contact ||
         memory.internal_edges_stamp == contact->internal_edges_stamp(setting.epoch);
}

// How far a manifold the method just computed may move before a recompute: the setting's
// distance for one with points; for an empty one, also no farther than its judged face's
// separation beyond what a manifold reaches, so that no new contact is missed (see
// `face_reach`).
inline float recycle_slack(const Setting& setting, const b2Manifold& manifold, const PolygonPair& p,
                           const b2Transform& b_in_a, const ContactMemory& memory, float margin) {
  const float distance = setting.config.recycle_distance;
  if (manifold.pointCount > 0) return distance;
  if (memory.last_face < 0) return 0;
  return std::min(distance, face_separation(memory.last_face, p.a, p.b, b_in_a) -
                                face_reach(margin));
}

// The installed backend's part of an evaluation (counted): a kept manifold, a skip, the method's
// answer, or who Box2D's code answers for. `recycling`: the world's contact's (nullptr:
// `collide_polygons`, which never keeps a manifold). Always inlined into the contact's
// `Evaluate`: GCC 12 left it out of line, and the call cost the pyramid's narrow phase 2.7 %
// (callgrind, 150 steps, Collide: 87.4 M instructions against 85.1 M inlined, as the evaluation
// was before).
[[gnu::always_inline]] inline Answer plug_in_answer(b2Manifold* manifold, const Setting& setting,
                                                    const PolygonPair& p, ContactMemory& memory,
                                                    const TriangleContact* contact,
                                                    ManifoldRecycling* recycling) {
  using Shapes = ContactMemory::Shapes;
  ThreadCounters& count = counters();
  if (memory.shapes == Shapes::Unchecked) look_at_shapes(p.a, p.b, memory);
  if (memory.shapes == Shapes::Polygons) {
    count.polygon_pairs.add();
    return Answer::Box2DOther;
  }
  count.triangle_pairs[static_cast<int>(*setting.backend)].add();

  const b2Transform b_in_a = b2MulT(p.xf_a, p.xf_b);
  const float margin = p.a.m_radius + p.b.m_radius;
  const bool recycles = recycling && setting.recycles();
  if (recycles) {
    if (keeps_manifold(setting, p, b_in_a, memory, *recycling, contact, margin)) {
      count.recycled.add();
      if (manifold->pointCount > 0) count.manifolds.add();
      return Answer::Plugin;
    }
    recycling->forget();
  }
  const bool skip_bounds =
      setting.config.bounds_early_out && circles_apart(p.a, p.b, b_in_a, memory, reach(margin));
  if (skip_bounds || (setting.config.warm_axis && setting.method && memory.last_face >= 0 &&
                      face_separation(memory.last_face, p.a, p.b, b_in_a) > face_reach(margin))) {
    manifold->pointCount = 0;
    count.skipped[static_cast<int>(skip_bounds ? Skip::Bounds : Skip::WarmAxis)].add();
    if (recycles && setting.never_recompute) recycling->remember(b_in_a, 1, setting.epoch);
    return Answer::Plugin;
  }
  // `Backend::Box2D` has no method: Box2D's own code is its answer, not a fallback. A method
  // that cannot answer falls back so that the world goes on, and is counted.
  if (!setting.method) return Answer::Box2DBackend;
  if (memory.shapes == Shapes::Triangles &&
      run_method(manifold, setting, p, b_in_a, memory, contact)) {
    if (manifold->pointCount > 0) count.manifolds.add();
    if (recycles) {
      const float slack = setting.never_recompute
                              ? 1.0f
                              : recycle_slack(setting, *manifold, p, b_in_a, memory, margin);
      recycling->remember(b_in_a, slack, setting.epoch);
    }
    return Answer::Plugin;
  }
  count.fallbacks.add();
  return Answer::Box2DFallback;
}

// The plug-in's answer for one polygon pair with `setting` (uninstalled: Box2D's own answer,
// uncounted, exactly as Box2D's own contact); `memory` is the pair's state, updated; `contact`
// the world's contact it belongs to, if any, and `recycling` its kept manifold's pose (both
// nullptr for `collide_polygons`).
inline void evaluate(b2Manifold* manifold, const Setting& setting, const PolygonPair& pair,
                     ContactMemory& memory, const TriangleContact* contact = nullptr,
                     ManifoldRecycling* recycling = nullptr) {
  const Answer answer = setting.backend
                            ? plug_in_answer(manifold, setting, pair, memory, contact, recycling)
                            : Answer::Box2DOther;
  if (answer == Answer::Plugin) return;
  b2CollidePolygons(manifold, &pair.a, pair.xf_a, &pair.b, pair.xf_b);
  if (answer == Answer::Box2DOther) return;
  if (manifold->pointCount > 0) counters().manifolds.add();
  // Box2D's code as the backend is kept like a method's answer (a manifold with points only:
  // it judges no face that could bound an empty one's slack).
  if (answer == Answer::Box2DBackend && recycling && setting.recycles()) {
    const float slack = setting.never_recompute ? 1.0f
                        : manifold->pointCount > 0 ? setting.config.recycle_distance
                                                   : 0.0f;
    recycling->remember(b2MulT(pair.xf_a, pair.xf_b), slack, setting.epoch);
  }
}

}  // namespace dyop::box2d::detail
