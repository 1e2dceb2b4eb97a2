#include "pair_families.hpp"

#include <cmath>
#include <optional>

#include "edge_data.hpp"
#include "internal_edges.hpp"
#include "triangle_contact.hpp"

namespace dyop::box2d::detail {
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
Triangle<float> triangle(const b2PolygonShape& shape) {
  return Triangle<float>::from_validated(vertices(shape), normals(shape));
}
Triangle<float> triangle(const b2PolygonShape& shape, const b2Transform& xf) {
  return Triangle<float>::from_validated(vertices(shape), normals(shape), xf.q.c, xf.q.s,
                                         vec(xf.p));
}

// The masks a fixture's pairs read: its fixed edge data, else found now.
ShapeMasks masks_of(const b2Fixture& fixture) {
  if (const std::optional<ShapeMasks> fixed = fixed_polygon_edges(fixture)) return *fixed;
  return polygon_internal_edges(fixture);
}

// Writes the solver's manifold `mf` of polygons `a` and `b` (computed in A's body frame; `b_in_a`:
// B's body frame given in A's) as Box2D's: the reference face from the polygon's own data (not
// the solver's recomputed normal: Box2D's solver then sees exactly the plane Box2D would have
// given it), points in the incident body's frame, the solver's keys.
void write_polygon_manifold(b2Manifold* manifold, const Manifold<float>& mf,
                            const b2PolygonShape& a, const b2PolygonShape& b,
                            const b2Transform& b_in_a) {
  manifold->pointCount = mf.point_count;
  if (mf.point_count == 0) return;
  const b2PolygonShape& ref = mf.reference_is_a ? a : b;
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

}  // namespace

void look_at_shapes(const b2PolygonShape& a, const b2PolygonShape& b, ContactMemory& memory) {
  memory.radius_sum = bounding_radius(a) + bounding_radius(b);
  if (a.m_count != 3 || b.m_count != 3) {
    memory.shapes = valid_polygon(a) && valid_polygon(b) ? ContactMemory::Shapes::Polygons
                                                         : ContactMemory::Shapes::InvalidPolygons;
    return;
  }
  memory.shapes = ContactMemory::Shapes::UnvalidatedTriangles;
}

void look_at_shapes(const b2PolygonShape& a, const b2CircleShape& b, ContactMemory& memory) {
  const bool valid =
      valid_polygon(a) && Circle<float>::check({b.m_p.x, b.m_p.y}, b.m_radius) == ConvexError::None;
  memory.shapes = valid ? ContactMemory::Shapes::PolygonAndCircle
                        : ContactMemory::Shapes::InvalidPolygonAndCircle;
  memory.radius_sum = bounding_radius(a) + b.m_radius;
}

bool valid_polygon(const b2PolygonShape& shape) {
  Vec2<float> v[b2_maxPolygonVertices];
  for (int i = 0; i < shape.m_count; ++i) v[i] = vec(shape.m_vertices[i]);
  return Polygon<float>::check(v, shape.m_count) == ConvexError::None;
}

float bounding_radius(const b2PolygonShape& shape) {
  float sq = 0;
  for (int i = 0; i < shape.m_count; ++i) {
    sq = std::max(sq, (shape.m_vertices[i] - shape.m_centroid).LengthSquared());
  }
  return std::sqrt(sq);
}

// Two triangles.

void TrianglePair::validate(ContactMemory& memory) const {
  memory.shapes = valid_triangle(a) && valid_triangle(b) ? ContactMemory::Shapes::Triangles
                                                         : ContactMemory::Shapes::InvalidTriangles;
}

void TrianglePair::find_masks(const TriangleContact& contact, const FoundMasks& masks,
                              std::uint8_t epoch, ContactMemory& memory) {
  memory.internal_edges = contact.find_internal_edges(masks.stamp, masks.fixtures, epoch);
}

Result<float> TrianglePair::solve(const Setting& setting, const Query& q, const PairPose& pose,
                                  ContactMemory& memory) const {
  PairState cold;
  PairState* const state = setting.config.lin_canny_cache ? &memory.warm_start : &cold;
  return penetrate(*setting.method, triangle(a), triangle(b, pose.b_in_a), q, state);
}

void TrianglePair::write(b2Manifold* manifold, const Manifold<float>& m,
                         const PairPose& pose) const {
  write_polygon_manifold(manifold, m, a, b, pose.b_in_a);
}

// Pairs beyond two triangles.

bool ExactPair::fixed_masks_of(const TriangleContact& contact, bool b_has_edges,
                               ContactMemory& memory) {
  const std::optional<ShapeMasks> fixed_a = fixed_polygon_edges(*contact.GetFixtureA());
  if (!fixed_a) return false;
  const std::optional<ShapeMasks> fixed_b =
      b_has_edges ? fixed_polygon_edges(*contact.GetFixtureB()) : ShapeMasks{};
  if (!fixed_b) return false;
  memory.internal_edges = {fixed_a->edges, fixed_a->closed_vertices};
  memory.masks_b = *fixed_b;
  return true;
}

void ExactPair::find_masks_of(const TriangleContact& contact, bool b_has_edges,
                              ContactMemory& memory) {
  const ShapeMasks a = masks_of(*contact.GetFixtureA());
  memory.internal_edges = {a.edges, a.closed_vertices};
  memory.masks_b = b_has_edges ? masks_of(*contact.GetFixtureB()) : ShapeMasks{};
}

// Two polygons.

void PolygonPair::write(b2Manifold* manifold, const Manifold<float>& m,
                        const PairPose& pose) const {
  write_polygon_manifold(manifold, m, a, b, pose.b_in_a);
}

}  // namespace dyop::box2d::detail
