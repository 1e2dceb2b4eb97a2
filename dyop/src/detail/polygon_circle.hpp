#pragma once
// Internal: the exact answer for a convex polygon and a circle (`dyop::collide`, see
// dyop/convex_pair.hpp), on any polygon-like type: the one implementation, shared by `collide` and
// the Box2D plug-in, which calls it in place on a `b2PolygonShape` (no `Polygon` built).

#include <algorithm>
#include <array>
#include <cmath>

#include "detail/axis_overlap.hpp"
#include "detail/fill_result.hpp"
#include "dyop/convex_pair.hpp"

namespace dyop::detail {

// Up to 8 vertices of one shape, in a pair's local frame.
template <class T>
using Local = std::array<Vec2<T>, max_polygon_vertices>;

// A polygon's vertices in the frame centred on its vertex 0, each placed when read (most are read
// once or twice: no copy of them all).
template <class T, class P>
struct Shifted {
  const P& p;
  Vec2<T> origin;
  Vec2<T> operator[](int i) const { return p.vertex(i) - origin; }
};

// The point of segment p→q nearest x, and which feature of the segment holds it.
template <class T>
Vec2<T> nearest_on_segment(const Vec2<T>& p, const Vec2<T>& q, const Vec2<T>& x,
                           Feature::Type& type, int& end) {
  const Vec2<T> d = q - p;
  const T t = d.dot(x - p);
  const T dd = d.squaredNorm();
  type = Feature::Type::Vertex;
  if (t <= 0) {
    end = 0;
    return p;
  }
  if (t >= dd) {
    end = 1;
    return q;
  }
  type = Feature::Type::Edge;
  end = 0;
  return p + (t / dd) * d;
}

// Where a circle's centre lies against a polygon (local frame): the polygon's boundary point
// nearest it, the feature holding that point, and the centre's signed distance (negative inside).
template <class T>
struct CenterPlace {
  int best_face = 0;  // CCW face the centre lies farthest beyond (first on ties)
  Feature::Type type = Feature::Type::Edge;
  int index = 0;                      // CCW face or vertex of the nearest point
  Vec2<T> nearest = Vec2<T>::Zero();  // on the polygon's boundary
  Vec2<T> normal = Vec2<T>::Zero();   // unit, from the polygon out toward the centre
  T signed_distance = 0;
};

// The nearest point lies on the face the centre lies farthest beyond (for a strictly convex
// polygon and a centre outside it: were it a vertex of another face, one of that vertex's two
// faces would lie farther, its normal being nearer the direction from the vertex to the centre),
// so that face alone is searched, as `b2CollidePolygonAndCircle` does.
template <class T, class P>
[[gnu::always_inline]] inline CenterPlace<T> place_center(const P& p, const Shifted<T, P>& v,
                                                          const Vec2<T>& c) {
  CenterPlace<T> out;
  T farthest = p.normal(0).dot(c - v[0]);
  for (int e = 1; e < p.count(); ++e) {
    const T s = p.normal(e).dot(c - v[e]);
    out.best_face = detail::select_index(s > farthest, e, out.best_face);
    farthest = std::max(farthest, s);
  }
  const int e = out.best_face;
  out.index = e;
  out.normal = p.normal(e);
  out.signed_distance = farthest;
  out.nearest = c - farthest * out.normal;
  // Inside: the nearest face line. A segment (two vertices) has no inside: its nearest point is on
  // it whichever side the centre lies on, also on its line.
  if (farthest <= 0 && p.count() > 2) return out;
  Feature::Type type;
  int end;
  const Vec2<T> on = nearest_on_segment(v[e], v[p.next(e)], c, type, end);
  if (type == Feature::Type::Edge) return out;  // the face's interior: its normal, its distance
  const T sq = (c - on).squaredNorm();
  // A centre on the vertex itself (its face's line rounded it outside, or its square underflows)
  // has no direction of its own: it is answered on the face, as a centre a hair inside would be,
  // so that the internal-edge rule judges that face.
  if (!(sq > 0)) {
    out.nearest = on;
    out.signed_distance = 0;
    return out;
  }
  out.type = type;
  out.nearest = on;
  out.index = end ? p.next(e) : e;
  out.signed_distance = std::sqrt(sq);
  out.normal = (c - on) / out.signed_distance;
  return out;
}

// The distance from `c` to the polygon's edge `e` as a segment (local frame).
template <class T, class P>
T segment_distance(const P& p, const Shifted<T, P>& v, int e, const Vec2<T>& c) {
  Feature::Type type;
  int end;
  return (c - nearest_on_segment(v[e], v[p.next(e)], c, type, end)).norm();
}

// `collide` for polygon `pa` and `circle`: `pa` a `Polygon<T>` or a `Segment<T>`, or any type with
// its members
// `count`, `vertex`, `normal`, `next`, `size`, `input_edge` and `input_vertex` (the Box2D plug-in
// reads a `b2PolygonShape` in place). `size` is read once, whatever the status (measured:
// docs/measurements.md, "The touching band measured where it matters"). Inline, so that a caller
// which reads a few fields of the answer has them from registers, not from a `Result` written to
// memory and read back.
template <class T, class P>
[[gnu::always_inline]] inline Result<T> collide_polygon_circle(const P& pa, const Circle<T>& circle,
                                                               const ConvexQuery<T>& q) {
  const Vec2<T> origin = pa.vertex(0);
  const Shifted<T, P> v{pa, origin};
  const Vec2<T> c = circle.center - origin;
  const T radius = circle.radius;
  const T band = touching_tolerance<T>() * std::max(pa.size(), radius);

  const CenterPlace<T> plain = place_center(pa, v, c);
  const T plain_separation = plain.signed_distance - radius;
  // The rule: a push along an internal edge's normal or from a closed vertex is replaced by the
  // least push along an allowed face the circle reaches; none: no contact from this pair.
  CenterPlace<T> ruled;  // the rule's face, where it replaces the plain answer
  const CenterPlace<T>* at = &plain;
  bool no_usable_axis = false;
  const ShapeMasks& m = q.masks_a;
  const bool refused = plain.type == Feature::Type::Edge
                           ? ((m.edges >> pa.input_edge(plain.index)) & 1) != 0
                           : ((m.closed_vertices >> pa.input_vertex(plain.index)) & 1) != 0;
  if (refused && plain_separation <= q.margin) {
    int best = -1;
    for (int e = 0; e < pa.count(); ++e) {
      if (((m.edges >> pa.input_edge(e)) & 1) != 0) continue;
      if (segment_distance(pa, v, e, c) > radius + q.margin + band) continue;
      const T s = pa.normal(e).dot(c - v[e]);
      if (best < 0 || s > ruled.signed_distance) {
        best = e;
        ruled.signed_distance = s;
      }
    }
    no_usable_axis = best < 0;
    if (best >= 0) {
      ruled.type = Feature::Type::Edge;
      ruled.index = best;
      ruled.best_face = best;
      ruled.normal = pa.normal(best);
      ruled.nearest = c - ruled.signed_distance * ruled.normal;
      at = &ruled;
    }
  }

  Result<T> r;
  r.status = status_of_overlap(-plain_separation, band);
  // The status and a pair apart are the plain answer's; a touching or penetrating one is pushed
  // along the rule's face.
  const CenterPlace<T>& answer = r.status == Status::Separated ? plain : *at;
  if (q.level == Level::Overlap) return r;
  r.separation = answer.signed_distance - radius;
  r.depth = std::max(T(0), -r.separation);
  r.normal = answer.normal;
  if (q.level == Level::Contact || (q.level == Level::Manifold && q.witnesses)) {
    r.witness_a = answer.nearest + origin;
    r.witness_b = c - radius * answer.normal + origin;
    const int index = answer.type == Feature::Type::Edge ? pa.input_edge(answer.index)
                                                         : pa.input_vertex(answer.index);
    r.feature_a = {answer.type, static_cast<std::uint8_t>(index)};
    r.feature_b = {Feature::Type::Vertex, 0};
  }
  if (q.level != Level::Manifold) return r;
  Manifold<T>& mf = r.manifold;
  mf.reference_is_a = true;
  mf.reference_edge = static_cast<std::uint8_t>(pa.input_edge(at->best_face));
  mf.normal = at->normal;
  const T separation = at->signed_distance - radius;
  if (no_usable_axis || separation > q.margin) return r;
  ManifoldPoint<T>& point = mf.points[0];
  point.point = c - radius * at->normal + origin;
  point.separation = separation;
  point.key = 0;
  mf.point_count = 1;
  return r;
}

}  // namespace dyop::detail
