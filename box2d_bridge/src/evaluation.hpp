#pragma once
// Internal: the plug-in's one evaluation of a polygon pair, for a world's contact and for
// `collide_polygons` alike. What answers (the backend's method, or Box2D's `b2CollidePolygons`),
// which skips apply, where the internal-edge masks come from and what is counted are decided here
// and nowhere else.
//
// Inline: most evaluations in a world end in a kept manifold or a skip that costs a few dozen
// instructions, and Box2D's own contact answers a pair apart after one face test, so every call,
// every register saved and every transformed vertex counts. The skip tests rotate one normal into
// the other body's frame instead of moving three vertices. The method's run is out of line
// (evaluation.cpp), and so are a world's contact's keep and answer (`TriangleContact::Evaluate`).

#include <box2d/b2_collision.h>
#include <box2d/b2_polygon_shape.h>

#include <algorithm>
#include <optional>

#include "convex_evaluation.hpp"
#include "dyop/box2d.hpp"
#include "found_masks.hpp"
#include "installation.hpp"
#include "polygon_pair.hpp"
#include "recycling.hpp"
#include "stats.hpp"
#include "triangle_contact.hpp"

namespace dyop::box2d::detail {

// The first evaluation: what the two shapes are (triangles, not yet validated, or larger
// polygons) and their bounding radii, kept in `memory` (the shapes of a fixture never change).
void look_at_shapes(const b2PolygonShape& a, const b2PolygonShape& b, ContactMemory& memory);

// The first evaluation that runs the backend on two triangles: valid ones or not
// (`Shapes::Triangles`, `Shapes::InvalidTriangles`). Deferred until then: most contacts a broad
// phase makes never run the backend (docs/measurements.md, "Choices in the code").
void validate_triangles(const b2PolygonShape& a, const b2PolygonShape& b, ContactMemory& memory);

// The setting's method on two valid triangles (`b_in_a`: B's body frame given in A's), with the
// pair's internal-edge masks when the rule is on: `contact` (a world's contact, whose memory is
// `memory` and `masks`) reads them from its fixtures' fixed edge data, else finds them when its
// own do not hold, and only once an answer without them is not apart beyond the skins (it runs
// the method again with them); nullptr (`collide_polygons`): the caller set them in `memory`.
// True when it answered and `manifold` holds its answer; false when the method could not answer
// (`Status::Invalid`) and Box2D's code must. `recycling`: the contact's kept pose, as the last
// answer afresh left it (it bounds how far the pair moved since: `FoundMasks::motion`), nullptr
// for none.
bool run_method(b2Manifold* manifold, const Setting& setting, const PolygonPair& pair,
                const b2Transform& b_in_a, ContactMemory& memory, const TriangleContact* contact,
                FoundMasks* masks, const ManifoldRecycling* recycling);

// True unless `r` (with `Apart::Gap`) is apart beyond `margin`: such an answer is the answer under
// any masks (`Query::internal_edges`, `ConvexQuery`'s masks, `Apart::Gap`; tested over every input
// class and edge mask in the library's `InternalEdgesRule` test), for every pair family.
inline bool needs_masks(const Result<float>& r, float margin) {
  return !(r.status == Status::Separated && r.separation > margin);
}

// Writes the solver's manifold `mf` (computed in A's body frame; `b_in_a`: B's body frame given in
// A's) as Box2D's: the reference face from the polygon's own data, points in the incident body's
// frame, the solver's keys.
void write_manifold(b2Manifold* manifold, const Manifold<float>& mf, const PolygonPair& pair,
                    const b2Transform& b_in_a);

// True when a world's contact `contact` (the rule on) holds no masks that hold now under the
// setting's install and the world as it is (see evaluation.cpp); its stamp and fixture count are
// brought up to date. `recycling`: the pose of its last answer afresh, nullptr for none;
// `centroid_b` and `lever` as `ManifoldRecycling::motion` takes them.
bool masks_put_off(const Setting& setting, const b2Transform& b_in_a, const b2Vec2& centroid_b,
                   float lever, FoundMasks& masks, const TriangleContact& contact,
                   const ManifoldRecycling* recycling);

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

// The manifold in `manifold` may stay (`Config::recycle_distance`, or the measurement floor's
// `Setting::never_recompute`): see recycling.hpp. A change of the pair's internal-edge masks
// (their stamp moved, or they were forgotten) recomputes; a change of the world's fixture count
// alone recomputes only once the pair may have moved toward it (`masks_hold`): one near the pair
// makes or ends a contact with one of its bodies, which forgets the masks at once. `rule`: the
// internal-edge rule is in force for the pair.
inline bool keeps_manifold_at(const Setting& setting, bool rule, const b2Transform& b_in_a,
                              const b2Vec2& centroid_b, float lever,
                              const ManifoldRecycling& recycling, const TriangleContact* contact,
                              FoundMasks* masks) {
  if (setting.never_recompute) return recycling.slack > 0 && recycling.epoch == setting.epoch;
  if (!recycling.keeps(b_in_a, centroid_b, lever, setting.epoch)) return false;
  if (!rule || !contact) return true;
  if (masks->fixed()) return true;  // changed only by a refresh, which recomputes
  if (masks->stamp != contact->internal_edges_stamp(setting.epoch)) return false;
  // Put off: the manifold was answered without masks (apart beyond the margin, the same under any).
  if (!masks->found()) return true;
  notice_fixture_count(*masks, contact->world_fixtures());
  return masks_hold(*masks, setting.config.recycle_distance);
}

// `keeps_manifold_at` for a polygon pair: B's centroid, the lever from the pair's bounding radii
// and the skins `margin`.
inline bool keeps_manifold(const Setting& setting, const PolygonPair& p, const b2Transform& b_in_a,
                           const ContactMemory& memory, const ManifoldRecycling& recycling,
                           const TriangleContact* contact, FoundMasks* masks, float margin) {
  return keeps_manifold_at(setting, setting.internal_edges, b_in_a, p.b.m_centroid,
                           recycle_lever(memory.radius_sum, margin), recycling, contact, masks);
}

// How far a manifold the method just computed may move before a recompute: the setting's
// distance for one with points (a share of it for a pair with a static body: `static_pair_share`);
// for an empty one, also no farther than its judged face's separation beyond what a manifold
// reaches, so that no new contact is missed (see `face_reach`); never below 0 (that marks a skip:
// `ManifoldRecycling::lose_pose`).
inline float recycle_slack(const Setting& setting, const b2Manifold& manifold, const PolygonPair& p,
                           const b2Transform& b_in_a, const ContactMemory& memory, float margin,
                           bool static_pair) {
  const float distance = setting.config.recycle_distance * (static_pair ? static_pair_share : 1);
  if (manifold.pointCount > 0) return distance;
  if (memory.last_face < 0) return 0;
  return std::max(0.0f, std::min(distance, face_separation(memory.last_face, p.a, p.b, b_in_a) -
                                               face_reach(margin)));
}

// An evaluation of a triangle pair under an install is one of three acts, each counted: keep the
// last manifold (a world's contact only), skip, or answer. `evaluate` runs them in one function;
// a world's contact in `TriangleContact::Evaluate`, keep and answer out of line.

// Keep: true when the world's contact keeps the manifold in `manifold` (see `keeps_manifold`),
// counted. Otherwise its pose stays until an answer replaces it, or a skip loses it.
[[gnu::always_inline]] inline bool keep(const b2Manifold& manifold, const Setting& setting,
                                        const PolygonPair& p, ContactMemory& memory,
                                        const ManifoldRecycling& recycling,
                                        const TriangleContact* contact, FoundMasks* masks) {
  // Only a method's run remembers a pose, so the shapes are triangles; an uninstall keeps the
  // epoch, hence the method's check.
  if (setting.method && keeps_manifold(setting, p, b2MulT(p.xf_a, p.xf_b), memory, recycling,
                                       contact, masks, p.a.m_radius + p.b.m_radius)) {
    ThreadCounters& count = counters();
    count.triangle_pairs[static_cast<int>(*setting.backend)].add();
    count.recycled.add();
    if (manifold.pointCount > 0) count.manifolds.add();
    return true;
  }
  return false;
}

// The skip that proves the manifold of a pair of triangles (`triangle_shapes`) empty
// (`Config::bounds_early_out`, `Config::warm_axis`), if any. `b_in_a`: B's body frame given in A's.
inline std::optional<Skip> skip_of(const Setting& setting, const PolygonPair& p,
                                   const b2Transform& b_in_a, const ContactMemory& memory) {
  const float margin = p.a.m_radius + p.b.m_radius;
  if (setting.config.bounds_early_out && circles_apart(p.a, p.b, b_in_a, memory, reach(margin))) {
    return Skip::Bounds;
  }
  if (setting.config.warm_axis && setting.method && memory.last_face >= 0 &&
      face_separation(memory.last_face, p.a, p.b, b_in_a) > face_reach(margin)) {
    return Skip::WarmAxis;
  }
  return std::nullopt;
}

// Skip: true when a pair of triangles under an install, nothing kept, is skipped (`skip_of`): its
// manifold emptied, its pose lost (`recycling`, nullptr for `collide_polygons`), counted last (the
// thread's first count makes its counters: a call, with nothing else left to keep across it).
[[gnu::always_inline]] inline bool skip(b2Manifold* manifold, const Setting& setting,
                                        const PolygonPair& p, const b2Transform& b_in_a,
                                        const ContactMemory& memory, ManifoldRecycling* recycling) {
  const std::optional<Skip> reason = skip_of(setting, p, b_in_a, memory);
  if (!reason) return false;
  manifold->pointCount = 0;
  if (recycling) {
    if (setting.never_recompute && setting.method) {
      recycling->remember(b_in_a, p.b.m_centroid, 1, setting.epoch);
    } else {
      recycling->lose_pose();
    }
  }
  ThreadCounters& count = counters();
  count.skipped[static_cast<int>(*setting.backend)][static_cast<int>(*reason)].add();
  return true;
}

// Answer, once nothing was kept or skipped: the method's answer (`run_method`), its pose
// remembered for keeping (`recycling`: the world's contact's, nullptr for `collide_polygons`);
// Box2D's code for `Backend::Box2D` (its answer, not a fallback), for invalid triangles and for a
// method that could not answer (a counted fallback, so that the world goes on).
[[gnu::always_inline]] inline void answer(b2Manifold* manifold, const Setting& setting,
                                          const PolygonPair& p, const b2Transform& b_in_a,
                                          ContactMemory& memory, const TriangleContact* contact,
                                          FoundMasks* masks, ManifoldRecycling* recycling) {
  ThreadCounters& count = counters();
  count.triangle_pairs[static_cast<int>(*setting.backend)].add();
  if (setting.method) {
    if (memory.shapes == ContactMemory::Shapes::UnvalidatedTriangles) {
      validate_triangles(p.a, p.b, memory);
    }
    if (memory.shapes == ContactMemory::Shapes::Triangles &&
        run_method(manifold, setting, p, b_in_a, memory, contact, masks, recycling)) {
      if (manifold->pointCount > 0) count.manifolds.add();
      if (recycling && setting.recycles()) {
        const float slack =
            setting.never_recompute
                ? 1.0f
                : recycle_slack(setting, *manifold, p, b_in_a, memory, p.a.m_radius + p.b.m_radius,
                                contact && contact->with_static_body());
        recycling->remember(b_in_a, p.b.m_centroid, slack, setting.epoch);
      }
      return;
    }
    count.fallbacks.add();
  }
  b2CollidePolygons(manifold, &p.a, p.xf_a, &p.b, p.xf_b);
  if (manifold->pointCount > 0) count.manifolds.add();
}

// True for a pair whose shapes were looked at and found to be triangles (valid, invalid or not
// validated yet).
inline bool triangle_shapes(const ContactMemory& memory) {
  using Shapes = ContactMemory::Shapes;
  // One range test: every evaluation in full asks.
  constexpr auto index = [](Shapes s) { return static_cast<int>(s); };
  static_assert(index(Shapes::InvalidTriangles) == index(Shapes::Triangles) + 1 &&
                index(Shapes::UnvalidatedTriangles) == index(Shapes::Triangles) + 2);
  return memory.shapes >= Shapes::Triangles && memory.shapes <= Shapes::UnvalidatedTriangles;
}

// The plug-in's answer for one polygon pair with `setting` (uninstalled: Box2D's own answer,
// uncounted, exactly as Box2D's own contact); `memory` is the pair's state, updated; `contact`
// the world's contact it belongs to, if any, `masks` what it found of its masks and `recycling`
// its kept manifold's pose (all nullptr for `collide_polygons`): keep, skip or answer.
inline void evaluate(b2Manifold* manifold, const Setting& setting, const PolygonPair& pair,
                     ContactMemory& memory, const TriangleContact* contact = nullptr,
                     FoundMasks* masks = nullptr, ManifoldRecycling* recycling = nullptr) {
  if (setting.backend) {
    if (memory.shapes == ContactMemory::Shapes::Unchecked) look_at_shapes(pair.a, pair.b, memory);
    if (triangle_shapes(memory)) {
      if (recycling && keep(*manifold, setting, pair, memory, *recycling, contact, masks)) return;
      const b2Transform b_in_a = b2MulT(pair.xf_a, pair.xf_b);
      if (skip(manifold, setting, pair, b_in_a, memory, recycling)) return;
      answer(manifold, setting, pair, b_in_a, memory, contact, masks, recycling);
      return;
    }
    evaluate_polygons(manifold, setting, pair, memory, contact, masks, recycling);
    return;
  }
  b2CollidePolygons(manifold, &pair.a, pair.xf_a, &pair.b, pair.xf_b);
}

}  // namespace dyop::box2d::detail
