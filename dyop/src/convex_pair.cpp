#include "dyop/convex_pair.hpp"

#include <algorithm>
#include <cmath>

#include "detail/clip_manifold.hpp"
#include "detail/fill_result.hpp"
#include "detail/polygon_circle.hpp"

namespace dyop {
namespace {

using detail::AxisOverlap;
using detail::status_of_overlap;

using detail::Local;

// The two polygons in a frame centred on A's first CCW vertex (as `detail::PairFrame` does for
// triangles): accuracy relative to the pair's size, not to its distance from the origin. Axis k:
// 0..count(A)−1 are A's edge normals, then B's negated ones, so that every axis points from A
// to B.
template <class T>
struct Frame {
  const Polygon<T>& pa;
  const Polygon<T>& pb;
  Vec2<T> origin;
  Local<T> a;
  Local<T> b;
  T scale;  // the larger polygon's size: the unit of relative tolerances

  Frame(const Polygon<T>& pa_, const Polygon<T>& pb_)
      : pa(pa_), pb(pb_), origin(pa_.vertex(0)), scale(std::max(pa_.size(), pb_.size())) {
    for (int i = 0; i < pa.count(); ++i) a[i] = pa.vertex(i) - origin;
    for (int j = 0; j < pb.count(); ++j) b[j] = pb.vertex(j) - origin;
  }
  int axes() const { return pa.count() + pb.count(); }
  bool of_a(int k) const { return k < pa.count(); }
  int edge(int k) const { return of_a(k) ? k : k - pa.count(); }
  Vec2<T> axis(int k) const { return of_a(k) ? pa.normal(k) : Vec2<T>(-pb.normal(edge(k))); }
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
template <class T>
AxisOverlap<T> overlap_on_axis(const Frame<T>& f, int k) {
  const bool own_a = f.of_a(k);
  const int e = f.edge(k);
  const Vec2<T>& n = own_a ? f.pa.normal(e) : f.pb.normal(e);
  AxisOverlap<T> o;
  o.axis = k;
  o.overlap = n.dot((own_a ? f.a : f.b)[e]) -
              least_along(n, own_a ? f.b : f.a, own_a ? f.pb.count() : f.pa.count(), o.deep);
  return o;
}

// Every axis's overlap (`AxisOverlap`: max over the face's shape minus min over the other's along
// the face normal; negative: apart along it). The deepest vertices are left out (`deep` 0): most
// pairs need them for one axis at most (`overlap_on_axis`).
template <class T>
struct Overlaps {
  std::array<AxisOverlap<T>, 2 * max_polygon_vertices> axis;
  int best_a = 0;  // least of A's axes (first on ties)
  int best_b = 0;  // least of B's axes (first on ties)
  int least = 0;   // least of all (A's on ties): decides the status

  explicit Overlaps(const Frame<T>& f) {
    for (int k = 0; k < f.axes(); ++k) {
      const bool own_a = f.of_a(k);
      const int e = f.edge(k);
      const Vec2<T>& n = own_a ? f.pa.normal(e) : f.pb.normal(e);
      const Local<T>& own = own_a ? f.a : f.b;
      const Local<T>& other = own_a ? f.b : f.a;
      AxisOverlap<T>& o = axis[static_cast<std::size_t>(k)];
      o.axis = k;
      o.overlap = n.dot(own[e]) - least_value(n, other, own_a ? f.pb.count() : f.pa.count());
    }
    best_a = least_in(0, f.pa.count(), ~0u);
    best_b = least_in(f.pa.count(), f.axes(), ~0u);
    least = axis[best_b].overlap < axis[best_a].overlap ? best_b : best_a;
  }
  // The least of axes [from, to) whose bit is set in `mask` (first on ties); −1: none.
  int least_in(int from, int to, unsigned mask) const {
    int best = -1;
    T least = 0;
    for (int k = from; k < to; ++k) {
      const bool take = ((mask >> k) & 1u) != 0 && (best < 0 || axis[k].overlap < least);
      least = take ? axis[k].overlap : least;
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

template <class T>
Closest<T> closest_features(const Frame<T>& f) {
  Closest<T> best;
  T best_sq = -1;
  // Vertices of `points` (shape `pp`) against the segments of `segments` (shape `ps`).
  const auto search = [&](const Polygon<T>& pp, const Local<T>& points, const Polygon<T>& ps,
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
  search(f.pa, f.a, f.pb, f.b, true);
  search(f.pb, f.b, f.pa, f.a, false);
  best.distance = std::sqrt(best_sq);
  return best;
}

// The Contact level's fields of a touching or penetrating pair answered on `ax` (as
// `detail::fill_from_axis` for triangles), the Depth level's at least.
template <class T>
void fill_from_axis(const Frame<T>& f, Level level, const AxisOverlap<T>& ax, Result<T>& r) {
  if (level == Level::Overlap) return;
  r.separation = -ax.overlap;
  r.depth = ax.overlap > 0 ? ax.overlap : T(0);
  r.normal = f.axis(ax.axis);
  if (level == Level::Depth) return;
  const auto vertex = [](const Polygon<T>& p, int i) {
    return Feature{Feature::Type::Vertex, static_cast<std::uint8_t>(p.input_vertex(i))};
  };
  const auto edge = [](const Polygon<T>& p, int e) {
    return Feature{Feature::Type::Edge, static_cast<std::uint8_t>(p.input_edge(e))};
  };
  if (f.of_a(ax.axis)) {  // A's face, B's deepest vertex
    const Vec2<T>& deep = f.b[ax.deep];
    r.witness_b = deep + f.origin;
    r.witness_a = deep + ax.overlap * r.normal + f.origin;
    r.feature_a = edge(f.pa, ax.axis);
    r.feature_b = vertex(f.pb, ax.deep);
  } else {  // B's face, A's deepest vertex
    const Vec2<T>& deep = f.a[ax.deep];
    r.witness_a = deep + f.origin;
    r.witness_b = deep - ax.overlap * r.normal + f.origin;
    r.feature_a = vertex(f.pa, ax.deep);
    r.feature_b = edge(f.pb, f.edge(ax.axis));
  }
}

// A pair proven apart: the exact distance and closest points, or only the gap (`Apart::Gap`).
template <class T>
void fill_apart(const Frame<T>& f, const ConvexQuery<T>& q, const AxisOverlap<T>& least,
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
template <class T>
void set_reference_face(const Frame<T>& f, int k, Manifold<T>& m) {
  const Polygon<T>& rp = f.of_a(k) ? f.pa : f.pb;
  m.reference_is_a = f.of_a(k);
  m.reference_edge = static_cast<std::uint8_t>(rp.input_edge(f.edge(k)));
  m.normal = f.axis(k);
}

// Box2D's clip (`detail::clip_manifold` for triangles, the same steps over any vertex count): the
// incident edge most anti-parallel to the reference normal, clipped against the reference face's
// side lines moved out by the margin, points kept within the margin.
template <class T>
void clip_manifold(const Frame<T>& f, int k, T margin, Manifold<T>& m) {
  using detail::ClipSide;
  const bool ref_is_a = f.of_a(k);
  const int e = f.edge(k);
  const Polygon<T>& rp = ref_is_a ? f.pa : f.pb;
  const Polygon<T>& ip = ref_is_a ? f.pb : f.pa;
  const Local<T>& rv = ref_is_a ? f.a : f.b;
  const Local<T>& iv = ref_is_a ? f.b : f.a;
  const Vec2<T>& n = rp.normal(e);
  set_reference_face(f, k, m);

  int inc = 0;
  T most = n.dot(ip.normal(0));
  for (int j = 1; j < ip.count(); ++j) {
    const T d = n.dot(ip.normal(j));
    inc = detail::select_index(d < most, j, inc);
    most = std::min(most, d);
  }
  m.incident_edge = static_cast<std::uint8_t>(ip.input_edge(inc));

  const Vec2<T>& v1 = rv[e];
  const Vec2<T> tangent(-n.y(), n.x());
  const Vec2<T>& p0 = iv[inc];
  const Vec2<T>& p1 = iv[ip.next(inc)];
  const T s0 = tangent.dot(p0);
  const T s1 = tangent.dot(p1);
  const T lo = tangent.dot(v1) - margin;
  const T hi = tangent.dot(rv[rp.next(e)]) + margin;
  if (std::max(s0, s1) < lo || std::min(s0, s1) > hi) return;

  const detail::ClippedEnd<T> ends[2] = {detail::clip_end(s0, s1, lo, hi, T(0)),
                                         detail::clip_end(s1, s0, lo, hi, T(1))};
  const Vec2<T>* vertex_point[2] = {&p0, &p1};
  const detail::PointKeys keys(m.reference_edge, rp.input_vertex(e), rp.input_vertex(rp.next(e)),
                               m.incident_edge, ip.input_vertex(inc), ip.input_vertex(ip.next(inc)),
                               ref_is_a);
  const T front = n.dot(v1);
  for (int end = 0; end < 2; ++end) {
    const bool cut = ends[end].side != ClipSide::None;
    const Vec2<T> p = cut ? Vec2<T>(p0 + ends[end].along * (p1 - p0)) : *vertex_point[end];
    const T separation = n.dot(p) - front;
    // Written into the next slot whether kept or not, counted only when within the margin (as
    // `detail::clip_manifold`: whether an end lies beyond it does not predict).
    ManifoldPoint<T>& out = m.points[static_cast<std::size_t>(m.point_count)];
    out.point = p + f.origin;
    out.separation = separation;
    out.key = keys.key(end, ends[end].side);
    m.point_count += static_cast<int>(separation <= margin);
  }
}

// True when axis k is allowed by the masks: its edge not internal, its deepest vertex (of the
// other shape) not closed.
template <class T>
bool axis_allowed(const Frame<T>& f, const ConvexQuery<T>& q, int k) {
  const bool own_a = f.of_a(k);
  const Polygon<T>& own = own_a ? f.pa : f.pb;
  const Polygon<T>& other = own_a ? f.pb : f.pa;
  const ShapeMasks& own_masks = own_a ? q.masks_a : q.masks_b;
  const ShapeMasks& other_masks = own_a ? q.masks_b : q.masks_a;
  if (((own_masks.edges >> own.input_edge(f.edge(k))) & 1) != 0) return false;
  // The deep vertex is looked for only when the other shape has closed vertices at all.
  if (other_masks.closed_vertices == 0) return true;
  const int deep = overlap_on_axis(f, k).deep;
  return ((other_masks.closed_vertices >> other.input_vertex(deep)) & 1) == 0;
}

// What one shape's edges say to the rule (bits by CCW edge), as `detail::edge_bits` for triangles.
struct EdgeBits {
  unsigned wholly_inside = 0;  // edges whose line holds the other shape wholly inside
  unsigned cut_other = 0;      // the other shape's edges both of whose ends lie beyond one line
};

template <class T>
EdgeBits edge_bits(const Polygon<T>& own, const Local<T>& own_v, const Polygon<T>& other,
                   const Local<T>& other_v, T reach) {
  EdgeBits out;
  unsigned beyond[max_polygon_vertices] = {};  // bit e: the other's vertex w beyond edge e's line
  for (int e = 0; e < own.count(); ++e) {
    const Vec2<T>& n = own.normal(e);
    const T line = n.dot(own_v[e]);
    bool inside = true;
    for (int w = 0; w < other.count(); ++w) {
      const T d = n.dot(other_v[w]) - line;
      inside = inside && d < -reach;
      beyond[w] |= static_cast<unsigned>(d > reach) << e;
    }
    out.wholly_inside |= static_cast<unsigned>(inside) << e;
  }
  for (int j = 0; j < other.count(); ++j) {
    out.cut_other |= static_cast<unsigned>((beyond[j] & beyond[other.next(j)]) != 0) << j;
  }
  return out;
}

// The axes the rule lets answer: allowed by the masks and touched by the other shape within
// `reach` (its least, and Box2D's reference among them); when one shape touches no edge of the
// other, the other holds it whole and the masks alone decide (see `Query::internal_edges`).
template <class T>
struct UsableAxes {
  int best_a = -1;  // least usable axis of A's; −1: none
  int best_b = -1;  // least usable axis of B's; −1: none
  bool any() const { return best_a >= 0 || best_b >= 0; }
};

template <class T>
UsableAxes<T> usable_axes(const Frame<T>& f, const ConvexQuery<T>& q, const Overlaps<T>& o,
                          T reach) {
  const int na = f.pa.count();
  unsigned allowed = 0;
  for (int k = 0; k < f.axes(); ++k) {
    allowed |= static_cast<unsigned>(axis_allowed(f, q, k)) << k;
  }
  const EdgeBits a = edge_bits(f.pa, f.a, f.pb, f.b, reach);
  const EdgeBits b = edge_bits(f.pb, f.b, f.pa, f.a, reach);
  const unsigned touched_a = ~(a.wholly_inside | b.cut_other) & ((1u << na) - 1);
  const unsigned touched_b = ~(b.wholly_inside | a.cut_other) & ((1u << f.pb.count()) - 1);
  const unsigned usable =
      touched_a != 0 && touched_b != 0 ? allowed & (touched_a | touched_b << na) : allowed;
  return {o.least_in(0, na, usable), o.least_in(na, f.axes(), usable)};
}

// Box2D's reference rule between A's best axis `a` and B's `b` (−1: none on that side).
template <class T>
int reference_of(const Overlaps<T>& o, int a, int b, T hysteresis) {
  if (a < 0) return b;
  if (b < 0) return a;
  return detail::pick_reference(o.axis[a], o.axis[b], hysteresis).axis;
}

}  // namespace

template <class T>
Result<T> collide(const Polygon<T>& pa, const Polygon<T>& pb, const ConvexQuery<T>& q) {
  const Frame<T> f(pa, pb);
  const Overlaps<T> o(f);
  const T band = touching_tolerance<T>() * f.scale;
  const AxisOverlap<T>& least = o.axis[o.least];
  int reference = reference_of(o, o.best_a, o.best_b, q.face_hysteresis);
  int answer_axis = o.least;
  bool no_usable_axis = false;
  // The rule, only for a pair not apart beyond the margin whose plain axis or face it refuses.
  if ((q.masks_a.any() || q.masks_b.any()) && least.overlap >= -q.margin &&
      !(axis_allowed(f, q, o.least) && (reference == o.least || axis_allowed(f, q, reference)))) {
    const UsableAxes<T> u = usable_axes(f, q, o, q.margin + band);
    no_usable_axis = !u.any();
    if (u.any()) {
      answer_axis = u.best_a < 0                                          ? u.best_b
                    : u.best_b < 0                                        ? u.best_a
                    : o.axis[u.best_b].overlap < o.axis[u.best_a].overlap ? u.best_b
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
    fill_from_axis(f, level,
                   level >= Level::Contact ? overlap_on_axis(f, answer_axis) : o.axis[answer_axis],
                   r);
  }
  if (q.level != Level::Manifold) return r;
  if (no_usable_axis || -o.axis[reference].overlap > q.margin) {
    set_reference_face(f, reference, r.manifold);
  } else {
    clip_manifold(f, reference, q.margin, r.manifold);
  }
  return r;
}

template <class T>
Result<T> collide(const Polygon<T>& pa, const Circle<T>& circle, const ConvexQuery<T>& q) {
  return detail::collide_polygon_circle(pa, circle, q);
}

template Result<float> collide(const Polygon<float>&, const Polygon<float>&,
                               const ConvexQuery<float>&);
template Result<double> collide(const Polygon<double>&, const Polygon<double>&,
                                const ConvexQuery<double>&);
template Result<float> collide(const Polygon<float>&, const Circle<float>&,
                               const ConvexQuery<float>&);
template Result<double> collide(const Polygon<double>&, const Circle<double>&,
                                const ConvexQuery<double>&);

}  // namespace dyop
