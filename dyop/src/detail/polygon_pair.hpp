#pragma once
// Internal: the exact answer for two convex polygons (`dyop::collide`, see dyop/convex_pair.hpp),
// on any polygon-like types: the one implementation, shared by `collide` and the Box2D plug-in,
// which calls it on its `b2PolygonShape`s in place (A as its shape holds it, B placed in A's body
// frame as the frame reads it: no `Polygon` built).
//
// A polygon-like type (`Polygon<T>`, `Segment<T>`: a polygon of two vertices, one edge per side)
// has a `Polygon<T>`'s members `count`, `vertex`, `normal`, `next`, `size`, `input_vertex` and
// `input_edge`; `vertex(i)` and `normal(i)` are read once each (into the frame), so they may
// compute the vertex or normal on each call. `size` is read only where the touching band needs it
// when the type also has `size_bound` (see `size_bound`), so it may measure.

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "detail/axis_overlap.hpp"
#include "detail/clip_manifold.hpp"
#include "detail/fill_result.hpp"
#include "detail/polygon_circle.hpp"
#include "detail/validated_size.hpp"
#include "dyop/convex_pair.hpp"

namespace dyop::detail::polygon_pair {

// The two polygons in a frame centred on A's first CCW vertex (as `detail::PairFrame` does for
// triangles): accuracy relative to the pair's size, not to its distance from the origin. Axis k:
// 0..count(A)−1 are A's edge normals, then B's negated ones, so that every axis points from A
// to B.
template <class T, class PA, class PB>
struct Frame {
  using Scalar = T;
  const PA& pa;
  const PB& pb;
  Vec2<T> origin;
  Local<T> v[2];  // A's vertices (v[0]) and B's, local, read once from the shapes
  Local<T> n[2];  // their edges' unit outward normals, read once from the shapes
  int counts[2];  // A's vertex count, B's
  T scale_bound;  // at least `scale()`, free to read (`size_bound`)

  [[gnu::always_inline]] Frame(const PA& pa_, const PB& pb_)
      : pa(pa_),
        pb(pb_),
        origin(pa_.vertex(0)),
        counts{pa_.count(), pb_.count()},
        scale_bound(std::max(size_bound(pa_), size_bound(pb_))) {
    for (int i = 0; i < counts[0]; ++i) {
      v[0][i] = pa.vertex(i) - origin;
      n[0][i] = pa.normal(i);
    }
    for (int j = 0; j < counts[1]; ++j) {
      v[1][j] = pb.vertex(j) - origin;
      n[1][j] = pb.normal(j);
    }
  }
  // The larger polygon's size: the unit of relative tolerances.
  T scale() const { return std::max(pa.size(), pb.size()); }
  // The index of A's arrays (0) or B's (1).
  static int side(bool own_a) { return static_cast<int>(!own_a); }
  int axes() const { return counts[0] + counts[1]; }
  bool of_a(int k) const { return k < counts[0]; }
  int edge(int k) const { return of_a(k) ? k : k - counts[0]; }
  Vec2<T> axis(int k) const { return of_a(k) ? n[0][k] : Vec2<T>(-n[1][k - counts[0]]); }
  // Edge e's unit outward normal of A (`own_a`) or B.
  const Vec2<T>& normal(bool own_a, int e) const { return n[side(own_a)][e]; }
  const Local<T>& vertices(bool own_a) const { return v[side(own_a)]; }
  int count(bool own_a) const { return counts[side(own_a)]; }
  int next(bool own_a, int i) const { return i + 1 < count(own_a) ? i + 1 : 0; }
  int input_vertex(bool own_a, int i) const {
    return own_a ? pa.input_vertex(i) : pb.input_vertex(i);
  }
  int input_edge(bool own_a, int e) const { return own_a ? pa.input_edge(e) : pb.input_edge(e); }
};

// The least of `n·v[i]` over `count` vertices, and the first vertex that realises it. Selected,
// not branched on: which vertex is deepest does not predict (as `detail::min3` for triangles).
template <class T>
T least_along(const Vec2<T>& n, const Local<T>& v, int count, int& deep) {
  T least = n.dot(v[0]);
  deep = 0;
  for (int i = 1; i < count; ++i) {
    const T d = n.dot(v[i]);
    const bool less = d < least;
    least = std::min(least, d);
    deep = detail::select_index(less, i, deep);
  }
  return least;
}

// The least of `n·v[i]` over `count` vertices, without the vertex.
template <class T>
T least_value(const Vec2<T>& n, const Local<T>& v, int count) {
  T least = n.dot(v[0]);
  for (int i = 1; i < count; ++i) least = std::min(least, n.dot(v[i]));
  return least;
}

// Axis k's overlap with the other shape's deepest vertex (first on ties): what the Contact level
// and the rule's closed vertices read.
template <class F>
AxisOverlap<typename F::Scalar> overlap_on_axis(const F& f, int k) {
  const bool own_a = f.of_a(k);
  const int e = f.edge(k);
  const auto n = f.normal(own_a, e);
  AxisOverlap<typename F::Scalar> o;
  o.axis = k;
  o.overlap =
      n.dot(f.vertices(own_a)[e]) - least_along(n, f.vertices(!own_a), f.count(!own_a), o.deep);
  return o;
}

// Every axis's overlap (`AxisOverlap`: max over the face's shape minus min over the other's along
// the face normal; negative: apart along it). The deepest vertices are left out (`deep` 0): most
// pairs need them for one axis at most (`overlap_on_axis`).
template <class T>
struct Overlaps {
  std::array<T, 2 * max_polygon_vertices> overlap{};  // by axis
  int best_a = 0;                                     // least of A's axes (first on ties)
  int best_b = 0;                                     // least of B's axes (first on ties)
  int least = 0;  // least of all (A's on ties): decides the status

  template <class F>
  explicit Overlaps(const F& f) {
    const int na = f.counts[0];
    for (int e = 0; e < na; ++e) {
      overlap[e] = f.n[0][e].dot(f.v[0][e]) - least_value(f.n[0][e], f.v[1], f.counts[1]);
    }
    for (int e = 0; e < f.counts[1]; ++e) {
      overlap[na + e] = f.n[1][e].dot(f.v[1][e]) - least_value(f.n[1][e], f.v[0], na);
    }
    best_a = least_of(0, na);
    best_b = least_of(na, f.axes());
    least = overlap[best_b] < overlap[best_a] ? best_b : best_a;
  }
  // Axis k's overlap, without its deepest vertex (`deep` 0).
  AxisOverlap<T> at(int k) const { return {k, overlap[k], 0}; }
  // The least of axes [from, to), to > from (first on ties).
  int least_of(int from, int to) const {
    int best = from;
    T least = overlap[from];
    for (int k = from + 1; k < to; ++k) {
      best = detail::select_index(overlap[k] < least, k, best);
      least = std::min(least, overlap[k]);
    }
    return best;
  }
  // The least of axes [from, to) whose bit is set in `mask` (first on ties); −1: none.
  int least_in(int from, int to, unsigned mask) const {
    int best = -1;
    T least = 0;
    for (int k = from; k < to; ++k) {
      const bool take = ((mask >> k) & 1u) != 0 && (best < 0 || overlap[k] < least);
      least = take ? overlap[k] : least;
      best = detail::select_index(take, k, best);
    }
    return best;
  }
};

// The closest features of a pair apart: the least vertex–segment distance over both directions.
template <class T>
struct Closest {
  T distance = 0;
  Vec2<T> on_a = Vec2<T>::Zero();  // local
  Vec2<T> on_b = Vec2<T>::Zero();  // local
  Feature feature_a;
  Feature feature_b;
};

template <class F>
Closest<typename F::Scalar> closest_features(const F& f) {
  using T = typename F::Scalar;
  Closest<T> best;
  T best_sq = -1;
  // Vertices of `points` (shape `pp`) against the segments of `segments` (shape `ps`).
  const auto search = [&](const auto& pp, const Local<T>& points, const auto& ps,
                          const Local<T>& segments, bool points_of_a) {
    for (int i = 0; i < pp.count(); ++i) {
      for (int j = 0; j < ps.count(); ++j) {
        Feature::Type type;
        int end;
        const Vec2<T> on =
            detail::nearest_on_segment(segments[j], segments[ps.next(j)], points[i], type, end);
        const T sq = (points[i] - on).squaredNorm();
        if (best_sq >= 0 && !(sq < best_sq)) continue;
        best_sq = sq;
        const Feature at_point{Feature::Type::Vertex,
                               static_cast<std::uint8_t>(pp.input_vertex(i))};
        const int index =
            type == Feature::Type::Edge ? ps.input_edge(j) : ps.input_vertex(end ? ps.next(j) : j);
        const Feature at_segment{type, static_cast<std::uint8_t>(index)};
        best.on_a = points_of_a ? points[i] : on;
        best.on_b = points_of_a ? on : points[i];
        best.feature_a = points_of_a ? at_point : at_segment;
        best.feature_b = points_of_a ? at_segment : at_point;
      }
    }
  };
  search(f.pa, f.v[0], f.pb, f.v[1], true);
  search(f.pb, f.v[1], f.pa, f.v[0], false);
  best.distance = std::sqrt(best_sq);
  return best;
}

// The Contact level's fields of a touching or penetrating pair answered on `ax` (as
// `detail::fill_from_axis` for triangles), the Depth level's at least.
template <class F, class T = typename F::Scalar>
void fill_from_axis(const F& f, Level level, const AxisOverlap<T>& ax, Result<T>& r) {
  if (level == Level::Overlap) return;
  r.separation = -ax.overlap;
  r.depth = ax.overlap > 0 ? ax.overlap : T(0);
  r.normal = f.axis(ax.axis);
  if (level == Level::Depth) return;
  const auto vertex = [&](bool of_a, int i) {
    return Feature{Feature::Type::Vertex, static_cast<std::uint8_t>(f.input_vertex(of_a, i))};
  };
  const auto edge = [&](bool of_a, int e) {
    return Feature{Feature::Type::Edge, static_cast<std::uint8_t>(f.input_edge(of_a, e))};
  };
  if (f.of_a(ax.axis)) {  // A's face, B's deepest vertex
    const Vec2<T>& deep = f.v[1][ax.deep];
    r.witness_b = deep + f.origin;
    r.witness_a = deep + ax.overlap * r.normal + f.origin;
    r.feature_a = edge(true, ax.axis);
    r.feature_b = vertex(false, ax.deep);
  } else {  // B's face, A's deepest vertex
    const Vec2<T>& deep = f.v[0][ax.deep];
    r.witness_a = deep + f.origin;
    r.witness_b = deep - ax.overlap * r.normal + f.origin;
    r.feature_a = vertex(true, ax.deep);
    r.feature_b = edge(false, f.edge(ax.axis));
  }
}

// A pair proven apart: the exact distance and closest points, or only the gap (`Apart::Gap`).
template <class F, class T = typename F::Scalar>
void fill_apart(const F& f, const ConvexQuery<T>& q, const AxisOverlap<T>& least,
                const Closest<T>* near, Result<T>& r) {
  r.status = Status::Separated;
  if (q.level == Level::Overlap) return;
  r.depth = 0;
  if (q.apart == Apart::Gap) {
    r.separation = std::max(T(0), -least.overlap);
    r.normal = f.axis(least.axis);
    return;
  }
  const Closest<T> c = near ? *near : closest_features(f);
  r.separation = c.distance;
  r.normal = (c.on_b - c.on_a) / c.distance;
  if (q.level == Level::Depth || (q.level == Level::Manifold && !q.witnesses)) return;
  r.witness_a = c.on_a + f.origin;
  r.witness_b = c.on_b + f.origin;
  r.feature_a = c.feature_a;
  r.feature_b = c.feature_b;
}

// The reference face's fields of `m` for axis `k` (no point yet).
template <class F, class T = typename F::Scalar>
void set_reference_face(const F& f, int k, Manifold<T>& m) {
  m.reference_is_a = f.of_a(k);
  m.reference_edge = static_cast<std::uint8_t>(f.input_edge(f.of_a(k), f.edge(k)));
  m.normal = f.axis(k);
}

// Box2D's clip (`detail::clip_manifold` for triangles, the same steps over any vertex count): the
// incident edge most anti-parallel to the reference normal, clipped against the reference face's
// side lines moved out by the margin, points kept within the margin.
template <class F, class T = typename F::Scalar>
[[gnu::always_inline]] inline void clip_manifold(const F& f, int k, T margin, Manifold<T>& m) {
  const bool ref_is_a = f.of_a(k);
  const int e = f.edge(k);
  const Local<T>& rv = f.vertices(ref_is_a);
  const Local<T>& iv = f.vertices(!ref_is_a);
  const Vec2<T> n = f.normal(ref_is_a, e);
  set_reference_face(f, k, m);

  int inc = 0;
  T most = n.dot(f.normal(!ref_is_a, 0));
  for (int j = 1; j < f.count(!ref_is_a); ++j) {
    const T d = n.dot(f.normal(!ref_is_a, j));
    inc = detail::select_index(d < most, j, inc);
    most = std::min(most, d);
  }
  m.incident_edge = static_cast<std::uint8_t>(f.input_edge(!ref_is_a, inc));

  const int e_next = f.next(ref_is_a, e);
  const int inc_next = f.next(!ref_is_a, inc);
  const detail::PointKeys keys(m.reference_edge, f.input_vertex(ref_is_a, e),
                               f.input_vertex(ref_is_a, e_next), m.incident_edge,
                               f.input_vertex(!ref_is_a, inc), f.input_vertex(!ref_is_a, inc_next),
                               ref_is_a);
  detail::clip_incident_edge(rv[e], rv[e_next], n, iv[inc], iv[inc_next], margin, keys, f.origin,
                             m);
}

// True when axis k is allowed by the masks: its edge not internal, and not realised inside the
// other body (`detail::realised_inside`, as for triangles).
template <class F, class T = typename F::Scalar>
bool axis_allowed(const F& f, const ConvexQuery<T>& q, int k) {
  const bool own_a = f.of_a(k);
  const ShapeMasks& own_masks = own_a ? q.masks_a : q.masks_b;
  const ShapeMasks& other_masks = own_a ? q.masks_b : q.masks_a;
  if (((own_masks.edges >> f.input_edge(own_a, f.edge(k))) & 1) != 0) return false;
  // The deep vertex is looked for only when the other shape has closed vertices at all.
  if (other_masks.closed_vertices == 0) return true;
  const Vec2<T> n = f.normal(own_a, f.edge(k));
  const Local<T>& other_v = f.vertices(!own_a);
  const int count = f.count(!own_a);
  T d[max_polygon_vertices];
  unsigned closed = 0;
  unsigned internal = 0;
  for (int w = 0; w < count; ++w) {
    d[w] = n.dot(other_v[w]);
    closed |= ((other_masks.closed_vertices >> f.input_vertex(!own_a, w)) & 1u) << w;
    internal |= ((other_masks.edges >> f.input_edge(!own_a, w)) & 1u) << w;
    // A segment's side lying flat on the face realises the axis only when it faces the face (a
    // polygon's flat outline edge at its deepest vertex always does): back to back, the face
    // would push through the segment's other side.
    if (count == 2) internal |= static_cast<unsigned>(!(f.normal(!own_a, w).dot(n) < 0)) << w;
  }
  return !realised_inside(d, other_v.data(), count, closed, internal);
}

// What one shape's edges say to the rule (bits by CCW edge), as `detail::edge_bits` for triangles.
struct EdgeBits {
  unsigned wholly_inside = 0;  // edges whose line holds the other shape wholly inside
  unsigned cut_other = 0;      // the other shape's edges both of whose ends lie beyond one line
};

template <class F, class T = typename F::Scalar>
EdgeBits edge_bits(const F& f, bool own_a, T reach) {
  const Local<T>& own_v = f.vertices(own_a);
  const Local<T>& other_v = f.vertices(!own_a);
  EdgeBits out;
  unsigned beyond[max_polygon_vertices] = {};  // bit e: the other's vertex w beyond edge e's line
  for (int e = 0; e < f.count(own_a); ++e) {
    const Vec2<T> n = f.normal(own_a, e);
    const T line = n.dot(own_v[e]);
    bool inside = true;
    for (int w = 0; w < f.count(!own_a); ++w) {
      const T d = n.dot(other_v[w]) - line;
      inside = inside && d < -reach;
      beyond[w] |= static_cast<unsigned>(d > reach) << e;
    }
    out.wholly_inside |= static_cast<unsigned>(inside) << e;
  }
  for (int j = 0; j < f.count(!own_a); ++j) {
    out.cut_other |= static_cast<unsigned>((beyond[j] & beyond[f.next(!own_a, j)]) != 0) << j;
  }
  return out;
}

// The axes the rule lets answer: allowed by the masks and touched by the other shape within
// `reach` (its least, and Box2D's reference among them); when one shape touches no edge of the
// other, the other holds it whole and the masks alone decide (see `Query::internal_edges`).
struct UsableAxes {
  int best_a = -1;      // least usable axis of A's; −1: none
  int best_b = -1;      // least usable axis of B's; −1: none
  unsigned usable = 0;  // bit k: axis k is usable
  bool any() const { return best_a >= 0 || best_b >= 0; }
};

template <class F, class T = typename F::Scalar>
UsableAxes usable_axes(const F& f, const ConvexQuery<T>& q, const Overlaps<T>& o, T reach) {
  const int na = f.counts[0];
  unsigned allowed = 0;
  for (int k = 0; k < f.axes(); ++k) {
    allowed |= static_cast<unsigned>(axis_allowed(f, q, k)) << k;
  }
  const EdgeBits a = edge_bits(f, true, reach);
  const EdgeBits b = edge_bits(f, false, reach);
  const unsigned touched_a = ~(a.wholly_inside | b.cut_other) & ((1u << na) - 1);
  const unsigned touched_b = ~(b.wholly_inside | a.cut_other) & ((1u << f.counts[1]) - 1);
  const unsigned usable =
      touched_a != 0 && touched_b != 0 ? allowed & (touched_a | touched_b << na) : allowed;
  return {o.least_in(0, na, usable), o.least_in(na, f.axes(), usable), usable};
}

// Box2D's reference rule between A's best axis `a` and B's `b` (−1: none on that side).
template <class T>
int reference_of(const Overlaps<T>& o, int a, int b, T hysteresis) {
  if (a < 0) return b;
  if (b < 0) return a;
  return detail::pick_reference(o.at(a), o.at(b), hysteresis).axis;
}

// `collide` for polygons `pa` and `pb`: each a `Polygon<T>` or any polygon-like type (see the
// file's head). Inline, so that a caller which reads a few fields of the answer has them from
// registers, not from a `Result` written to memory and read back.
template <class T, class PA, class PB>
[[gnu::always_inline]] inline Result<T> collide_polygons(const PA& pa, const PB& pb,
                                                         const ConvexQuery<T>& q) {
  const Frame<T, PA, PB> f(pa, pb);
  const Overlaps<T> o(f);
  const AxisOverlap<T> least = o.at(o.least);
  int reference = reference_of(o, o.best_a, o.best_b, q.face_hysteresis);
  int answer_axis = o.least;
  bool no_usable_axis = false;
  unsigned answerable = (1u << f.axes()) - 1;  // every axis; the usable ones when the rule rules
  // The rule, only for a pair not apart beyond the margin whose plain axis or face it refuses.
  const bool ruled =
      (q.masks_a.any() || q.masks_b.any()) && least.overlap >= -q.margin &&
      !(axis_allowed(f, q, o.least) && (reference == o.least || axis_allowed(f, q, reference)));
  const T band = status_band(least.overlap, touching_tolerance<T>() * f.scale_bound, ruled,
                             [&] { return touching_tolerance<T>() * f.scale(); });
  if (ruled) {
    const UsableAxes u = usable_axes(f, q, o, q.margin + band);
    no_usable_axis = !u.any();
    answerable = u.usable;
    if (u.any()) {
      answer_axis = u.best_a < 0                                ? u.best_b
                    : u.best_b < 0                              ? u.best_a
                    : o.overlap[u.best_b] < o.overlap[u.best_a] ? u.best_b
                                                                : u.best_a;
      reference = reference_of(o, u.best_a, u.best_b, q.face_hysteresis);
    } else {
      reference = o.least;
    }
  }

  Result<T> r;
  r.status = status_of_overlap(least.overlap, band);
  // A least overlap inside the band proves only that the pair does not overlap by more than it: a
  // gap along an edge normal can be far less than the distance, so the distance decides.
  Closest<T> near;
  const bool in_band = r.status == Status::Touching;
  if (in_band) near = closest_features(f);
  if (r.status == Status::Separated || (in_band && near.distance > band)) {
    fill_apart(f, q, least, in_band ? &near : nullptr, r);
  } else {
    const Level level = q.level == Level::Manifold && !q.witnesses ? Level::Depth : q.level;
    fill_from_axis(
        f, level, level >= Level::Contact ? overlap_on_axis(f, answer_axis) : o.at(answer_axis), r);
  }
  if (q.level != Level::Manifold) return r;
  if (no_usable_axis || -o.overlap[reference] > q.margin) {
    set_reference_face(f, reference, r.manifold);
  } else {
    clip_manifold(f, reference, q.margin, r.manifold);
    if (r.manifold.point_count > 0) {
      r.manifold.lead =
          lead_over(f, o.overlap, f.counts[0], f.axes(), answerable, reference, q.lead_reach);
    }
  }
  return r;
}

}  // namespace dyop::detail::polygon_pair

namespace dyop::detail {
using polygon_pair::collide_polygons;
}  // namespace dyop::detail
