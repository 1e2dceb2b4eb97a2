// GJK + EPA in 2D (G. van den Bergen, "Proximity Queries and Penetration Depth Computation on 3D
// Game Objects", GDC 2001; dyop/epa.hpp has the whole description).
//   1. GJK: a simplex of support points of A − B (each a pair of vertex indices) iterated towards
//      the origin; it ends with the distance (origin outside) or a triangle enclosing the origin.
//   2. EPA: from that polygon (completed to positive area when GJK stopped on a point or a
//      segment), split the edge closest to the origin at the support point along its normal, until
//      the support lies no farther than `epa_tolerance` beyond it; that edge gives depth and
//      normal.
//   Invariants: the polygon stays convex and counter-clockwise; edges are differences of like
//   vertices, so a sliver's edge keeps an accurate direction; at most epa_max_iterations each.

#include "dyop/epa.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

#include "detail/fill_result.hpp"

namespace dyop {
namespace {

using detail::PairFrame;

// A point of the Minkowski difference A − B with the CCW vertices that make it: the indices are
// what turns a GJK simplex into witness points and features, and they give accurate edge vectors.
template <class T>
struct Support {
  Vec2<T> w = Vec2<T>::Zero();
  int ia = 0;
  int ib = 0;
};

template <class T>
Support<T> support(const PairFrame<T>& f, const Vec2<T>& d) {
  Support<T> s;
  T most_a = d.dot(f.a[0]);
  T least_b = d.dot(f.b[0]);
  for (int i = 1; i < 3; ++i) {
    const T da = d.dot(f.a[i]);
    const T db = d.dot(f.b[i]);
    if (da > most_a) {
      most_a = da;
      s.ia = i;
    }
    if (db < least_b) {
      least_b = db;
      s.ib = i;
    }
  }
  s.w = f.a[s.ia] - f.b[s.ib];
  return s;
}

// The edge from p to q as a difference of like vertices: the vertex the two support points share
// cancels exactly, so an edge of A − B that is a short edge of a sliver keeps an accurate
// direction (q.w − p.w would carry rounding relative to the pair's size, not the edge's length).
template <class T>
Vec2<T> edge_vector(const PairFrame<T>& f, const Support<T>& p, const Support<T>& q) {
  return (f.a[q.ia] - f.a[p.ia]) - (f.b[q.ib] - f.b[p.ib]);
}

// GJK's simplex, kept to the points that carry its closest point to the origin,
// v = Σ lambda[i]·p[i].w. Three points mean the origin is enclosed (v is then zero).
template <class T>
struct Simplex {
  std::array<Support<T>, 3> p{};
  std::array<T, 3> lambda{};
  int n = 0;
  Vec2<T> v = Vec2<T>::Zero();
};

template <class T>
Simplex<T> vertex_simplex(const Support<T>& p) {
  Simplex<T> s;
  s.p[0] = p;
  s.lambda[0] = 1;
  s.n = 1;
  s.v = p.w;
  return s;
}

template <class T>
Simplex<T> closest_on_segment(const PairFrame<T>& f, const Support<T>& p, const Support<T>& q) {
  const Vec2<T> e = edge_vector(f, p, q);
  const T ee = e.squaredNorm();
  const T t = -p.w.dot(e);
  // Two support points closer than the tolerance are one point of A − B (distinct vertex pairs
  // give equal points when an edge of A equals an edge of B): the segment has no direction.
  const T same = epa_tolerance<T>() * f.scale;
  if (ee <= same * same || t >= ee) return vertex_simplex(q);
  if (t <= 0) return vertex_simplex(p);
  Simplex<T> s;
  s.p[0] = p;
  s.p[1] = q;
  s.n = 2;
  s.lambda[1] = t / ee;
  s.lambda[0] = 1 - s.lambda[1];
  // Along the edge's unit normal rather than p + t·e: when the distance is small next to the
  // pair, p + t·e is mostly rounding of p and would send the next support search astray.
  const Vec2<T> n = right_perp(e) / std::sqrt(ee);
  s.v = n.dot(p.w) * n;
  return s;
}

// The origin's side of every edge is tested as cross(x, edge) with the exact edge vector, so the
// verdict is accurate to rounding relative to the pair's size even for a needle-shaped simplex.
// A flat simplex (height within the tolerance) has no trustworthy inside: its edges decide.
template <class T>
Simplex<T> closest_on_triangle(const PairFrame<T>& f, const Support<T>& p0, const Support<T>& p1,
                               const Support<T>& p2) {
  const std::array<const Support<T>*, 3> x = {&p0, &p1, &p2};
  std::array<Vec2<T>, 3> e;
  T longest = 0;
  for (int i = 0; i < 3; ++i) {
    e[i] = edge_vector(f, *x[i], *x[detail::next3(i)]);
    longest = std::max(longest, e[i].norm());
  }
  const T twice_area = cross(e[0], Vec2<T>(-e[2]));
  const bool flat = std::abs(twice_area) <= epa_tolerance<T>() * f.scale * longest;
  std::array<bool, 3> outside = {true, true, true};
  if (!flat) {
    const T orientation = twice_area > 0 ? T(1) : T(-1);
    for (int i = 0; i < 3; ++i) outside[i] = orientation * cross(x[i]->w, e[i]) < 0;
    if (!outside[0] && !outside[1] && !outside[2]) {
      Simplex<T> s;
      s.p = {p0, p1, p2};
      s.n = 3;
      return s;
    }
  }
  Simplex<T> best;
  T best_sq = std::numeric_limits<T>::infinity();
  for (int i = 0; i < 3; ++i) {
    if (!outside[i]) continue;
    const Simplex<T> s = closest_on_segment(f, *x[i], *x[detail::next3(i)]);
    if (s.v.squaredNorm() < best_sq) {
      best_sq = s.v.squaredNorm();
      best = s;
    }
  }
  return best;
}

template <class T>
Simplex<T> add_point(const PairFrame<T>& f, const Simplex<T>& s, const Support<T>& w) {
  if (s.n == 0) return vertex_simplex(w);
  if (s.n == 1) return closest_on_segment(f, s.p[0], w);
  return closest_on_triangle(f, s.p[0], s.p[1], w);
}

template <class T>
bool in_simplex(const Simplex<T>& s, const Support<T>& w) {
  for (int i = 0; i < s.n; ++i) {
    if (s.p[i].ia == w.ia && s.p[i].ib == w.ib) return true;
  }
  return false;
}

// EPA's convex polygon inside A − B, counter-clockwise. Edge i runs from v[i] to v[i + 1].
template <class T>
struct Polygon {
  // It starts with at most 4 vertices and each expansion adds one, so it never overflows.
  static constexpr int capacity = 4 + epa_max_iterations;
  std::array<Support<T>, capacity> v{};
  std::array<Vec2<T>, capacity> normal{};  // unit, outward
  std::array<T, capacity> dist{};          // signed distance of the edge's line from the origin
  int n = 0;

  int next(int i) const { return i + 1 == n ? 0 : i + 1; }
  int prev(int i) const { return i == 0 ? n - 1 : i - 1; }

  void set_edge(const PairFrame<T>& f, int i) {
    const Vec2<T> e = edge_vector(f, v[i], v[next(i)]);
    normal[i] = right_perp(e) / e.norm();
    dist[i] = normal[i].dot(v[i].w);
  }

  int closest() const {
    int best = 0;
    for (int i = 1; i < n; ++i) {
      if (dist[i] < dist[best]) best = i;
    }
    return best;
  }
};

// Adds `w` to `poly` through edge `e` when it lies beyond that edge by more than the tolerance
// (otherwise the edge is on the boundary of A − B and nothing changes; returns false). Every
// other edge `w` also lies beyond is dropped with it, so the polygon stays the convex hull: `w`
// is a support point, so those edges form one chain around `e`. Two old vertices always stay.
template <class T>
bool expand(const PairFrame<T>& f, Polygon<T>& poly, int e, const Support<T>& w) {
  if (poly.normal[e].dot(w.w) - poly.dist[e] <= epa_tolerance<T>() * f.scale) return false;
  auto sees = [&](int i) { return poly.normal[i].dot(w.w) > poly.dist[i]; };
  int first = e;
  int last = e;
  int visible = 1;
  while (visible < poly.n - 1 && sees(poly.prev(first))) {
    first = poly.prev(first);
    ++visible;
  }
  while (visible < poly.n - 1 && sees(poly.next(last))) {
    last = poly.next(last);
    ++visible;
  }
  // Rebuilt from the end of the visible chain round to its start, then `w`: the kept vertices'
  // edges are unchanged but for the two that now meet `w`.
  Polygon<T> out;
  out.n = poly.n - visible + 2;
  int i = poly.next(last);
  for (int k = 0; k + 1 < out.n; ++k, i = poly.next(i)) {
    out.v[k] = poly.v[i];
    out.normal[k] = poly.normal[i];
    out.dist[k] = poly.dist[i];
  }
  out.v[out.n - 1] = w;
  out.set_edge(f, out.n - 2);
  out.set_edge(f, out.n - 1);
  poly = out;
  return true;
}

// EPA's first polygon: GJK's simplex, completed to a triangle (or quadrilateral) of positive area
// when GJK stopped on a point or a segment with the origin on it. The supports on either side of
// a segment cannot both lie on its line, since A − B is at least as wide as A.
template <class T>
Polygon<T> initial_polygon(const PairFrame<T>& f, const Simplex<T>& s) {
  Polygon<T> poly;
  if (s.n == 3) {
    const bool cw = cross(edge_vector(f, s.p[0], s.p[1]), edge_vector(f, s.p[0], s.p[2])) < 0;
    poly.v[0] = s.p[0];
    poly.v[1] = s.p[cw ? 2 : 1];
    poly.v[2] = s.p[cw ? 1 : 2];
    poly.n = 3;
    for (int i = 0; i < 3; ++i) poly.set_edge(f, i);
    return poly;
  }
  Support<T> p = s.p[0];
  Support<T> q = s.p[1];
  if (s.n == 1) {
    // Any direction gives a second point; of the two ends along x, the one farther from p.
    const Support<T> right = support(f, Vec2<T>(1, 0));
    const Support<T> left = support(f, Vec2<T>(-1, 0));
    q = (right.w - p.w).squaredNorm() >= (left.w - p.w).squaredNorm() ? right : left;
  }
  const Vec2<T> e = edge_vector(f, p, q);
  const Vec2<T> m = right_perp(e) / e.norm();
  const Support<T> on_right = support(f, m);
  const Support<T> on_left = support(f, Vec2<T>(-m));
  const bool right_wider = m.dot(on_right.w - p.w) >= m.dot(p.w - on_left.w);
  // Counter-clockwise: a point right of p→q goes between p and q, one on the left after q.
  if (!right_wider) std::swap(p, q);
  poly.v = {p, right_wider ? on_right : on_left, q};
  poly.n = 3;
  for (int i = 0; i < 3; ++i) poly.set_edge(f, i);
  expand(f, poly, 2, right_wider ? on_left : on_right);
  return poly;
}

// Candidate axis (0..5) closest in direction to the unit `n`; ties go to the lower index. The
// squared chord |u − n|², not the cosine u·n, which cannot tell apart angles below √eps.
template <class T>
int nearest_axis(const PairFrame<T>& f, const Vec2<T>& n) {
  int best = 0;
  T best_chord = (f.axis(0) - n).squaredNorm();
  for (int k = 1; k < 6; ++k) {
    const T chord = (f.axis(k) - n).squaredNorm();
    if (chord < best_chord) {
      best_chord = chord;
      best = k;
    }
  }
  return best;
}

template <class T>
Feature simplex_feature(const Triangle<T>& t, int i0, int i1) {
  if (i0 == i1) return detail::input_feature(t, {Feature::Type::Vertex, std::uint8_t(i0)});
  const int edge = detail::next3(i0) == i1 ? i0 : i1;
  return detail::input_feature(t, {Feature::Type::Edge, std::uint8_t(edge)});
}

// GJK ended with the origin farther than the touching band from A − B: the distance, normal,
// witnesses and features come from the simplex (a vertex or an edge of A − B).
template <class T>
void answer_separated(const PairFrame<T>& f, const Query<T>& q, const Simplex<T>& s, Result<T>& r) {
  const Support<T>& p = s.p[0];
  if (s.n == 1) {
    r.separation = p.w.norm();
    r.normal = -p.w / r.separation;
  } else {
    // The edge's own normal, not −v/|v|: accurate however small the distance is.
    const Vec2<T> e = edge_vector(f, p, s.p[1]);
    r.normal = right_perp(e) / e.norm();
    if (r.normal.dot(p.w) > 0) r.normal = -r.normal;
    r.separation = -r.normal.dot(p.w);
  }
  if (q.level == Level::Depth) return;
  Vec2<T> on_a = Vec2<T>::Zero();
  Vec2<T> on_b = Vec2<T>::Zero();
  for (int i = 0; i < s.n; ++i) {
    on_a += s.lambda[i] * f.a[s.p[i].ia];
    on_b += s.lambda[i] * f.b[s.p[i].ib];
  }
  r.witness_a = on_a + f.origin;
  r.witness_b = on_b + f.origin;
  const Support<T>& last = s.p[s.n - 1];
  r.feature_a = simplex_feature(f.ta, p.ia, last.ia);
  r.feature_b = simplex_feature(f.tb, p.ib, last.ib);
  // Within the margin a separated pair still gets a (speculative) manifold, on the face Box2D's
  // rule picks: faces of A and B parallel to within rounding (a body resting on another) would
  // otherwise swap from step to step, and warm starting with them.
  if (q.level == Level::Manifold) {
    detail::fill_manifold(f, q, detail::reference_face(detail::all_overlaps(f), q.face_hysteresis),
                          r);
  }
}

}  // namespace

template <class T>
Result<T> epa(const Triangle<T>& a, const Triangle<T>& b, const Query<T>& query) {
  const PairFrame<T> f(a, b);
  const T band = detail::touching_band(f);
  const T tolerance = epa_tolerance<T>() * f.scale;
  Result<T> r;

  // GJK (van den Bergen 2001), started from the difference of the centroids, a point of A − B
  // that usually points straight at the answer.
  Vec2<T> v = (f.a[0] + f.a[1] + f.a[2] - f.b[0] - f.b[1] - f.b[2]) / T(3);
  Simplex<T> s;
  bool near_origin = false;
  while (r.iterations < epa_max_iterations) {
    const Support<T> w = support(f, Vec2<T>(-v));
    ++r.iterations;
    const T vw = v.dot(w.w);
    const T vn = v.norm();
    // v·w/|v| is a lower bound on the distance: beyond the band, the status is settled.
    if (query.level == Level::Overlap && vw > band * vn) {
      r.status = Status::Separated;
      return r;
    }
    // Upper bound |v| and lower bound v·w/|v| agree within the tolerance, or no progress left.
    if (s.n > 0 && (vn * vn - vw <= tolerance * vn || in_simplex(s, w))) break;
    s = add_point(f, s, w);
    v = s.v;
    // Enclosed, or within rounding of the simplex: only EPA can tell touching from penetrating.
    if (s.n == 3 || v.norm() <= band) {
      near_origin = true;
      break;
    }
  }
  if (!near_origin) {
    r.status = Status::Separated;
    if (query.level != Level::Overlap) answer_separated(f, query, s, r);
    return r;
  }

  // EPA: split the polygon's edge nearest the origin by the support point along its normal until
  // that point is no farther than the edge. The polygon holds the origin (to within the band), so
  // its nearest edge is a lower bound on the depth and, once on the boundary, the depth itself.
  Polygon<T> poly = initial_polygon(f, s);
  int nearest = poly.closest();
  for (int steps = 0; steps < epa_max_iterations; ++steps) {
    if (query.level == Level::Overlap && poly.dist[nearest] > band) break;
    const Support<T> w = support(f, poly.normal[nearest]);
    ++r.iterations;
    if (!expand(f, poly, nearest, w)) break;
    nearest = poly.closest();
  }
  const T depth = poly.dist[nearest];
  r.status = detail::status_of_overlap(depth, band);
  if (query.level == Level::Overlap) return r;
  // EPA's own depth and normal are reported; the candidate axis nearest to its normal only
  // names the features, the witnesses and the manifold's reference face.
  detail::AxisOverlap<T> ax = detail::overlap_on_axis(f, nearest_axis(f, poly.normal[nearest]));
  ax.overlap = depth;
  detail::fill_from_axis(f, query.level, ax, r);
  r.normal = poly.normal[nearest];
  if (query.level == Level::Manifold) {
    detail::fill_manifold(
        f, query, detail::reference_face(detail::all_overlaps(f), query.face_hysteresis), r);
  }
  return r;
}

template Result<float> epa(const Triangle<float>&, const Triangle<float>&, const Query<float>&);
template Result<double> epa(const Triangle<double>&, const Triangle<double>&, const Query<double>&);

}  // namespace dyop
