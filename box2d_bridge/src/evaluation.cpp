#include "evaluation.hpp"

#include <cmath>

#include "convex_evaluation.hpp"
#include "triangle_contact.hpp"

namespace dyop::box2d {
namespace detail {
namespace {

Vec2<float> vec(const b2Vec2& v) { return {v.x, v.y}; }

bool valid_triangle(const b2PolygonShape& shape) {
  return Triangle<float>::check(vec(shape.m_vertices[0]), vec(shape.m_vertices[1]),
                                vec(shape.m_vertices[2])) == TriangleError::None;
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

// True when a world's contact holds no masks that hold now (`masks`; the rule on): none found
// under its stamp as it is now (see `TriangleContact::internal_edges_stamp`), or found before a
// change of the world's fixture count and the pair has moved since as far as such a change could
// matter (`masks_hold`; `recycling`: the pose of the last answer afresh). A new stamp is recorded
// at once, and a contact with a static body then tells the others
// (`TriangleContact::internal_edges_stamp_moved`); a new fixture count tells nobody (every contact
// sees it). But the masks are found only for an answer that needs them (`needs_masks`): most
// contacts a broad phase makes never come within the margin, and finding a static triangle's
// masks costs a query of the world's broad phase and the covering tests.
bool masks_put_off(const Setting& setting, const b2Transform& b_in_a, const b2Vec2& centroid_b,
                   float lever, FoundMasks& masks, const TriangleContact& contact,
                   const ManifoldRecycling* recycling) {
  const std::uint16_t stamp = contact.internal_edges_stamp(setting.epoch);
  if (masks.stamp != stamp) {
    contact.internal_edges_stamp_moved(masks.stamp);
    masks.stamp = stamp;
    masks.motion = FoundMasks::not_found;
  } else {
    notice_fixture_count(masks, contact.world_fixtures());
    if (masks.found() && masks.motion >= 0) {
      // Since the last answer afresh, which had not seen the count move or followed the motion
      // already: every evaluation in between kept its manifold (within the recycling distance of
      // that pose) or was a skip (then the motion is infinite).
      masks.motion +=
          recycling ? recycling->motion(b_in_a, centroid_b, lever, setting.epoch) : HUGE_VALF;
      if (!masks_hold(masks, setting.config.recycle_distance)) {
        masks.motion = FoundMasks::not_found;
      }
    }
  }
  return !masks.found();
}

void look_at_shapes(const b2PolygonShape& a, const b2PolygonShape& b, ContactMemory& memory) {
  memory.radius_sum = bounding_radius(a) + bounding_radius(b);
  if (a.m_count != 3 || b.m_count != 3) {
    memory.shapes = valid_polygon(a) && valid_polygon(b) ? ContactMemory::Shapes::Polygons
                                                         : ContactMemory::Shapes::InvalidPolygons;
    return;
  }
  memory.shapes = ContactMemory::Shapes::UnvalidatedTriangles;
}

void validate_triangles(const b2PolygonShape& a, const b2PolygonShape& b, ContactMemory& memory) {
  memory.shapes = valid_triangle(a) && valid_triangle(b) ? ContactMemory::Shapes::Triangles
                                                         : ContactMemory::Shapes::InvalidTriangles;
}

bool run_method(b2Manifold* manifold, const Setting& setting, const PolygonPair& pair,
                const b2Transform& b_in_a, ContactMemory& memory, const TriangleContact* contact,
                FoundMasks* masks, const ManifoldRecycling* recycling) {
  Query<float> query;
  query.level = Level::Manifold;
  query.margin = pair.a.m_radius + pair.b.m_radius;  // the skins: speculative, as Box2D's
  query.face_hysteresis = face_hysteresis;
  query.apart = Apart::Gap;  // beyond the skins a manifold is empty: no distance is needed
  query.witnesses = false;   // Box2D's solver reads the manifold alone
  PairState cold;
  PairState* const state = setting.config.lin_canny_cache ? &memory.warm_start : &cold;
  const Triangle<float> a = placed(pair.a);
  const Triangle<float> b = placed(pair.b, b_in_a);
  // The masks: the fixtures' fixed edge data; else a world's contact's own when they hold; a
  // caller's (`collide_polygons`) as given.
  bool put_off = false;
  if (setting.internal_edges) {
    const std::optional<InternalEdges> fixed =
        contact ? contact->fixed_internal_edges() : std::nullopt;
    if (fixed) {
      memory.internal_edges = *fixed;
      masks->stamp = FoundMasks::fixed_stamp;
    } else {
      put_off = contact &&
                masks_put_off(setting, b_in_a, pair.b.m_centroid,
                              recycle_lever(memory.radius_sum, pair.a.m_radius + pair.b.m_radius),
                              *masks, *contact, recycling);
    }
    if (!put_off) query.internal_edges = memory.internal_edges;
  }
  Result<float> r = penetrate(*setting.method, a, b, query, state);
  if (put_off && needs_masks(r, query.margin)) {
    masks->found_now(contact->world_fixtures());
    memory.internal_edges =
        contact->find_internal_edges(masks->stamp, masks->fixtures, setting.epoch);
    query.internal_edges = memory.internal_edges;
    // The methods with the rule (`dyop`, `sat`) keep no pair state: this run answers afresh.
    if (query.internal_edges.any()) r = penetrate(*setting.method, a, b, query, state);
  }
  if (query.internal_edges.any()) counters().internal_edge_pairs.add();
  if (r.status == Status::Invalid) return false;

  const Manifold<float>& mf = r.manifold;
  memory.last_face = static_cast<std::int8_t>(mf.reference_edge + (mf.reference_is_a ? 0 : 3));
  write_manifold(manifold, mf, pair, b_in_a);
  return true;
}

void write_manifold(b2Manifold* manifold, const Manifold<float>& mf, const PolygonPair& pair,
                    const b2Transform& b_in_a) {
  manifold->pointCount = mf.point_count;
  if (mf.point_count == 0) return;

  // The reference face in its own body's frame, from the polygon's own data (not the method's
  // recomputed normal): the solver then sees exactly the plane Box2D would have given it.
  const b2PolygonShape& ref = mf.reference_is_a ? pair.a : pair.b;
  const int e1 = mf.reference_edge;
  const int e2 = e1 + 1 < ref.m_count ? e1 + 1 : 0;
  manifold->type = mf.reference_is_a ? b2Manifold::e_faceA : b2Manifold::e_faceB;
  manifold->localNormal = ref.m_normals[e1];
  manifold->localPoint = 0.5f * (ref.m_vertices[e1] + ref.m_vertices[e2]);
  for (int i = 0; i < mf.point_count; ++i) {
    // Points lie on the incident polygon, computed in A's frame: B's points go back to B's frame.
    const b2Vec2 p(mf.points[i].point.x(), mf.points[i].point.y());
    b2ManifoldPoint& mp = manifold->points[i];
    mp.localPoint = mf.reference_is_a ? b2MulT(b_in_a, p) : p;
    mp.normalImpulse = 0;
    mp.tangentImpulse = 0;
    mp.id.key = mf.points[i].key;
  }
}

}  // namespace detail

void collide_polygons(b2Manifold* manifold, Backend backend, const b2PolygonShape& shape_a,
                      const b2Transform& xf_a, const b2PolygonShape& shape_b,
                      const b2Transform& xf_b, ContactMemory* memory, const Config& config) {
  ContactMemory cold;
  detail::evaluate(manifold, detail::Setting(backend, config, 0), {shape_a, xf_a, shape_b, xf_b},
                   memory ? *memory : cold);
}

}  // namespace dyop::box2d

namespace dyop::box2d {

void collide_polygon_and_circle(b2Manifold* manifold, Backend backend,
                                const b2PolygonShape& polygon, const b2Transform& xf_a,
                                const b2CircleShape& circle, const b2Transform& xf_b,
                                ContactMemory* memory, const Config& config) {
  ContactMemory cold;
  detail::evaluate_polygon_circle(manifold, detail::Setting(backend, config, 0), polygon, xf_a,
                                  circle, xf_b, memory ? *memory : cold, nullptr, nullptr, nullptr);
}

}  // namespace dyop::box2d
