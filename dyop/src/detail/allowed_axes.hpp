#pragma once
// Internal: which of a pair's six axes may give its depth, normal and reference face when the
// caller marks edges internal or vertices flat (`Query::inactive_edges`, `flat_vertices`).
//
// Axis k is an edge normal of one triangle, realised at the other triangle's deepest vertex
// along it (first on ties, as `overlap_on_axis` picks it). It is allowed when its edge is not
// internal and its deepest vertex is not a flat vertex of the other body: at a flat vertex the
// outline's only direction is the normal of that body's own edge there, which is an axis of its
// own.

#include <array>

#include "detail/axis_overlap.hpp"
#include "dyop/result.hpp"

namespace dyop::detail {

template <class T>
struct AllowedAxes {
  std::array<T, 6> overlap;
  int least = 0;           // least overlap of all six (A's on ties): decides the status
  int least_blocked = -1;  // least overlap among the axes not allowed; -1: every axis allowed
  int best_a = -1;         // least allowed axis of A's; -1: none
  int best_b = -1;         // least allowed axis of B's; -1: none

  bool any() const { return best_a >= 0 || best_b >= 0; }
  // The least allowed axis (A's on ties); `any()` must hold.
  int least_allowed() const {
    if (best_a < 0) return best_b;
    if (best_b < 0) return best_a;
    return overlap[best_b] < overlap[best_a] ? best_b : best_a;
  }
  // Box2D's reference face among the allowed axes; `any()` must hold.
  AxisOverlap<T> reference(T hysteresis) const {
    const AxisOverlap<T> a{best_a, best_a >= 0 ? overlap[best_a] : T(0), 0};
    const AxisOverlap<T> b{best_b, best_b >= 0 ? overlap[best_b] : T(0), 0};
    if (best_a < 0) return b;
    if (best_b < 0) return a;
    return pick_reference(a, b, hysteresis);
  }
};

// True when axis k of `f` is allowed by `q`'s masks (caller's order, see `Query`).
template <class T>
bool axis_allowed(const PairFrame<T>& f, const Query<T>& q, int k) {
  const int deep = overlap_on_axis(f, k).deep;
  const bool own_is_a = k < 3;
  const int edge_bit = own_is_a ? f.ta.input_edge(k) : 3 + f.tb.input_edge(k - 3);
  const int vertex_bit = own_is_a ? 3 + f.tb.input_vertex(deep) : f.ta.input_vertex(deep);
  return ((q.inactive_edges >> edge_bit) & 1) == 0 && ((q.flat_vertices >> vertex_bit) & 1) == 0;
}

template <class T>
AllowedAxes<T> allowed_axes(const PairFrame<T>& f, const Query<T>& q,
                            const std::array<T, 6>& overlap) {
  AllowedAxes<T> out;
  out.overlap = overlap;
  const int all_a = argmin3(overlap, 0);
  const int all_b = argmin3(overlap, 3);
  out.least = overlap[all_b] < overlap[all_a] ? all_b : all_a;
  for (int k = 0; k < 6; ++k) {
    int& best = axis_allowed(f, q, k) ? (k < 3 ? out.best_a : out.best_b) : out.least_blocked;
    if (best < 0 || overlap[k] < overlap[best]) best = k;
  }
  return out;
}

}  // namespace dyop::detail
