#pragma once
// Internal: the Dynamic Pivot Point and the features nearest to it (DyOP-PD's selection step).
//
// The pivot is the centre of the intersection box of the two AABBs: per axis the midpoint of
// [max(minA, minB), min(maxA, maxB)], which is the centre of the gap when the boxes are apart.

#include "detail/axis_overlap.hpp"
#include "detail/closest_features.hpp"

namespace dyop::detail {

template <class T>
Vec2<T> pivot_point(const PairFrame<T>& f) {
  Vec2<T> lo_a = f.a[0].cwiseMin(f.a[1]).cwiseMin(f.a[2]);
  Vec2<T> hi_a = f.a[0].cwiseMax(f.a[1]).cwiseMax(f.a[2]);
  Vec2<T> lo_b = f.b[0].cwiseMin(f.b[1]).cwiseMin(f.b[2]);
  Vec2<T> hi_b = f.b[0].cwiseMax(f.b[1]).cwiseMax(f.b[2]);
  return T(0.5) * (lo_a.cwiseMax(lo_b) + hi_a.cwiseMin(hi_b));
}

// CCW index of the vertex of `verts` nearest to `p`.
template <class T>
int nearest_vertex(const std::array<Vec2<T>, 3>& verts, const Vec2<T>& p) {
  T least;
  int index;
  min3((verts[0] - p).squaredNorm(), (verts[1] - p).squaredNorm(), (verts[2] - p).squaredNorm(),
       least, index);
  return index;
}

// CCW index of the edge of triangle `t` (local vertices `verts`) nearest to `p`: the squared
// distance to each segment, clamped along the stored unit tangent without branches.
template <class T>
int nearest_edge(const Triangle<T>& t, const std::array<Vec2<T>, 3>& verts, const Vec2<T>& p) {
  T d[3];
  for (int j = 0; j < 3; ++j) {
    const Vec2<T> w = p - verts[j];
    const Vec2<T> u = t.tangent(j);
    const T along = std::min(std::max(u.dot(w), T(0)), t.edge_length(j));
    d[j] = (w - along * u).squaredNorm();
  }
  T least;
  int index;
  min3(d[0], d[1], d[2], least, index);
  return index;
}

// The pivot heuristic's verdict from its two directions (vertex of one against edge of the other;
// `overlap` > 0 when the vertex is on the inner side of the edge line). A direction whose vertex is
// inside the other triangle penetrates; of two, the shallower wins. When none does, the pair is
// called apart by the larger signed distance, or touching (overlap 0) when that is not positive.
template <class T>
AxisOverlap<T> choose_direction(const AxisOverlap<T>& a_into_b, bool a_inside,
                                const AxisOverlap<T>& b_into_a, bool b_inside) {
  if (a_inside || b_inside) {
    return !b_inside || (a_inside && a_into_b.overlap <= b_into_a.overlap) ? a_into_b : b_into_a;
  }
  AxisOverlap<T> chosen = a_into_b.overlap <= b_into_a.overlap ? a_into_b : b_into_a;
  if (chosen.overlap > 0) chosen.overlap = 0;
  return chosen;
}

}  // namespace dyop::detail
