#pragma once
// Internal: the pair families the plug-in's contact answers — two triangles, two polygons (a side
// with more than 3 vertices), a polygon and a circle, an edge (or a chain's edge) and a polygon, an
// edge and a circle — each as what the acts of an evaluation need of it (evaluation.hpp: keep,
// skip, answer, written once for every family): where the pair is, a face's separation, which
// masks it takes, its manifold function (the solver's answer, written as Box2D's manifold) and
// Box2D's own function. Each is a function of the shapes, their transforms and the masks handed to
// it, as Box2D v3's manifold functions are; where the masks come from is the contact's business
// (contact.hpp). A world's contact learns its family once, when it is made (`family_of`).

#include <box2d/b2_circle_shape.h>
#include <box2d/b2_collision.h>
#include <box2d/b2_edge_shape.h>
#include <box2d/b2_polygon_shape.h>

#include <algorithm>
#include <cfloat>
#include <cstdint>
#include <optional>

#include "dyop/box2d.hpp"
#include "detail/polygon_circle.hpp"
#include "detail/polygon_pair.hpp"
#include "dyop/convex_pair.hpp"
#include "installation.hpp"
#include "recycling.hpp"
#include "shape_in_place.hpp"
#include "stats.hpp"

namespace dyop::box2d::detail {

enum class Family : std::uint8_t {
  Triangles,
  Polygons,
  PolygonAndCircle,
  EdgeAndPolygon,
  EdgeAndCircle
};

// The family of a pair whose shapes were looked at (`look_at_shapes`).
inline Family family_of(ContactMemory::Shapes shapes) {
  using Shapes = ContactMemory::Shapes;
  if (shapes >= Shapes::EdgeAndCircle) return Family::EdgeAndCircle;
  if (shapes >= Shapes::EdgeAndPolygon) return Family::EdgeAndPolygon;
  if (shapes >= Shapes::PolygonAndCircle) return Family::PolygonAndCircle;
  return shapes >= Shapes::Polygons ? Family::Polygons : Family::Triangles;
}

// True for a pair whose B lies on the back of its two-sided edge (`EdgeBackAndPolygon`,
// `EdgeBackAndCircle`).
inline bool on_edge_back(ContactMemory::Shapes shapes) {
  return shapes == ContactMemory::Shapes::EdgeBackAndPolygon ||
         shapes == ContactMemory::Shapes::EdgeBackAndCircle;
}

// A two-sided edge's pair (`memory`) on the edge's back (`back`) or front from now on, its masks
// with it where the edge's ends are known (`ContactMemory::edge_ends`).
void face_edge_side(ContactMemory& memory, bool back);

// True when `c` (the edge's frame) lies behind the front of two-sided edge `edge`, as the first
// look at the pair decides its side.
inline bool on_back_of(const b2EdgeShape& edge, const b2Vec2& c) {
  return b2Cross(edge.m_vertex2 - edge.m_vertex1, c - edge.m_vertex1) > 0;
}

// What the first look at two polygons finds (their `Shapes` and bounding radii, kept in
// `memory`: the shapes of a fixture never change). Triangles are validated later, by the first
// answer that runs the method (`TrianglePair::accepted`): most contacts a broad phase makes never
// run it (docs/measurements.md, "Choices in the code").
void look_at_shapes(const b2PolygonShape& a, const b2PolygonShape& b, ContactMemory& memory);
// The same for a polygon and a circle.
void look_at_shapes(const b2PolygonShape& a, const b2CircleShape& b, ContactMemory& memory);
// The same for an edge and a polygon or a circle whose centroid (centre) lies at `centroid_b_in_a`
// in the edge's body frame: its side of the edge, for a two-sided edge (ties to the front).
void look_at_shapes(const b2EdgeShape& a, const b2PolygonShape& b, const b2Vec2& centroid_b_in_a,
                    ContactMemory& memory);
void look_at_shapes(const b2EdgeShape& a, const b2CircleShape& b, const b2Vec2& centroid_b_in_a,
                    ContactMemory& memory);

// The masks of a one-sided edge (`m_oneSided`: a chain's edge, or `SetOneSided`) from its ghost
// vertices, `Segment`'s bits: its back internal; an end closed where the outline through it
// (the ghost edge and the edge) is flat or reflex (`turns_flat_or_reflex`: concave seen from the
// front).
ShapeMasks one_sided_masks(const b2EdgeShape& edge);

// True when `Polygon<float>` accepts the shape's vertices (Box2D's hull may keep vertices that are
// collinear within rounding, or a sliver).
bool valid_polygon(const b2PolygonShape& shape);

// Distance from the shape's centroid to its farthest vertex (body frame).
float bounding_radius(const b2PolygonShape& shape);

// A shape's longest edge is at most twice its bounding radius, so at most twice a pair's
// `radius_sum`; twice that again covers the float rounding of both measures.
constexpr float size_bound_per_radius_sum = 4;

// Where a pair is, for keeping, skipping and remembering its manifold.
struct PairPose {
  b2Transform b_in_a;      // B's body frame given in A's
  b2Vec2 centroid_b_in_a;  // B's centroid (a circle's centre) in A's body frame
  float margin;            // the skins (metres): manifold points are kept up to this far apart
  float radius_sum;        // the shapes' bounding radii summed (`ContactMemory::radius_sum`, m)

  // The motion bound's lever (`recycle_lever`).
  float lever() const { return recycle_lever(radius_sum, margin); }
  // At least the longest edge of either shape (metres), for the solver's touching band (`InPlace`).
  float size_bound() const { return size_bound_per_radius_sum * radius_sum; }
};

// The exact solver on shapes read in place: one copy of its code for every family that reads
// them so, polygons and edges alike (out of line: a world whose bodies meet every family runs each
// path's code, and copies of the solver in each would not stay in the instruction cache).
Result<float> solve_in_place(const InPlace& a, const Placed& b, const ConvexQuery<float>& q);
Result<float> solve_in_place(const InPlace& a, const Circle<float>& b, const ConvexQuery<float>& q);

// Separation of two polygons along face `face` (A's edge `face`, or B's edge `face − a.m_count`;
// `b_in_a`: B's body frame given in A's), with the other polygon's whole support: a lower bound
// on their distance. The face's normal is rotated into the other body's frame, so the other's
// vertices are used as its shape holds them. `N`: the vertex count of both when known at compile
// time (triangles), else 0.
template <int N>
[[gnu::always_inline]] inline float face_separation(int face, const b2PolygonShape& a,
                                                    const b2PolygonShape& b,
                                                    const b2Transform& b_in_a) {
  const auto least_along = [](const b2Vec2& n, const b2PolygonShape& shape) {
    const int count = N > 0 ? N : shape.m_count;
    float least = b2Dot(n, shape.m_vertices[0]);
    for (int i = 1; i < count; ++i) least = std::min(least, b2Dot(n, shape.m_vertices[i]));
    return least;
  };
  const int count_a = N > 0 ? N : a.m_count;
  if (face < count_a) {
    const b2Vec2& n = a.m_normals[face];
    return least_along(b2MulT(b_in_a.q, n), b) + b2Dot(n, b_in_a.p - a.m_vertices[face]);
  }
  const int e = face - count_a;
  const b2Vec2& n = b.m_normals[e];
  const b2Vec2 m = b2Mul(b_in_a.q, n);  // B's normal in A's frame
  return least_along(m, a) - b2Dot(m, b_in_a.p) - b2Dot(n, b.m_vertices[e]);
}

// Two faces of a pair beyond two triangles whose separations differ by less than this times the
// pair's `radius_sum` tie, and A's stays the reference (`ExactPair::hysteresis`). Why: it is the
// rounding of computing them (32 ε of the pair's size, as `touching_tolerance`), so the depth the
// solver reads from the manifold stays exact within it, while a resting stack's faces, equal but
// for rounding, keep their reference from step to step. Swapping renames the contact points
// (a vertex on a face becomes a face under a vertex) and loses their warm starts: with no tie, a
// tower of ten 1 m `SetAsBox` boxes drifts 14 cm in 10 s where Box2D's own stands within 2 mm;
// with it, as with Box2D's 0.1·linearSlop hysteresis (which leaves the depth up to 0.5 mm off).
constexpr float face_tie_per_radius = 32 * FLT_EPSILON;

// Beyond this separation along any one face normal (metres), for skins summing to `margin`, a
// manifold has no point: the reference face the full evaluation picks separates the pair by at
// least that face's separation minus `face_hysteresis` (it is the best face of A or B, B's only
// when it beats A's by the hysteresis), and every clipped point lies on the incident edge, at
// least as far from the reference line as the nearer of its ends. So a face whose separation
// exceeds margin + face_hysteresis proves the manifold empty, exactly.
inline float face_reach(float margin) { return margin + face_hysteresis; }

// The face the solver judged a pair on (`ContactMemory::last_face`: A's edges first, then B's).
inline std::int8_t judged_face(const Manifold<float>& m, int count_a) {
  return static_cast<std::int8_t>(m.reference_edge + (m.reference_is_a ? 0 : count_a));
}

// Two triangles: the setting's method (DyOP-PD for `Backend::Dyop`), Box2D's `b2CollidePolygons`
// for `Backend::Box2D`, for a triangle the method refuses and for a method that cannot answer.
struct TrianglePair {
  using Query = dyop::Query<float>;
  // B's face is the reference only when it beats A's by this (metres): Box2D's own.
  static float hysteresis(const PairPose&) { return face_hysteresis; }

  const b2PolygonShape& a;
  const b2Transform& xf_a;
  const b2PolygonShape& b;
  const b2Transform& xf_b;

  TrianglePair(const b2PolygonShape& shape_a, const b2Transform& xfa, const b2PolygonShape& shape_b,
               const b2Transform& xfb)
      : a(shape_a), xf_a(xfa), b(shape_b), xf_b(xfb) {}
  float margin() const { return a.m_radius + b.m_radius; }  // the skins, as Box2D's
  b2Vec2 centroid_b() const { return b.m_centroid; }
  // The plug-in's solver answers under `setting` (else Box2D's function).
  static bool solver_on(const Setting& setting) { return setting.method.has_value(); }
  // The internal-edge rule is in force under `setting` (the method honours the masks).
  static bool rule(const Setting& setting) { return setting.internal_edges; }
  // The solver takes the shapes: validated at the first answer that asks (`validate`).
  bool accepted(ContactMemory& memory) const {
    if (memory.shapes == ContactMemory::Shapes::UnvalidatedTriangles) validate(memory);
    return memory.shapes == ContactMemory::Shapes::Triangles;
  }
  // `Triangles` or `InvalidTriangles` into `memory`, as `Triangle<float>` takes both or not.
  void validate(ContactMemory& memory) const;
  float face_separation(int face, const PairPose& pose) const {
    return detail::face_separation<3>(face, a, b, pose.b_in_a);
  }
  // What the empty manifold just answered proves of the gap beyond a manifold's reach: its
  // judged face's separation minus `face_reach` (metres; at most 0 when none).
  float gap(const Result<float>&, const PairPose& pose, const ContactMemory& memory) const {
    return memory.last_face < 0 ? 0
                                : face_separation(memory.last_face, pose) - face_reach(pose.margin);
  }
  static void take_masks(Query& q, const ContactMemory& memory) {
    q.internal_edges = memory.internal_edges;
  }
  static bool any_masks(const Query& q) { return q.internal_edges.any(); }
  b2Vec2 centroid_a() const { return a.m_centroid; }
  int count_a() const { return 3; }
  // Box2D's rules exclude no pair of polygons (see `EdgePair::excluded`), nor does a face of
  // another shape face B instead (see `EdgePair::faces_away`).
  static std::optional<float> excluded(const PairPose&) { return std::nullopt; }
  static bool faces_away(const PairPose&, ContactMemory&) { return false; }
  Result<float> solve(const Setting& setting, const Query& q, const PairPose& pose,
                      ContactMemory& memory) const;
  void write(b2Manifold* manifold, const Manifold<float>& m, const PairPose& pose) const;
  void box2d(b2Manifold* manifold) const { b2CollidePolygons(manifold, &a, xf_a, &b, xf_b); }
  // An evaluation kept or answered (`count`) or skipped (`count_skip`), on `to`.
  static void count(ThreadCounters& to, const Setting& setting, const ContactMemory&) {
    to.triangle_pairs[static_cast<int>(*setting.backend)].add();
  }
  static void count_skip(ThreadCounters& to, const Setting& setting, const ContactMemory&,
                         Skip reason) {
    to.skipped[static_cast<int>(*setting.backend)][static_cast<int>(reason)].add();
  }
};

// What the pairs beyond two triangles share: answered exactly (`dyop::collide`) under every
// backend but `Box2D` and `Config::triangles_only`, with the masks of each shape (`ShapeMasks`:
// A's in `ContactMemory::internal_edges`, B's in `masks_b`; a one-sided edge's are its ghost
// vertices', set by the first look at its shapes).
struct ExactPair {
  using Query = ConvexQuery<float>;
  // The reference face is the least overlap's, A's within rounding (`face_tie_per_radius`): the
  // manifold as the solver reads it is then the exact depth.
  static float hysteresis(const PairPose& pose) { return face_tie_per_radius * pose.radius_sum; }
  static bool solver_on(const Setting& setting) {
    return setting.backend != Backend::Box2D && !setting.config.triangles_only;
  }
  static bool rule(const Setting& setting) { return setting.config.internal_edges; }
  // The empty manifold's gap: the solver's (`Apart::Gap`) beyond a manifold's reach.
  static float gap(const Result<float>& r, const PairPose& pose, const ContactMemory&) {
    return r.status == Status::Separated ? r.separation - face_reach(pose.margin) : 0;
  }
  static void take_masks(Query& q, const ContactMemory& memory) {
    q.masks_a = {memory.internal_edges.edges, memory.internal_edges.closed_vertices};
    q.masks_b = memory.masks_b;
  }
  static bool any_masks(const Query& q) { return q.masks_a.any() || q.masks_b.any(); }
  static bool faces_away(const PairPose&, ContactMemory&) { return false; }
  // A skip's reason, counted beside the skipped evaluation (the family's `count`).
  static void count_skip_reason(ThreadCounters& to, Skip why) {
    to.other_skipped[static_cast<int>(why)].add();
  }
};

// What the polygon families beyond two triangles share: A is a polygon.
struct PolygonAPair : ExactPair {
  const b2PolygonShape& a;
  const b2Transform& xf_a;

  PolygonAPair(const b2PolygonShape& shape_a, const b2Transform& xfa) : a(shape_a), xf_a(xfa) {}
  b2Vec2 centroid_a() const { return a.m_centroid; }
  int count_a() const { return a.m_count; }
  static std::optional<float> excluded(const PairPose&) { return std::nullopt; }
};

// Two polygons, one of more than 3 vertices.
struct PolygonPair : PolygonAPair {
  const b2PolygonShape& b;
  const b2Transform& xf_b;

  PolygonPair(const b2PolygonShape& shape_a, const b2Transform& xfa, const b2PolygonShape& shape_b,
              const b2Transform& xfb)
      : PolygonAPair(shape_a, xfa), b(shape_b), xf_b(xfb) {}
  float margin() const { return a.m_radius + b.m_radius; }
  b2Vec2 centroid_b() const { return b.m_centroid; }
  static bool accepted(const ContactMemory& memory) {
    return memory.shapes == ContactMemory::Shapes::Polygons;
  }
  float face_separation(int face, const PairPose& pose) const {
    return detail::face_separation<0>(face, a, b, pose.b_in_a);
  }
  // Inline (below): the solver's answer then stays in registers (measured: docs/measurements.md,
  // "Everyday shapes").
  inline Result<float> solve(const Setting&, const Query& q, const PairPose& pose,
                             ContactMemory&) const;
  void write(b2Manifold* manifold, const Manifold<float>& m, const PairPose& pose) const;
  void box2d(b2Manifold* manifold) const { b2CollidePolygons(manifold, &a, xf_a, &b, xf_b); }
  static void count(ThreadCounters& to, const Setting& setting, const ContactMemory& memory) {
    to.polygon_pairs.add();
    if (solver_on(setting) && accepted(memory)) to.exact_pairs.add();
  }
};

// Writes the solver's manifold of shape A and circle `b` (`center`: the circle's centre in A's
// frame; `face_normal` and `face_point`: the normal of A's face the solver named, as A holds it,
// and a point of it) as Box2D's: on that face, its own normal and point; nearest a vertex, the
// normal from the vertex to the centre and a point of that plane; the point at the circle's centre,
// key 0.
inline void write_circle_manifold(b2Manifold* manifold, const Manifold<float>& mf,
                                  const b2Vec2& face_normal, const b2Vec2& face_point,
                                  const b2CircleShape& b, const b2Vec2& center) {
  manifold->pointCount = mf.point_count;
  if (mf.point_count == 0) return;
  const b2Vec2 normal(mf.normal.x(), mf.normal.y());
  manifold->type = b2Manifold::e_faceA;
  if (normal.x == face_normal.x && normal.y == face_normal.y) {
    manifold->localNormal = face_normal;
    manifold->localPoint = face_point;
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

// A polygon (fixture A) and a circle (fixture B), in Box2D's registry order; its manifolds are
// `e_faceA`, as Box2D's (see `write`).
struct PolygonCirclePair : PolygonAPair {
  const b2CircleShape& b;
  const b2Transform& xf_b;

  PolygonCirclePair(const b2PolygonShape& shape_a, const b2Transform& xfa,
                    const b2CircleShape& shape_b, const b2Transform& xfb)
      : PolygonAPair(shape_a, xfa), b(shape_b), xf_b(xfb) {}
  // The polygon's skin: `b2CollidePolygonAndCircle` keeps a point up to the two radii's sum.
  float margin() const { return a.m_radius; }
  b2Vec2 centroid_b() const { return b.m_p; }
  static bool accepted(const ContactMemory& memory) {
    return memory.shapes == ContactMemory::Shapes::PolygonAndCircle;
  }
  // The circle beyond the line of A's face `face`: apart at least that far.
  float face_separation(int face, const PairPose& pose) const {
    return b2Dot(a.m_normals[face], pose.centroid_b_in_a - a.m_vertices[face]) - b.m_radius;
  }
  // Inline (below), at both of the answer's calls: the solver's answer then stays in registers
  // (measured: docs/measurements.md, "Everyday shapes").
  [[gnu::always_inline]] inline Result<float> solve(const Setting&, const Query& q,
                                                    const PairPose& pose, ContactMemory&) const;
  // Inline: the answer's manifold then stays in registers (measured: docs/measurements.md,
  // "Everyday shapes").
  void write(b2Manifold* manifold, const Manifold<float>& m, const PairPose& pose) const {
    const int e1 = m.reference_edge;
    const int e2 = e1 + 1 < a.m_count ? e1 + 1 : 0;
    write_circle_manifold(manifold, m, a.m_normals[e1],
                          0.5f * (a.m_vertices[e1] + a.m_vertices[e2]), b, pose.centroid_b_in_a);
  }
  void box2d(b2Manifold* manifold) const {
    b2CollidePolygonAndCircle(manifold, &a, xf_a, &b, xf_b);
  }
  static void count(ThreadCounters& to, const Setting& setting, const ContactMemory& memory) {
    to.circle_pairs.add();
    if (solver_on(setting) && accepted(memory)) to.exact_pairs.add();
  }
};

// What the edge families share: A is an edge (a `b2EdgeShape`, or a chain's child edge made for
// the evaluation), read by the solver as a `Segment` (`EdgeSides`); answered exactly unless
// `Config::edges_and_chains` is off; Box2D's one-sided rules first (`excluded`).
struct EdgePair : ExactPair {
  const b2EdgeShape& a;
  const b2Transform& xf_a;

  // The ground's face stays the reference unless B's beats it by Box2D's own hysteresis, as on a
  // triangulated ground: a body resting over an edge's end, tilted a thousandth in its skins, would
  // otherwise take its own tilted face's normal there, and slide off a flat top when frictionless.
  static float hysteresis(const PairPose&) { return face_hysteresis; }

  EdgePair(const b2EdgeShape& edge, const b2Transform& xfa) : a(edge), xf_a(xfa) {}
  static bool solver_on(const Setting& setting) {
    return ExactPair::solver_on(setting) && setting.config.edges_and_chains;
  }
  b2Vec2 centroid_a() const { return 0.5f * (a.m_vertex1 + a.m_vertex2); }
  static constexpr int count_a() { return 2; }
  // Box2D's one-sided rule: a one-sided edge gives no contact to a B whose centroid (a circle's
  // centre) lies behind its line (`b2CollideEdgeAndPolygon`'s test, in the same arithmetic). Then
  // how far behind (metres, ≥ 0: B keeps no contact while it moves less); else nothing.
  std::optional<float> excluded(const PairPose& pose) const { return behind(pose); }
  std::optional<float> behind(const PairPose& pose) const {
    if (!a.m_oneSided) return std::nullopt;
    b2Vec2 along = a.m_vertex2 - a.m_vertex1;
    const b2Vec2 offset = pose.centroid_b_in_a - a.m_vertex1;
    // The side first, unnormalised: the same sign; the distance only when behind.
    if (!(b2Cross(offset, along) < 0.0f)) return std::nullopt;
    along.Normalize();
    const float distance = b2Dot(b2Vec2(along.y, -along.x), offset);
    return distance < 0.0f ? -distance : 0.0f;
  }
  // With a two-sided edge's ends known (`ContactMemory::edge_ends`): B changes sides, its masks
  // with it, once its centroid has gone around an end (to the other side of A's line, beyond that
  // end); true when it lies beyond a corner's other edge (`beyond_corner`), which faces it there.
  bool faces_away(const PairPose& pose, ContactMemory& memory) const {
    if (a.m_oneSided || memory.edge_ends.neighbours() == 0) return false;
    return turned_away(pose, memory);
  }
  bool turned_away(const PairPose& pose, ContactMemory& memory) const;
  // A's side `face`'s unit normal (0 the front, 1 the back), as the solver reads it.
  b2Vec2 side_normal(int face) const { return EdgeSides(a).normals[face]; }
  // The first vertex of A's side `face` (the front runs from `m_vertex1`, the back back to it).
  const b2Vec2& side_start(int face) const { return face == 0 ? a.m_vertex1 : a.m_vertex2; }
  // Writes the solver's manifold `mf` with A's side as the reference face: `e_faceA`, its normal
  // and its first end, B's points in B's frame (`b_in_a`: B's body frame given in A's); B's face:
  // `e_faceB`, that face's own normal and midpoint, the points on the edge in A's frame.
  void write_faces(b2Manifold* manifold, const Manifold<float>& mf, const b2PolygonShape* b,
                   const b2Transform& b_in_a) const;
  static void count(ThreadCounters& to, const Setting& setting, const ContactMemory& memory) {
    to.edge_pairs.add();
    if (solver_on(setting) && accepted_shapes(memory)) to.exact_pairs.add();
  }
  static bool accepted_shapes(const ContactMemory& memory) {
    using Shapes = ContactMemory::Shapes;
    return memory.shapes == Shapes::EdgeAndPolygon || memory.shapes == Shapes::EdgeBackAndPolygon ||
           memory.shapes == Shapes::EdgeAndCircle || memory.shapes == Shapes::EdgeBackAndCircle;
  }
  static bool accepted(const ContactMemory& memory) { return accepted_shapes(memory); }
};

// An edge (fixture A) and a polygon (B).
struct EdgePolygonPair : EdgePair {
  const b2PolygonShape& b;
  const b2Transform& xf_b;

  EdgePolygonPair(const b2EdgeShape& edge, const b2Transform& xfa, const b2PolygonShape& shape_b,
                  const b2Transform& xfb)
      : EdgePair(edge, xfa), b(shape_b), xf_b(xfb) {}
  float margin() const { return a.m_radius + b.m_radius; }
  b2Vec2 centroid_b() const { return b.m_centroid; }
  float face_separation(int face, const PairPose& pose) const;
  inline Result<float> solve(const Setting&, const Query& q, const PairPose& pose,
                             ContactMemory&) const;
  void write(b2Manifold* manifold, const Manifold<float>& m, const PairPose& pose) const {
    write_faces(manifold, m, &b, pose.b_in_a);
  }
  void box2d(b2Manifold* manifold) const { b2CollideEdgeAndPolygon(manifold, &a, xf_a, &b, xf_b); }
};

// An edge (fixture A) and a circle (B).
struct EdgeCirclePair : EdgePair {
  const b2CircleShape& b;
  const b2Transform& xf_b;

  EdgeCirclePair(const b2EdgeShape& edge, const b2Transform& xfa, const b2CircleShape& shape_b,
                 const b2Transform& xfb)
      : EdgePair(edge, xfa), b(shape_b), xf_b(xfb) {}
  // As Box2D's `b2CollideEdgeAndCircle`: a point up to both radii apart.
  float margin() const { return a.m_radius; }
  // Box2D's one-sided rules for a circle: behind the edge (`behind`), or its centre beyond an end
  // of a one-sided edge within the face region of the edge the chain goes on with there (that
  // edge's pair answers it: without this, a convex end would push the circle from its vertex
  // along a direction outside the outline's normals there). Nothing to keep for the latter.
  std::optional<float> excluded(const PairPose& pose) const;
  b2Vec2 centroid_b() const { return b.m_p; }
  float face_separation(int face, const PairPose& pose) const {
    return b2Dot(side_normal(face), pose.centroid_b_in_a - side_start(face)) - b.m_radius;
  }
  Result<float> solve(const Setting&, const Query& q, const PairPose& pose, ContactMemory&) const {
    const b2Vec2& center = pose.centroid_b_in_a;
    const EdgeSides sides(a);
    return solve_in_place(sides.in_place(pose.size_bound()),
                          Circle<float>{{center.x, center.y}, b.m_radius}, q);
  }
  void write(b2Manifold* manifold, const Manifold<float>& m, const PairPose& pose) const {
    write_circle_manifold(manifold, m, side_normal(m.reference_edge), a.m_vertex1, b,
                          pose.centroid_b_in_a);
  }
  void box2d(b2Manifold* manifold) const { b2CollideEdgeAndCircle(manifold, &a, xf_a, &b, xf_b); }
};

inline Result<float> PolygonPair::solve(const Setting&, const Query& q, const PairPose& pose,
                                        ContactMemory&) const {
  return solve_in_place(InPlace(a, pose.size_bound()), Placed(b, pose.b_in_a, pose.size_bound()),
                        q);
}

inline Result<float> EdgePolygonPair::solve(const Setting&, const Query& q, const PairPose& pose,
                                            ContactMemory&) const {
  const EdgeSides sides(a);
  return solve_in_place(sides.in_place(pose.size_bound()),
                        Placed(b, pose.b_in_a, pose.size_bound()), q);
}

inline Result<float> PolygonCirclePair::solve(const Setting&, const Query& q, const PairPose& pose,
                                              ContactMemory&) const {
  const b2Vec2& center = pose.centroid_b_in_a;
  return solve_in_place(InPlace(a, pose.size_bound()),
                        Circle<float>{{center.x, center.y}, b.m_radius}, q);
}

}  // namespace dyop::box2d::detail
