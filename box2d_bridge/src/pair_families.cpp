#include "pair_families.hpp"

#include <cmath>
#include <optional>

#include "edge_data.hpp"
#include "internal_edges.hpp"
#include "contact.hpp"

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

// Box2D's face fields of a manifold on polygon `ref`'s edge `edge` (`type`: whose face): the
// polygon's own normal and the edge's midpoint (not the solver's recomputed normal: Box2D's solver
// then sees exactly the plane Box2D would have given it).
void write_polygon_face(b2Manifold* manifold, b2Manifold::Type type, const b2PolygonShape& ref,
                        int edge) {
  const int next = edge + 1 < ref.m_count ? edge + 1 : 0;
  manifold->type = type;
  manifold->localNormal = ref.m_normals[edge];
  manifold->localPoint = 0.5f * (ref.m_vertices[edge] + ref.m_vertices[next]);
}

// The solver's points of `mf` (computed in A's body frame; `b_in_a`: B's body frame given in A's)
// as Box2D's: on the incident shape, in its body frame (B's go back to B's frame), with the
// solver's keys and no impulse yet.
void write_points(b2Manifold* manifold, const Manifold<float>& mf, const b2Transform& b_in_a) {
  for (int i = 0; i < mf.point_count; ++i) {
    const b2Vec2 p(mf.points[i].point.x(), mf.points[i].point.y());
    b2ManifoldPoint& mp = manifold->points[i];
    mp.localPoint = mf.reference_is_a ? b2MulT(b_in_a, p) : p;
    mp.normalImpulse = 0;
    mp.tangentImpulse = 0;
    mp.id.key = mf.points[i].key;
  }
}

// Writes the solver's manifold `mf` of polygons `a` and `b` as Box2D's.
void write_polygon_manifold(b2Manifold* manifold, const Manifold<float>& mf,
                            const b2PolygonShape& a, const b2PolygonShape& b,
                            const b2Transform& b_in_a) {
  manifold->pointCount = mf.point_count;
  if (mf.point_count == 0) return;
  write_polygon_face(manifold, mf.reference_is_a ? b2Manifold::e_faceA : b2Manifold::e_faceB,
                     mf.reference_is_a ? a : b, mf.reference_edge);
  write_points(manifold, mf, b_in_a);
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

namespace {

// The shapes of an edge pair: `front`, `back` or `invalid`, by the segment's validity and, for a
// two-sided edge, the side of B's centroid (ties to the front); its bounding radius, half its
// length about its midpoint.
void look_at_edge(const b2EdgeShape& a, bool b_valid, const b2Vec2& centroid_b_in_a, float radius_b,
                  ContactMemory::Shapes front, ContactMemory::Shapes back,
                  ContactMemory::Shapes invalid, ContactMemory& memory) {
  memory.radius_sum = 0.5f * b2Distance(a.m_vertex1, a.m_vertex2) + radius_b;
  if (!b_valid || Segment<float>::check(vec(a.m_vertex1), vec(a.m_vertex2)) != ConvexError::None) {
    memory.shapes = invalid;
    return;
  }
  const bool on_back = !a.m_oneSided && on_back_of(a, centroid_b_in_a);
  memory.shapes = on_back ? back : front;
  // A one-sided edge's masks are its shape's, once (`EdgePair::take_masks`).
  const ShapeMasks m = a.m_oneSided ? one_sided_masks(a) : ShapeMasks{};
  memory.internal_edges = {m.edges, m.closed_vertices};
  memory.edge_ends = {};  // not known yet (the contact's masks bring them)
}

}  // namespace

void look_at_shapes(const b2EdgeShape& a, const b2PolygonShape& b, const b2Vec2& centroid_b_in_a,
                    ContactMemory& memory) {
  using Shapes = ContactMemory::Shapes;
  look_at_edge(a, valid_polygon(b), centroid_b_in_a, bounding_radius(b), Shapes::EdgeAndPolygon,
               Shapes::EdgeBackAndPolygon, Shapes::InvalidEdgeAndPolygon, memory);
}

void look_at_shapes(const b2EdgeShape& a, const b2CircleShape& b, const b2Vec2& centroid_b_in_a,
                    ContactMemory& memory) {
  using Shapes = ContactMemory::Shapes;
  const bool valid = Circle<float>::check(vec(b.m_p), b.m_radius) == ConvexError::None;
  look_at_edge(a, valid, centroid_b_in_a, b.m_radius, Shapes::EdgeAndCircle,
               Shapes::EdgeBackAndCircle, Shapes::InvalidEdgeAndCircle, memory);
}

void face_edge_side(ContactMemory& memory, bool back) {
  using Shapes = ContactMemory::Shapes;
  if (on_edge_back(memory.shapes) == back) return;
  const bool circle =
      memory.shapes == Shapes::EdgeAndCircle || memory.shapes == Shapes::EdgeBackAndCircle;
  memory.shapes = circle ? (back ? Shapes::EdgeBackAndCircle : Shapes::EdgeAndCircle)
                         : (back ? Shapes::EdgeBackAndPolygon : Shapes::EdgeAndPolygon);
  if (memory.edge_ends.neighbours() == 0) return;
  const ShapeMasks m = side_masks(memory.edge_ends, back);
  memory.internal_edges = {m.edges, m.closed_vertices};
}

bool EdgePair::turned_away(const PairPose& pose, ContactMemory& memory) const {
  const b2Vec2 along = a.m_vertex2 - a.m_vertex1;
  const b2Vec2 offset = pose.centroid_b_in_a - a.m_vertex1;
  const float side = b2Cross(along, offset);  // > 0: the back
  const float t = b2Dot(along, offset);
  if (side != 0 && (t < 0 || t > b2Dot(along, along))) face_edge_side(memory, side > 0);
  return beyond_corner(memory.edge_ends, a.m_vertex1, a.m_vertex2, on_edge_back(memory.shapes),
                       pose.centroid_b_in_a);
}

ShapeMasks one_sided_masks(const b2EdgeShape& edge) {
  const b2Vec2 before = edge.m_vertex1 - edge.m_vertex0;
  const b2Vec2 along = edge.m_vertex2 - edge.m_vertex1;
  const b2Vec2 after = edge.m_vertex3 - edge.m_vertex2;
  // The outline runs along the chain with its solid on the left (the front is on the right).
  ShapeMasks m;
  m.edges = 0b10;
  m.closed_vertices =
      static_cast<std::uint8_t>(static_cast<unsigned>(turns_flat_or_reflex(before, along)) |
                                static_cast<unsigned>(turns_flat_or_reflex(along, after)) << 1);
  return m;
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

Result<float> TrianglePair::solve(const Setting& setting, const Query& q, const PairPose& pose,
                                  ContactMemory& memory) const {
  if (!setting.run) return {};  // Invalid: Box2D's function answers, counted as a fallback
  // No state: a cold start, as a state never written.
  PairState* const state = setting.config.lin_canny_cache ? &memory.warm_start : nullptr;
  return setting.run(triangle(a), triangle(b, pose.b_in_a), q, state);
}

void TrianglePair::write(b2Manifold* manifold, const Manifold<float>& m,
                         const PairPose& pose) const {
  write_polygon_manifold(manifold, m, a, b, pose.b_in_a);
}

// Two polygons.

void PolygonPair::write(b2Manifold* manifold, const Manifold<float>& m,
                        const PairPose& pose) const {
  write_polygon_manifold(manifold, m, a, b, pose.b_in_a);
}

Result<float> solve_in_place(const InPlace& a, const Placed& b, const ConvexQuery<float>& q) {
  return dyop::detail::collide_polygons(a, b, q);
}

Result<float> solve_in_place(const InPlace& a, const Circle<float>& b,
                             const ConvexQuery<float>& q) {
  return dyop::detail::collide_polygon_circle(a, b, q);
}

// Edge pairs.

void EdgePair::write_faces(b2Manifold* manifold, const Manifold<float>& mf, const b2PolygonShape* b,
                           const b2Transform& b_in_a) const {
  manifold->pointCount = mf.point_count;
  if (mf.point_count == 0) return;
  if (mf.reference_is_a) {
    manifold->type = b2Manifold::e_faceA;
    manifold->localNormal = side_normal(mf.reference_edge);
    manifold->localPoint = a.m_vertex1;
  } else {
    write_polygon_face(manifold, b2Manifold::e_faceB, *b, mf.reference_edge);
  }
  write_points(manifold, mf, b_in_a);
}

std::optional<float> EdgeCirclePair::excluded(const PairPose& pose) const {
  if (const std::optional<float> gap = behind(pose)) return gap;
  if (!a.m_oneSided) return std::nullopt;
  const b2Vec2& q = pose.centroid_b_in_a;
  const b2Vec2 along = a.m_vertex2 - a.m_vertex1;
  // Beyond the first end, in the face region of the edge before it; beyond the second, of the one
  // after it (`b2CollideEdgeAndCircle`'s tests).
  if (b2Dot(along, q - a.m_vertex1) <= 0 && b2Dot(a.m_vertex1 - a.m_vertex0, a.m_vertex1 - q) > 0) {
    return 0.0f;
  }
  if (b2Dot(along, a.m_vertex2 - q) <= 0 && b2Dot(a.m_vertex3 - a.m_vertex2, q - a.m_vertex2) > 0) {
    return 0.0f;
  }
  return std::nullopt;
}

float EdgePolygonPair::face_separation(int face, const PairPose& pose) const {
  if (face < 2) {
    const b2Vec2 n = side_normal(face);
    const b2Vec2 m = b2MulT(pose.b_in_a.q, n);  // A's side normal in B's frame
    float least = b2Dot(m, b.m_vertices[0]);
    for (int i = 1; i < b.m_count; ++i) least = std::min(least, b2Dot(m, b.m_vertices[i]));
    return least + b2Dot(n, pose.b_in_a.p - side_start(face));
  }
  const int e = face - 2;
  const b2Vec2& n = b.m_normals[e];
  const b2Vec2 m = b2Mul(pose.b_in_a.q, n);  // B's normal in A's frame
  const float least = std::min(b2Dot(m, a.m_vertex1), b2Dot(m, a.m_vertex2));
  return least - b2Dot(m, pose.b_in_a.p) - b2Dot(n, b.m_vertices[e]);
}

}  // namespace dyop::box2d::detail
