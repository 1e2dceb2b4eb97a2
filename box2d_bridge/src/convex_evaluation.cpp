#include "convex_evaluation.hpp"

#include <cmath>
#include <optional>

#include "dyop/convex_pair.hpp"
#include "edge_data.hpp"
#include "evaluation.hpp"
#include "internal_edges.hpp"
#include "stats.hpp"
#include "triangle_contact.hpp"

namespace dyop::box2d::detail {
namespace {

// A `b2PolygonShape` as the solver's polygon (Box2D's CCW vertices and its own unit normals), in
// its body frame or placed by `xf`.
Polygon<float> placed(const b2PolygonShape& shape, const b2Transform* xf = nullptr) {
  Vec2<float> v[b2_maxPolygonVertices];
  Vec2<float> n[b2_maxPolygonVertices];
  for (int i = 0; i < shape.m_count; ++i) {
    v[i] = {shape.m_vertices[i].x, shape.m_vertices[i].y};
    n[i] = {shape.m_normals[i].x, shape.m_normals[i].y};
  }
  if (!xf) return Polygon<float>::from_validated(v, n, shape.m_count);
  return Polygon<float>::from_validated(v, n, shape.m_count, xf->q.c, xf->q.s, {xf->p.x, xf->p.y});
}

// The masks a fixture's pairs read: its fixed edge data, else found now.
ShapeMasks masks_of(const b2Fixture& fixture) {
  if (const std::optional<ShapeMasks> fixed = fixed_polygon_edges(fixture)) return *fixed;
  return polygon_internal_edges(fixture);
}

// True unless `r` (with `Apart::Gap`) is apart beyond `margin`: only then can masks change it.
bool needs_masks(const Result<float>& r, float margin) {
  return !(r.status == Status::Separated && r.separation > margin);
}

// Box2D's own answer for a pair the plug-in hands back (`Backend::Box2D`, `triangles_only`).
bool box2d_answers(const Setting& setting) {
  return setting.backend == Backend::Box2D || setting.config.triangles_only;
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

void evaluate_polygons(b2Manifold* manifold, const Setting& setting, const PolygonPair& p,
                       ContactMemory& memory, const TriangleContact* contact, FoundMasks* masks) {
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
  const b2Transform b_in_a = b2MulT(p.xf_a, p.xf_b);
  if (setting.config.bounds_early_out && circles_apart(p.a, p.b, b_in_a, memory, reach(margin))) {
    manifold->pointCount = 0;
    return;
  }
  const Polygon<float> a = placed(p.a);
  const Polygon<float> b = placed(p.b, &b_in_a);
  ConvexQuery<float> q;
  q.level = Level::Manifold;
  q.margin = margin;
  q.face_hysteresis = face_hysteresis;
  q.apart = Apart::Gap;  // beyond the skins a manifold is empty: no distance is needed
  q.witnesses = false;   // Box2D's solver reads the manifold alone
  // The masks: both fixtures' fixed edge data; else a world's contact's own when they hold, found
  // only once an answer without them is not apart beyond the skins; a caller's as given.
  bool put_off = false;
  if (setting.config.internal_edges) {
    const std::optional<ShapeMasks> fixed_a =
        contact ? fixed_polygon_edges(*contact->GetFixtureA()) : std::nullopt;
    const std::optional<ShapeMasks> fixed_b =
        fixed_a ? fixed_polygon_edges(*contact->GetFixtureB()) : std::nullopt;
    if (fixed_a && fixed_b) {
      memory.internal_edges = {fixed_a->edges, fixed_a->closed_vertices};
      memory.masks_b = *fixed_b;
      masks->stamp = FoundMasks::fixed_stamp;
    } else {
      put_off = contact && masks_put_off(setting, p, b_in_a, memory, *masks, *contact, nullptr);
    }
    if (!put_off) {
      q.masks_a = {memory.internal_edges.edges, memory.internal_edges.closed_vertices};
      q.masks_b = memory.masks_b;
    }
  }
  Result<float> r = collide(a, b, q);
  if (put_off && needs_masks(r, margin)) {
    masks->found_now(contact->world_fixtures());
    q.masks_a = masks_of(*contact->GetFixtureA());
    q.masks_b = masks_of(*contact->GetFixtureB());
    memory.internal_edges = {q.masks_a.edges, q.masks_a.closed_vertices};
    memory.masks_b = q.masks_b;
    if (q.masks_a.any() || q.masks_b.any()) r = collide(a, b, q);
  }
  if (q.masks_a.any() || q.masks_b.any()) count.internal_edge_pairs.add();
  if (r.manifold.point_count > 0) count.manifolds.add();
  write_manifold(manifold, r.manifold, p, b_in_a);
}

void evaluate_polygon_circle(b2Manifold* manifold, const Setting& setting, const b2PolygonShape& a,
                             const b2Transform& xf_a, const b2CircleShape& b,
                             const b2Transform& xf_b, ContactMemory& memory,
                             const TriangleContact* contact) {
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
  // The circle's centre in A's body frame: the pair is computed there (the skin of the polygon is
  // the margin, as `b2CollidePolygonAndCircle` keeps a point up to the sum of the two radii).
  const b2Vec2 center = b2MulT(xf_a, b2Mul(xf_b, b.m_p));
  const float margin = a.m_radius;
  manifold->pointCount = 0;
  const float reach_sum = memory.radius_sum + reach(margin);
  if (setting.config.bounds_early_out &&
      (center - a.m_centroid).LengthSquared() > reach_sum * reach_sum) {
    return;
  }
  const Polygon<float> pa = placed(a);
  const Circle<float> circle{{center.x, center.y}, b.m_radius};
  ConvexQuery<float> q;
  q.level = Level::Manifold;
  q.margin = margin;
  q.apart = Apart::Gap;
  q.witnesses = false;
  Result<float> r = collide(pa, circle, q);
  if (setting.config.internal_edges && contact && needs_masks(r, margin)) {
    q.masks_a = masks_of(*contact->GetFixtureA());
    if (q.masks_a.any()) {
      count.internal_edge_pairs.add();
      r = collide(pa, circle, q);
    }
  } else if (setting.config.internal_edges && !contact) {
    q.masks_a = {memory.internal_edges.edges, memory.internal_edges.closed_vertices};
    if (q.masks_a.any()) r = collide(pa, circle, q);
  }
  const Manifold<float>& mf = r.manifold;
  if (mf.point_count == 0) return;
  count.manifolds.add();
  // Box2D's circle manifold: A's face, its own normal and midpoint; nearest a vertex, the normal
  // from the vertex to the centre and a point of that plane.
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
  manifold->pointCount = 1;
  b2ManifoldPoint& mp = manifold->points[0];
  mp.localPoint = b.m_p;
  mp.normalImpulse = 0;
  mp.tangentImpulse = 0;
  mp.id.key = 0;
}

}  // namespace dyop::box2d::detail
