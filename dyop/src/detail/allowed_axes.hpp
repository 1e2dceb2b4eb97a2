#pragma once
// Internal: which of a pair's six axes may give its depth, normal and reference face when the
// caller marks edges internal or vertices closed (`Query::internal_edges`).
//
// Axis k is an edge normal of one triangle, realised at the other triangle's deepest vertex
// along it (first on ties, as `overlap_on_axis` picks it). It is allowed when its edge is not
// internal and its deepest vertex is not a closed vertex of the other body (there the outline's
// directions are other axes, of its own triangle's or of its neighbours' pairs). It is usable
// when, besides, the other triangle reaches the edge: a push along an edge's normal is a push
// back out through that edge.
//
// Used only for pairs not apart beyond the margin (`certify_axes` answers those plainly): no axis
// then separates the pair beyond the margin, whether usable or not.

#include <algorithm>
#include <array>

#include "detail/axis_overlap.hpp"
#include "detail/fill_result.hpp"
#include "dyop/result.hpp"

namespace dyop::detail {

template <class T>
struct AllowedAxes {
  std::array<T, 6> overlap;
  int least = 0;    // least overlap of all six (A's on ties): decides the status
  int best_a = -1;  // least usable axis of A's; -1: none
  int best_b = -1;  // least usable axis of B's; -1: none

  bool any() const { return best_a >= 0 || best_b >= 0; }
  // The least usable axis (A's on ties); `any()` must hold.
  int least_usable_axis() const {
    if (best_a < 0) return best_b;
    if (best_b < 0) return best_a;
    return overlap[best_b] < overlap[best_a] ? best_b : best_a;
  }
  // Box2D's reference face among the usable axes; `any()` must hold.
  AxisOverlap<T> reference(T hysteresis) const {
    const AxisOverlap<T> a{best_a, best_a >= 0 ? overlap[best_a] : T(0), 0};
    const AxisOverlap<T> b{best_b, best_b >= 0 ? overlap[best_b] : T(0), 0};
    if (best_a < 0) return b;
    if (best_b < 0) return a;
    return pick_reference(a, b, hysteresis);
  }
};

// True when axis k of `f` is allowed by `q`'s masks (caller's order, see `Query`).
// The deep vertex is looked for only when the other triangle has closed vertices at all.
template <class T>
bool axis_allowed(const PairFrame<T>& f, const Query<T>& q, int k) {
  const bool own_is_a = k < 3;
  const int edge_bit = own_is_a ? f.ta.input_edge(k) : 3 + f.tb.input_edge(k - 3);
  if ((q.internal_edges.edges >> edge_bit) & 1) return false;
  const int other_closed = own_is_a ? q.internal_edges.closed_vertices >> 3
                                   : q.internal_edges.closed_vertices & 7;
  if (other_closed == 0) return true;
  const int deep = overlap_on_axis(f, k).deep;
  const int vertex = own_is_a ? f.tb.input_vertex(deep) : f.ta.input_vertex(deep);
  return ((other_closed >> vertex) & 1) == 0;
}

// True when the other triangle touches axis k's edge, the segment, within `tol` (exact
// separating-axis test of a segment and a triangle: the segment's normal and the triangle's three
// normals). A push along the edge's normal is a push back out through that edge; an outline edge
// the other triangle does not reach (the bottom of a ground triangle whose apex a box touches) is
// no way out of the body, however allowed its direction.
template <class T>
bool edge_touched(const PairFrame<T>& f, int k, T tol) {
  const bool own_is_a = k < 3;
  const int i = own_is_a ? k : k - 3;
  const std::array<Vec2<T>, 3>& own = own_is_a ? f.a : f.b;
  const std::array<Vec2<T>, 3>& other = own_is_a ? f.b : f.a;
  const Triangle<T>& own_triangle = own_is_a ? f.ta : f.tb;
  const Triangle<T>& other_triangle = own_is_a ? f.tb : f.ta;
  const Vec2<T>& p = own[i];
  const Vec2<T>& q = own[next3(i)];
  const Vec2<T>& n = own_triangle.normal(i);
  const T outside = std::max({n.dot(other[0] - p), n.dot(other[1] - p), n.dot(other[2] - p)});
  if (outside < -tol) return false;  // the other triangle lies wholly inside the edge's line
  for (int j = 0; j < 3; ++j) {
    const Vec2<T>& m = other_triangle.normal(j);
    if (std::min(m.dot(p - other[j]), m.dot(q - other[j])) > tol) return false;
  }
  return true;
}

// One triangle's least usable axis (`first`: 0 for A's, 3 for B's), trying its axes from the
// least overlap up (first on ties, as `argmin3`), so that the usual pair checks one. `reached`:
// whether the other triangle reaches any of its edges (true when an axis is usable; exact when
// none is). The masks are read first: a pair is certified here because its least axis is refused,
// and whether the other triangle reaches a refused edge matters only when no allowed one is
// reached. Callgrind, Collide, against reaching every edge first: slide 96.0 M → 93.3 M and
// tiles 218.5 M → 214.7 M (full runs), the pyramid 38.2 M → 37.6 M (150 steps).
template <class T>
int least_usable(const PairFrame<T>& f, const Query<T>& q, const std::array<T, 6>& overlap,
                 int first, bool& reached) {
  // Sorted by hand (stable: ties keep index order): std::stable_sort's buffer for three indices
  // cost more than the rule's checks (callgrind, pyramid: 7 M instructions in new/delete).
  std::array<int, 3> order = {first, first + 1, first + 2};
  const auto before = [&](int x, int y) { return overlap[y] < overlap[x]; };  // y goes first
  if (before(order[0], order[1])) std::swap(order[0], order[1]);
  if (before(order[1], order[2])) std::swap(order[1], order[2]);
  if (before(order[0], order[1])) std::swap(order[0], order[1]);
  const T reach = q.margin + touching_band(f);  // the manifold's margin and the touching band
  std::array<bool, 3> refused{};
  for (int i = 0; i < 3; ++i) {
    refused[i] = !axis_allowed(f, q, order[i]);
    if (!refused[i] && edge_touched(f, order[i], reach)) {
      reached = true;
      return order[i];
    }
  }
  reached = false;
  for (int i = 0; i < 3 && !reached; ++i) {
    reached = refused[i] && edge_touched(f, order[i], reach);
  }
  return -1;
}

// One triangle's least axis allowed by the masks alone; -1: none.
template <class T>
int least_allowed_by_masks(const PairFrame<T>& f, const Query<T>& q,
                           const std::array<T, 6>& overlap, int first) {
  int best = -1;
  for (int k = first; k < first + 3; ++k) {
    if (axis_allowed(f, q, k) && (best < 0 || overlap[k] < overlap[best])) best = k;
  }
  return best;
}

template <class T>
AllowedAxes<T> allowed_axes(const PairFrame<T>& f, const Query<T>& q,
                            const std::array<T, 6>& overlap) {
  AllowedAxes<T> out;
  out.overlap = overlap;
  const int all_a = argmin3(overlap, 0);
  const int all_b = argmin3(overlap, 3);
  out.least = select_index(overlap[all_b] < overlap[all_a], all_b, all_a);
  bool reached_a = false;  // B reaches an edge of A
  bool reached_b = false;  // A reaches an edge of B
  out.best_a = least_usable(f, q, overlap, 0, reached_a);
  out.best_b = least_usable(f, q, overlap, 3, reached_b);
  if (reached_a && reached_b) return out;
  // One triangle reaches no edge of the other: the other holds it whole (a body sunk into a large
  // triangle). The masks alone then decide, so that it is pushed out through the outline.
  out.best_a = least_allowed_by_masks(f, q, overlap, 0);
  out.best_b = least_allowed_by_masks(f, q, overlap, 3);
  return out;
}

}  // namespace dyop::detail
