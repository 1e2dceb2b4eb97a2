#include "convex_evaluation.hpp"

#include <cmath>
#include <optional>

#include "detail/polygon_circle.hpp"
#include "detail/polygon_pair.hpp"
#include "detail/validated_size.hpp"
#include "dyop/convex_pair.hpp"
#include "edge_data.hpp"
#include "evaluation.hpp"
#include "internal_edges.hpp"
#include "recycling.hpp"
#include "stats.hpp"
#include "triangle_contact.hpp"

namespace dyop::box2d::detail {
namespace {

// A `b2PolygonShape` in its body frame as the solver reads a polygon
// (`detail::collide_polygon_circle`, `detail::collide_polygons`), in place: what
// `Polygon<float>::from_validated` would hold, without building it.
class InPlace {
 public:
  explicit InPlace(const b2PolygonShape& shape)
      : shape_(shape),
        size_(dyop::detail::validated_size<float>(
            shape.m_count, [&](int i) { return vertex(i); }, [&](int i) { return normal(i); })) {}
  int count() const { return shape_.m_count; }
  Vec2<float> vertex(int i) const { return {shape_.m_vertices[i].x, shape_.m_vertices[i].y}; }
  Vec2<float> normal(int i) const { return {shape_.m_normals[i].x, shape_.m_normals[i].y}; }
  int next(int i) const { return i + 1 < shape_.m_count ? i + 1 : 0; }
  float size() const { return size_; }
  // Box2D's vertices are CCW: the caller's order is the solver's.
  static int input_vertex(int i) { return i; }
  static int input_edge(int i) { return i; }

 private:
  const b2PolygonShape& shape_;
  float size_;
};

// A `b2PolygonShape` placed by `xf` (B's body frame in A's) as the solver reads a polygon
// (`detail::collide_polygons`): what `Polygon<float>::from_validated` with the transform would
// hold (its size measured in the body frame), each vertex and normal placed when read (the
// solver's frame reads each once).
class Placed : public InPlace {
 public:
  Placed(const b2PolygonShape& shape, const b2Transform& xf) : InPlace(shape), xf_(xf) {}
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

// The masks a fixture's pairs read: its fixed edge data, else found now.
ShapeMasks masks_of(const b2Fixture& fixture) {
  if (const std::optional<ShapeMasks> fixed = fixed_polygon_edges(fixture)) return *fixed;
  return polygon_internal_edges(fixture);
}

// Writes the solver's manifold of polygon `a` and circle `b` (`center`: the circle's centre in
// A's frame) as Box2D's: A's face, its own normal and midpoint; nearest a vertex, the normal from
// the vertex to the centre and a point of that plane; the point at the circle's centre, key 0.
void write_circle_manifold(b2Manifold* manifold, const Manifold<float>& mf, const b2PolygonShape& a,
                           const b2CircleShape& b, const b2Vec2& center) {
  manifold->pointCount = mf.point_count;
  if (mf.point_count == 0) return;
  const int e1 = mf.reference_edge;
  const int e2 = e1 + 1 < a.m_count ? e1 + 1 : 0;
  const b2Vec2 normal(mf.normal.x(), mf.normal.y());
  manifold->type = b2Manifold::e_faceA;
  if (normal.x == a.m_normals[e1].x && normal.y == a.m_normals[e1].y) {
    manifold->localNormal = a.m_normals[e1];
    manifold->localPoint = 0.5f * (a.m_vertices[e1] + a.m_vertices[e2]);
  } else {
    manifold->localNormal = normal;
    manifold->localPoint = center - (mf.points[0].separation + b.m_radius) * normal;
  }
  b2ManifoldPoint& mp = manifold->points[0];
  mp.localPoint = b.m_p;
  mp.normalImpulse = 0;
  mp.tangentImpulse = 0;
  mp.id.key = 0;
}

// Box2D's own answer for a pair the plug-in hands back (`Backend::Box2D`, `triangles_only`).
bool box2d_answers(const Setting& setting) {
  return setting.backend == Backend::Box2D || setting.config.triangles_only;
}

// The least of `n·v` over a polygon's vertices.
float least_along(const b2Vec2& n, const b2PolygonShape& shape) {
  float least = b2Dot(n, shape.m_vertices[0]);
  for (int i = 1; i < shape.m_count; ++i) least = std::min(least, b2Dot(n, shape.m_vertices[i]));
  return least;
}

// Separation of two polygons along face `face` (A's edge `face`, or B's edge `face − count of A`;
// `b_in_a`: B's body frame given in A's), with the other polygon's whole support: a lower bound
// on their distance (as `face_separation` for triangles). The face's normal is rotated into the
// other body's frame, so the other's vertices are used as its shape holds them.
float polygon_face_separation(int face, const b2PolygonShape& a, const b2PolygonShape& b,
                              const b2Transform& b_in_a) {
  if (face < a.m_count) {
    const b2Vec2& n = a.m_normals[face];
    return least_along(b2MulT(b_in_a.q, n), b) + b2Dot(n, b_in_a.p - a.m_vertices[face]);
  }
  const int e = face - a.m_count;
  const b2Vec2& n = b.m_normals[e];
  const b2Vec2 m = b2Mul(b_in_a.q, n);
  return least_along(m, a) - b2Dot(m, b_in_a.p) - b2Dot(n, b.m_vertices[e]);
}

// The face the solver judged the pair on (`ContactMemory::last_face`, as for triangles: A's
// edges first, then B's).
std::int8_t judged_face(const Manifold<float>& m, int count_a) {
  return static_cast<std::int8_t>(m.reference_edge + (m.reference_is_a ? 0 : count_a));
}

}  // namespace

bool valid_polygon(const b2PolygonShape& shape) {
  Vec2<float> v[b2_maxPolygonVertices];
  for (int i = 0; i < shape.m_count; ++i) v[i] = {shape.m_vertices[i].x, shape.m_vertices[i].y};
  return Polygon<float>::check(v, shape.m_count) == ConvexError::None;
}

float bounding_radius(const b2PolygonShape& shape) {
  float sq = 0;
  for (int i = 0; i < shape.m_count; ++i) {
    sq = std::max(sq, (shape.m_vertices[i] - shape.m_centroid).LengthSquared());
  }
  return std::sqrt(sq);
}

namespace {

// Where the pair is, for keeping its manifold: B's body frame in A's, B's centroid in its own
// frame (a circle's centre), the skins and the lever of `recycle_lever`.
struct ConvexPose {
  b2Transform b_in_a;
  b2Vec2 centroid_b;
  float margin;
  float lever;
};

// Keep: true when the world's contact keeps the manifold in `manifold` (counted).
bool keep(const Setting& setting, const ConvexPose& pose, const b2Manifold& manifold,
          const ManifoldRecycling* recycling, const TriangleContact* contact, FoundMasks* masks) {
  if (!recycling || !setting.recycles() || !(recycling->slack > 0)) return false;
  if (!keeps_manifold_at(setting, setting.config.internal_edges, pose.b_in_a, pose.centroid_b,
                         pose.lever, *recycling, contact, masks)) {
    return false;
  }
  ThreadCounters& count = counters();
  count.recycled.add();
  if (manifold.pointCount > 0) count.manifolds.add();
  return true;
}

// Skip: the empty manifold, the kept pose lost (or, for the measurement floor, kept for good).
void skip(b2Manifold* manifold, const Setting& setting, const ConvexPose& pose,
          ManifoldRecycling* recycling) {
  manifold->pointCount = 0;
  if (!recycling) return;
  if (setting.never_recompute && setting.method) {
    recycling->remember(pose.b_in_a, pose.centroid_b, 1, setting.epoch);
  } else {
    recycling->lose_pose();
  }
}

// The solver's answer `solve(query)` with the internal-edge rule: both fixtures' fixed edge data;
// else a world's contact's own masks when they hold, found only once an answer without them is
// not apart beyond the skins; a caller's (`memory`) as given. `circle`: B is a circle (no masks).
template <class Solve>
Result<float> answer_with_masks(const Setting& setting, const ConvexPose& pose,
                                ContactMemory& memory, const TriangleContact* contact,
                                FoundMasks* masks, const ManifoldRecycling* recycling, bool circle,
                                ConvexQuery<float>& q, const Solve& solve) {
  bool put_off = false;
  if (setting.config.internal_edges) {
    const std::optional<ShapeMasks> fixed_a =
        contact ? fixed_polygon_edges(*contact->GetFixtureA()) : std::nullopt;
    const std::optional<ShapeMasks> fixed_b = !fixed_a || circle
                                                  ? std::optional<ShapeMasks>(ShapeMasks{})
                                                  : fixed_polygon_edges(*contact->GetFixtureB());
    if (fixed_a && fixed_b) {
      memory.internal_edges = {fixed_a->edges, fixed_a->closed_vertices};
      memory.masks_b = *fixed_b;
      masks->stamp = FoundMasks::fixed_stamp;
    } else if (contact) {
      put_off = masks_put_off(setting, pose.b_in_a, pose.centroid_b, pose.lever, *masks, *contact,
                              recycling);
    }
    if (!put_off) {
      q.masks_a = {memory.internal_edges.edges, memory.internal_edges.closed_vertices};
      q.masks_b = memory.masks_b;
    }
  }
  Result<float> r = solve(q);
  if (put_off && needs_masks(r, q.margin)) {
    masks->found_now(contact->world_fixtures());
    q.masks_a = masks_of(*contact->GetFixtureA());
    q.masks_b = circle ? ShapeMasks{} : masks_of(*contact->GetFixtureB());
    memory.internal_edges = {q.masks_a.edges, q.masks_a.closed_vertices};
    memory.masks_b = q.masks_b;
    if (q.masks_a.any() || q.masks_b.any()) r = solve(q);
  }
  if (q.masks_a.any() || q.masks_b.any()) counters().internal_edge_pairs.add();
  return r;
}

// Remembers the pose of a manifold just answered: kept while the pair moves less than the
// setting's distance (a share of it with a static body); an empty one also no farther than its
// gap beyond what a manifold reaches (`Apart::Gap`: a lower bound on the distance, so no new
// contact is missed; see `face_reach`).
void remember(const Setting& setting, const ConvexPose& pose, const b2Manifold& manifold,
              const Result<float>& r, const TriangleContact* contact,
              ManifoldRecycling* recycling) {
  if (!recycling || !setting.recycles()) return;
  float slack = 1;
  if (!setting.never_recompute) {
    const bool static_pair = contact && contact->with_static_body();
    const float distance = setting.config.recycle_distance * (static_pair ? static_pair_share : 1);
    const float gap = r.status == Status::Separated ? r.separation - face_reach(pose.margin) : 0;
    slack = manifold.pointCount > 0 ? distance : std::max(0.0f, std::min(distance, gap));
  }
  recycling->remember(pose.b_in_a, pose.centroid_b, slack, setting.epoch);
}

}  // namespace

void evaluate_polygons(b2Manifold* manifold, const Setting& setting, const PolygonPair& p,
                       ContactMemory& memory, const TriangleContact* contact, FoundMasks* masks,
                       ManifoldRecycling* recycling) {
  ThreadCounters& count = counters();
  count.polygon_pairs.add();
  if (box2d_answers(setting) || memory.shapes == ContactMemory::Shapes::InvalidPolygons) {
    if (!box2d_answers(setting)) count.fallbacks.add();
    b2CollidePolygons(manifold, &p.a, p.xf_a, &p.b, p.xf_b);
    if (manifold->pointCount > 0) count.manifolds.add();
    return;
  }
  count.exact_pairs.add();
  const float margin = p.a.m_radius + p.b.m_radius;  // the skins: speculative, as Box2D's
  const ConvexPose pose{b2MulT(p.xf_a, p.xf_b), p.b.m_centroid, margin,
                        recycle_lever(memory.radius_sum, margin)};
  if (keep(setting, pose, *manifold, recycling, contact, masks)) return;
  if (setting.config.bounds_early_out &&
      circles_apart(p.a, p.b, pose.b_in_a, memory, reach(margin))) {
    return skip(manifold, setting, pose, recycling);
  }
  if (setting.config.warm_axis && memory.last_face >= 0 &&
      polygon_face_separation(memory.last_face, p.a, p.b, pose.b_in_a) > face_reach(margin)) {
    return skip(manifold, setting, pose, recycling);
  }
  const InPlace a(p.a);
  const Placed b(p.b, pose.b_in_a);
  ConvexQuery<float> q;
  q.level = Level::Manifold;
  q.margin = margin;
  q.face_hysteresis = face_hysteresis;
  q.apart = Apart::Gap;  // beyond the skins a manifold is empty: no distance is needed
  q.witnesses = false;   // Box2D's solver reads the manifold alone
  // The solver inlined into this evaluation, as for circles (`evaluate_polygon_circle`).
  const Result<float> r = answer_with_masks(
      setting, pose, memory, contact, masks, recycling, false,
      q, [&](const ConvexQuery<float>& query) __attribute__((always_inline)) {
        return dyop::detail::collide_polygons(a, b, query);
      });
  if (r.manifold.point_count > 0) count.manifolds.add();
  memory.last_face = judged_face(r.manifold, p.a.m_count);
  write_manifold(manifold, r.manifold, p, pose.b_in_a);
  remember(setting, pose, *manifold, r, contact, recycling);
}

void evaluate_polygon_circle(b2Manifold* manifold, const Setting& setting, const b2PolygonShape& a,
                             const b2Transform& xf_a, const b2CircleShape& b,
                             const b2Transform& xf_b, ContactMemory& memory,
                             const TriangleContact* contact, FoundMasks* masks,
                             ManifoldRecycling* recycling) {
  if (!setting.backend) {
    b2CollidePolygonAndCircle(manifold, &a, xf_a, &b, xf_b);
    return;
  }
  ThreadCounters& count = counters();
  count.circle_pairs.add();
  if (memory.shapes == ContactMemory::Shapes::Unchecked) {
    const bool valid = valid_polygon(a) &&
                       Circle<float>::check({b.m_p.x, b.m_p.y}, b.m_radius) == ConvexError::None;
    memory.shapes =
        valid ? ContactMemory::Shapes::PolygonAndCircle : ContactMemory::Shapes::InvalidPolygons;
    memory.radius_sum = bounding_radius(a) + b.m_radius;
  }
  if (box2d_answers(setting) || memory.shapes == ContactMemory::Shapes::InvalidPolygons) {
    if (!box2d_answers(setting)) count.fallbacks.add();
    b2CollidePolygonAndCircle(manifold, &a, xf_a, &b, xf_b);
    if (manifold->pointCount > 0) count.manifolds.add();
    return;
  }
  count.exact_pairs.add();
  // The pair is computed in A's body frame; the polygon's skin is the margin, as
  // `b2CollidePolygonAndCircle` keeps a point up to the sum of the two radii.
  const float margin = a.m_radius;
  const ConvexPose pose{b2MulT(xf_a, xf_b), b.m_p, margin,
                        recycle_lever(memory.radius_sum, margin)};
  if (keep(setting, pose, *manifold, recycling, contact, masks)) return;
  const b2Vec2 center = b2Mul(pose.b_in_a, b.m_p);
  const float reach_sum = memory.radius_sum + reach(margin);
  if (setting.config.bounds_early_out &&
      (center - a.m_centroid).LengthSquared() > reach_sum * reach_sum) {
    return skip(manifold, setting, pose, recycling);
  }
  // The circle beyond the line of the face it was judged on: apart at least that far.
  if (setting.config.warm_axis && memory.last_face >= 0 &&
      b2Dot(a.m_normals[memory.last_face], center - a.m_vertices[memory.last_face]) - b.m_radius >
          face_reach(margin)) {
    return skip(manifold, setting, pose, recycling);
  }
  const InPlace pa(a);
  const Circle<float> circle{{center.x, center.y}, b.m_radius};
  ConvexQuery<float> q;
  q.level = Level::Manifold;
  q.margin = margin;
  q.apart = Apart::Gap;
  q.witnesses = false;
  // The solver inlined into this evaluation (as a call, twice as `answer_with_masks` has it, the
  // answer went through memory: measured 66 → 59 ns a pair with `place_center` inlined too).
  const Result<float> r = answer_with_masks(
      setting, pose, memory, contact, masks, recycling, true,
      q, [&](const ConvexQuery<float>& query) __attribute__((always_inline)) {
        return dyop::detail::collide_polygon_circle(pa, circle, query);
      });
  memory.last_face = judged_face(r.manifold, a.m_count);
  write_circle_manifold(manifold, r.manifold, a, b, center);
  if (manifold->pointCount > 0) count.manifolds.add();
  remember(setting, pose, *manifold, r, contact, recycling);
}

}  // namespace dyop::box2d::detail
