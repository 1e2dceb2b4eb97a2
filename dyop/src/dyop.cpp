// DyOP-PD (the paper "Primitives penetration depth computation using Dynamic Pivot Point
// technique", reconstructed and corrected: docs/paper.md, dyop/dyop.hpp).
//
// `dyop`, exact:
//   1. Put the pair in A's local frame (PairFrame: A's first vertex subtracted).
//   2. Overlap along the six candidate axes (A's edge normals, B's negated), branch-free; the
//      least is the depth and its axis the normal (certify_axes, shared with `sat`).
//   3. Apart: the pivot (centre of the intersection box of the two AABBs, the gap's centre when
//      they are apart) names a vertex of each triangle and an edge of the other; their distance
//      stands when the gap along its direction equals it (duality: the distance is at least the
//      gap along any unit axis), else all vertex–edge pairs decide.
//   Invariant: touching and penetrating answers equal `sat`'s bit for bit; apart, the distance is
//   exact within the touching band.
// `dyop_fast`, the heuristic alone: the pivot's vertex of one triangle against the pivot's edge
// line of the other (normal form n·x = c, unit n), both ways; penetrating when a pivot vertex is
// strictly inside the other triangle (orientation signs, not area sums). No certification: it can
// miss a penetration or overstate its depth (measured in tests/dyop/method_accuracy_test.cpp).

#include "dyop/dyop.hpp"

#include "detail/certify_axes.hpp"
#include "detail/pivot.hpp"

#include <algorithm>
#include <limits>

namespace dyop {

namespace {

// The pivot's own answer to "which features are closest" for a pair found apart: A's vertex
// nearest the pivot against B's edge nearest it, and the other way round. The guess is certified
// by duality: the distance is at least the gap along any unit axis, so when the gap along the
// candidate's direction equals its length the candidate is the distance. Otherwise, the full
// search decides.
template <class T>
struct PivotFeatures {
  detail::Closest<T> operator()(const detail::PairFrame<T>& f) const {
    const Vec2<T> pivot = detail::pivot_point(f);
    const int edge_a = detail::nearest_edge(f.ta, f.a, pivot);
    const int edge_b = detail::nearest_edge(f.tb, f.b, pivot);
    detail::Closest<T> c;
    T sq = std::numeric_limits<T>::infinity();
    detail::consider_a_vertex(f, detail::nearest_vertex(f.a, pivot), edge_b, c, sq);
    detail::consider_b_vertex(f, detail::nearest_vertex(f.b, pivot), edge_a, c, sq);
    detail::finish_closest(c, sq);
    const Vec2<T>& u = c.normal;
    const T gap = std::min({u.dot(f.b[0]), u.dot(f.b[1]), u.dot(f.b[2])}) -
                  std::max({u.dot(f.a[0]), u.dot(f.a[1]), u.dot(f.a[2])});
    if (gap >= c.distance - detail::touching_band(f)) return c;
    return detail::closest_features(f);
  }
};

// True when `p` is strictly inside triangle `t` (local vertices `verts`): orientation signs
// against every edge, never the paper's comparison of area sums. All three are computed (no early
// exit): on real inputs the outcome of each test is unpredictable.
template <class T>
bool strictly_inside(const Triangle<T>& t, const std::array<Vec2<T>, 3>& verts, const Vec2<T>& p) {
  return std::max({t.normal(0).dot(p - verts[0]), t.normal(1).dot(p - verts[1]),
                   t.normal(2).dot(p - verts[2])}) < 0;
}

}  // namespace

template <class T>
Result<T> dyop(const Triangle<T>& a, const Triangle<T>& b, const Query<T>& query) {
  // No pivot-first early exit at the Overlap level: measured slower than all six axes (dyop.hpp).
  return detail::certify_axes(detail::PairFrame<T>(a, b), query, PivotFeatures<T>{});
}

template <class T>
Result<T> dyop_fast(const Triangle<T>& a, const Triangle<T>& b, const Query<T>& query) {
  const detail::PairFrame<T> f(a, b);
  const Vec2<T> pivot = detail::pivot_point(f);

  // One direction each way: the pivot's vertex of one triangle against the pivot's edge of the
  // other, as a signed distance from the edge line in normal form (negative: inside the line).
  detail::AxisOverlap<T> a_into_b;
  const int edge_b = detail::nearest_edge(b, f.b, pivot);
  a_into_b.axis = 3 + edge_b;
  a_into_b.deep = detail::nearest_vertex(f.a, pivot);
  a_into_b.overlap = -b.normal(edge_b).dot(f.a[a_into_b.deep] - f.b[edge_b]);
  const bool a_inside = strictly_inside(b, f.b, f.a[a_into_b.deep]);

  detail::AxisOverlap<T> b_into_a;
  const int edge_a = detail::nearest_edge(a, f.a, pivot);
  b_into_a.axis = edge_a;
  b_into_a.deep = detail::nearest_vertex(f.b, pivot);
  b_into_a.overlap = -a.normal(edge_a).dot(f.b[b_into_a.deep] - f.a[edge_a]);
  const bool b_inside = strictly_inside(a, f.a, f.b[b_into_a.deep]);

  return detail::answer_from_axis(f, query,
                                  detail::choose_direction(a_into_b, a_inside, b_into_a, b_inside));
}

template Result<float> dyop(const Triangle<float>&, const Triangle<float>&, const Query<float>&);
template Result<double> dyop(const Triangle<double>&, const Triangle<double>&,
                             const Query<double>&);
template Result<float> dyop_fast(const Triangle<float>&, const Triangle<float>&,
                                 const Query<float>&);
template Result<double> dyop_fast(const Triangle<double>&, const Triangle<double>&,
                                  const Query<double>&);

}  // namespace dyop
