#pragma once
// Internal: which of a pair's six axes may give its depth, normal and reference face when the
// caller marks edges internal or vertices closed (`Query::internal_edges`).
//
// Axis k is an edge normal of one triangle, realised at the other triangle's deepest vertex
// along it. It is allowed when its edge is not internal and it is not realised inside the other
// body: at a closed vertex of the other triangle (there the outline's directions are other axes,
// of its own triangle's or of its neighbours' pairs) with no outline edge of it lying flat on the
// axis's face (`realised_inside`). It is usable when, besides, the other triangle reaches the
// edge: a push along an edge's normal is a push back out through that edge.
//
// Used only for pairs not apart beyond the margin (`certify_axes` answers those plainly): no axis
// then separates the pair beyond the margin, whether usable or not.

#include <algorithm>
#include <array>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "detail/axis_overlap.hpp"
#include "detail/fill_result.hpp"
#include "dyop/result.hpp"

namespace dyop::detail {

template <class T>
struct AllowedAxes {
  std::array<T, 6> overlap;
  int least = 0;        // least overlap of all six (A's on ties): decides the status
  int best_a = -1;      // least usable axis of A's; -1: none
  int best_b = -1;      // least usable axis of B's; -1: none
  unsigned usable = 0;  // bit k: axis k is usable

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

// Bits 0..2 of `bits` (a triangle's flags by the caller's edge or vertex index) in CCW order:
// bit i is the caller's flag of CCW edge or vertex i (`input_edge`, `input_vertex`; a clockwise
// input swaps edges 0 and 2, vertices 1 and 2). Looked up, not shifted bit by bit.
template <class T>
unsigned ccw_edge_bits(const Triangle<T>& t, unsigned bits) {
  static constexpr std::uint8_t kCcw[2][8] = {{0, 1, 2, 3, 4, 5, 6, 7}, {0, 4, 2, 6, 1, 5, 3, 7}};
  return kCcw[t.flipped()][bits & 7u];
}
template <class T>
unsigned ccw_vertex_bits(const Triangle<T>& t, unsigned bits) {
  static constexpr std::uint8_t kCcw[2][8] = {{0, 1, 2, 3, 4, 5, 6, 7}, {0, 1, 4, 5, 2, 3, 6, 7}};
  return kCcw[t.flipped()][bits & 7u];
}

// True when axis k of `f` is allowed by `q`'s masks (caller's order, see `Query`).
// The deep vertex is looked for only when the other triangle has closed vertices at all.
template <class T>
bool axis_allowed(const PairFrame<T>& f, const Query<T>& q, int k) {
  const bool own_is_a = k < 3;
  const int edge_bit = own_is_a ? f.ta.input_edge(k) : 3 + f.tb.input_edge(k - 3);
  if ((q.internal_edges.edges >> edge_bit) & 1) return false;
  const int other_closed =
      own_is_a ? q.internal_edges.closed_vertices >> 3 : q.internal_edges.closed_vertices & 7;
  if (other_closed == 0) return true;
  const unsigned other_internal =
      own_is_a ? (q.internal_edges.edges >> 3) & 7u : q.internal_edges.edges & 7u;
  const Triangle<T>& other = own_is_a ? f.tb : f.ta;
  const std::array<Vec2<T>, 3>& other_v = own_is_a ? f.b : f.a;
  const Vec2<T>& n = own_is_a ? f.ta.normal(k) : f.tb.normal(k - 3);
  const T d[3] = {n.dot(other_v[0]), n.dot(other_v[1]), n.dot(other_v[2])};
  return !realised_inside(d, other_v.data(), 3,
                          ccw_vertex_bits(other, static_cast<unsigned>(other_closed)),
                          ccw_edge_bits(other, other_internal));
}

// What one triangle's three edges say to the rule (bits 0..2, CCW).
struct EdgeBits {
  unsigned allowed = 0;        // edges the masks allow (`axis_allowed`)
  unsigned wholly_inside = 0;  // edges whose line holds the other triangle wholly inside
  unsigned cut_other = 0;      // the other triangle's edges both of whose ends lie beyond a line
};

// The rule's look at one triangle's edges (`own`, its local vertices `own_v`) against the other
// triangle's local vertices `other`: for edge e (outward normal n) and the other's vertex w,
// n·v_w − n·p_e is its signed distance from the edge's line, from the products `all_overlaps` and
// `overlap_on_axis` take; beyond ±`reach` it counts as outside or inside. `internal`: own edges
// marked internal; `other_closed` and `other_internal`: the other's closed vertices and internal
// edges (all CCW bits); an axis is refused when its edge is internal or it is realised inside the
// other body (`realised_inside`).
template <class T>
EdgeBits edge_bits(const Triangle<T>& own, const std::array<Vec2<T>, 3>& own_v,
                   const std::array<Vec2<T>, 3>& other, unsigned internal, unsigned other_closed,
                   unsigned other_internal, T reach) {
  EdgeBits out;
  unsigned beyond[3] = {0, 0, 0};  // bits e: the other's vertex w beyond edge e's line
  for (int e = 0; e < 3; ++e) {
    const Vec2<T>& n = own.normal(e);
    const T line = n.dot(own_v[e]);
    const T d[3] = {n.dot(other[0]), n.dot(other[1]), n.dot(other[2])};
    const unsigned refused =
        ((internal >> e) & 1u) |
        static_cast<unsigned>(realised_inside(d, other.data(), 3, other_closed, other_internal));
    out.allowed |= (refused ^ 1u) << e;
    unsigned inside = 0;
    for (int w = 0; w < 3; ++w) {
      inside += static_cast<unsigned>(d[w] - line < -reach);
      beyond[w] |= static_cast<unsigned>(d[w] - line > reach) << e;
    }
    out.wholly_inside |= static_cast<unsigned>(inside == 3) << e;
  }
  for (int j = 0; j < 3; ++j) {
    out.cut_other |= static_cast<unsigned>((beyond[j] & beyond[next3(j)]) != 0) << j;
  }
  return out;
}

#if defined(__SSE2__)
// The same for float, the three edges in the lanes of one SSE register: the same products,
// differences and comparisons, so the same bits (tested against the generic one).
inline EdgeBits edge_bits(const Triangle<float>& own, const std::array<Vec2<float>, 3>& own_v,
                          const std::array<Vec2<float>, 3>& other, unsigned internal,
                          unsigned other_closed, unsigned other_internal, float reach) {
  const LaneProducts products = lane_products(own, own_v, other);
  const __m128 line = products.line;
  const __m128* d = products.along;
  // As `realised_inside`, an own edge per lane: the deep vertex as `realised_inside` picks it
  // (d1 < d0 picks 1, then d2 below the lesser picks 2); a closed one refuses the lane unless an
  // outline edge of the other at it lies flat (the same rise and bound as `realised_inside`).
  const unsigned one = static_cast<unsigned>(_mm_movemask_ps(_mm_cmplt_ps(d[1], d[0]))) & 7u;
  const unsigned two =
      static_cast<unsigned>(_mm_movemask_ps(_mm_cmplt_ps(d[2], _mm_min_ps(d[1], d[0])))) & 7u;
  const unsigned deep_at[3] = {~(one | two) & 7u, one & ~two, two};
  unsigned realised_inside = 0;
  const float sine = dyop::detail::flat_face_sine<float>();
  for (int w = 0; w < 3; ++w) {
    if (((other_closed >> w) & 1u) == 0) continue;
    // The lanes where the edge from w to its next or its previous vertex is an outline edge
    // lying flat, seen from w.
    unsigned flat = 0;
    const int after = next3(w);
    const int before = next3(after);
    const int edges[2] = {w, before};
    const int ends[2] = {after, before};
    for (int side = 0; side < 2; ++side) {
      if (((other_internal >> edges[side]) & 1u) != 0) continue;
      const int end = ends[side];
      const float bound = sine * sine * (other[end] - other[w]).squaredNorm();
      const __m128 rise = _mm_sub_ps(d[end], d[w]);
      flat |= static_cast<unsigned>(
                  _mm_movemask_ps(_mm_cmple_ps(_mm_mul_ps(rise, rise), _mm_set1_ps(bound)))) &
              7u;
    }
    realised_inside |= deep_at[w] & ~flat;
  }
  EdgeBits out;
  out.allowed = ~(internal | realised_inside) & 7u;
  const __m128 out_reach = _mm_set1_ps(reach);
  const __m128 in_reach = _mm_set1_ps(-reach);
  __m128 inside = _mm_castsi128_ps(_mm_set1_epi32(-1));
  unsigned beyond[3];
  for (int w = 0; w < 3; ++w) {
    const __m128 s = _mm_sub_ps(d[w], line);
    inside = _mm_and_ps(inside, _mm_cmplt_ps(s, in_reach));
    beyond[w] = static_cast<unsigned>(_mm_movemask_ps(_mm_cmpgt_ps(s, out_reach))) & 7u;
  }
  out.wholly_inside = static_cast<unsigned>(_mm_movemask_ps(inside)) & 7u;
  for (int j = 0; j < 3; ++j) {
    out.cut_other |= static_cast<unsigned>((beyond[j] & beyond[next3(j)]) != 0) << j;
  }
  return out;
}
#endif

// The least of the axes `first`..`first + 2` whose bit is set in `axes` (first on ties); -1: none.
template <class T>
int least_of(const std::array<T, 6>& overlap, unsigned axes, int first) {
  int best = -1;
  for (int k = first; k < first + 3; ++k) {
    if (((axes >> k) & 1u) != 0 && (best < 0 || overlap[k] < overlap[best])) best = k;
  }
  return best;
}

// The axes the rule lets answer (see the file's head): allowed by the masks and touched; when
// one triangle reaches no edge of the other, the other holds it whole (a body sunk into a large
// triangle) and the masks alone decide, so that it is pushed out through the outline. An edge is
// touched within `reach` (exact separating-axis test of the segment and the other triangle)
// unless the other triangle lies wholly inside its line, or both its ends lie beyond one line of
// the other triangle: a push along an edge's normal is a push back out through that edge, and an
// outline edge the other triangle does not reach (the bottom of a ground triangle whose apex a
// box touches) is no way out of the body, however allowed its direction.
template <class T>
AllowedAxes<T> allowed_axes(const PairFrame<T>& f, const Query<T>& q,
                            const std::array<T, 6>& overlap) {
  AllowedAxes<T> out;
  out.overlap = overlap;
  const int all_a = argmin3(overlap, 0);
  const int all_b = argmin3(overlap, 3);
  out.least = select_index(overlap[all_b] < overlap[all_a], all_b, all_a);
  const T reach = q.margin + touching_band(f);  // the manifold's margin and the touching band
  const InternalEdges& m = q.internal_edges;
  const unsigned edges_a = ccw_edge_bits(f.ta, m.edges & 7u);
  const unsigned edges_b = ccw_edge_bits(f.tb, (m.edges >> 3) & 7u);
  const EdgeBits a =
      edge_bits(f.ta, f.a, f.b, edges_a, ccw_vertex_bits(f.tb, (m.closed_vertices >> 3) & 7u),
                edges_b, reach);
  const EdgeBits b = edge_bits(f.tb, f.b, f.a, edges_b,
                               ccw_vertex_bits(f.ta, m.closed_vertices & 7u), edges_a, reach);
  const unsigned touched_a = ~(a.wholly_inside | b.cut_other) & 7u;
  const unsigned touched_b = ~(b.wholly_inside | a.cut_other) & 7u;
  const unsigned allowed = a.allowed | b.allowed << 3;
  const unsigned usable =
      touched_a != 0 && touched_b != 0 ? allowed & (touched_a | touched_b << 3) : allowed;
  out.usable = usable;
  out.best_a = least_of(overlap, usable, 0);
  out.best_b = least_of(overlap, usable, 3);
  return out;
}

}  // namespace dyop::detail
