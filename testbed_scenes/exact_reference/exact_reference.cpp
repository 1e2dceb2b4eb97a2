#include "exact_reference/exact_reference.hpp"

#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace dyop::workloads {
namespace {

using Q = mpq_class;
struct QVec {
  Q x, y;
};
QVec sub(const QVec& a, const QVec& b) { return {a.x - b.x, a.y - b.y}; }
Q dot(const QVec& a, const QVec& b) { return a.x * b.x + a.y * b.y; }
Q cross(const QVec& a, const QVec& b) { return a.x * b.y - a.y * b.x; }
QVec exact(const Vec2<double>& v) { return {Q(v.x()), Q(v.y())}; }

// 256 bits: the final rounding to double dominates every other error by 2^200.
constexpr unsigned kBits = 256;

using QPolygon = std::vector<QVec>;

// Twice the signed area (shoelace): positive for counter-clockwise vertices.
Q twice_area(const QPolygon& q) {
  Q sum = 0;
  for (std::size_t i = 0; i < q.size(); ++i) sum += cross(q[i], q[(i + 1) % q.size()]);
  return sum;
}

// The caller's vertices, exactly, in the caller's order.
QPolygon exact_polygon(const RawPolygon& p) {
  QPolygon q;
  for (int i = 0; i < p.count; ++i) q.push_back(exact(p.v[static_cast<std::size_t>(i)]));
  return q;
}

// The same vertices counter-clockwise.
QPolygon exact_ccw(const RawPolygon& p) {
  QPolygon q = exact_polygon(p);
  if (sgn(twice_area(q)) < 0) std::reverse(q.begin() + 1, q.end());
  return q;
}

// The outward normal of edge i of `own` (length |e|: not normalised, so exact): to the right of
// the edge for counter-clockwise vertices, to the left otherwise.
QVec outward_normal(const QPolygon& own, std::size_t i, bool ccw) {
  const QVec e = sub(own[(i + 1) % own.size()], own[i]);
  return ccw ? QVec{e.y, -e.x} : QVec{-e.y, e.x};
}

// N / |n| as a 256-bit float: the exact numerator over the normal's length.
mpf_class over_length(const Q& numerator, const QVec& n) {
  mpf_class value(numerator, kBits);
  value /= sqrt(mpf_class(dot(n, n), kBits));
  return value;
}

// How far `other` reaches past the line of edge i of `own` along its outward normal, times |n|.
Q edge_overlap_numerator(const QPolygon& own, std::size_t i, bool ccw, const QPolygon& other) {
  const QVec n = outward_normal(own, i, ccw);
  Q least = dot(n, other[0]);
  for (std::size_t k = 1; k < other.size(); ++k) {
    const Q d = dot(n, other[k]);
    if (d < least) least = d;
  }
  return dot(n, own[i]) - least;
}

// Least overlap over `own`'s edge normals (both counter-clockwise).
mpf_class least_overlap(const QPolygon& own, const QPolygon& other, bool& any_negative,
                        bool& any_zero) {
  mpf_class best(0, kBits);
  for (std::size_t i = 0; i < own.size(); ++i) {
    const Q numerator = edge_overlap_numerator(own, i, true, other);
    any_negative = any_negative || sgn(numerator) < 0;
    any_zero = any_zero || sgn(numerator) == 0;
    const mpf_class value = over_length(numerator, outward_normal(own, i, true));
    if (i == 0 || value < best) best = value;
  }
  return best;
}

// Squared distance from `p` to the segment q0–q1 (exact).
Q squared_distance(const QVec& p, const QVec& q0, const QVec& q1) {
  const QVec e = sub(q1, q0);
  const QVec w = sub(p, q0);
  const Q t = dot(w, e);
  const Q ee = dot(e, e);
  if (sgn(t) <= 0) return dot(w, w);
  if (t >= ee) {
    const QVec w1 = sub(p, q1);
    return dot(w1, w1);
  }
  const Q c = cross(e, w);
  return c * c / ee;
}

// Least squared distance from `p` to the edges of `edges` (exact).
Q least_squared_distance(const QVec& p, const QPolygon& edges) {
  Q best = -1;
  for (std::size_t j = 0; j < edges.size(); ++j) {
    const Q d = squared_distance(p, edges[j], edges[(j + 1) % edges.size()]);
    if (sgn(best) < 0 || d < best) best = d;
  }
  return best;
}

// Least squared distance from `points` to the edges of `edges` (exact).
Q least_squared_distance(const QPolygon& points, const QPolygon& edges) {
  Q best = -1;
  for (const QVec& p : points) {
    const Q d = least_squared_distance(p, edges);
    if (sgn(best) < 0 || d < best) best = d;
  }
  return best;
}

// `x` rounded to the nearest double: `get_d` truncates toward zero, so the double past it may be
// the nearer.
double nearest_double(const mpf_class& x) {
  const double toward_zero = x.get_d();
  const double away = std::nextafter(toward_zero, sgn(x) < 0 ? -HUGE_VAL : HUGE_VAL);
  const mpf_class below_error(abs(x - mpf_class(toward_zero, kBits)), kBits);
  const mpf_class above_error(abs(x - mpf_class(away, kBits)), kBits);
  return above_error < below_error ? away : toward_zero;
}

double rounded_sqrt(const Q& x) {
  return nearest_double(mpf_class(sqrt(mpf_class(x, kBits)), kBits));
}

}  // namespace

ExactAnswer exact_separation(const RawPolygonPair& p) {
  const QPolygon a = exact_ccw(p.a);
  const QPolygon b = exact_ccw(p.b);
  bool any_negative = false;
  bool any_zero = false;
  const mpf_class on_a = least_overlap(a, b, any_negative, any_zero);
  const mpf_class on_b = least_overlap(b, a, any_negative, any_zero);
  ExactAnswer out;
  if (any_negative) {
    Q d2 = least_squared_distance(a, b);
    const Q d2b = least_squared_distance(b, a);
    if (d2b < d2) d2 = d2b;
    out.sign = 1;
    out.separation = rounded_sqrt(d2);
    return out;
  }
  const mpf_class least = on_a < on_b ? on_a : on_b;
  out.sign = any_zero ? 0 : -1;
  out.separation = -nearest_double(least);
  return out;
}

ExactAnswer exact_separation(const RawPair& p) {
  return exact_separation(
      RawPolygonPair{RawPolygon::from_triangle(p.a), RawPolygon::from_triangle(p.b)});
}

ExactAnswer exact_separation(const RawCirclePair& p) {
  const QPolygon a = exact_ccw(p.a);
  const QVec c = exact(p.b.center);
  const Q r(p.b.radius);
  // The centre's signed distance from each edge line, times |n|: all at most 0 when it is inside
  // (or on) the polygon.
  bool outside = false;
  mpf_class nearest_line(0, kBits);
  for (std::size_t i = 0; i < a.size(); ++i) {
    const QVec n = outward_normal(a, i, true);
    const Q s = dot(n, sub(c, a[i]));
    outside = outside || sgn(s) > 0;
    const mpf_class value = over_length(s, n);
    if (i == 0 || value > nearest_line) nearest_line = value;
  }
  ExactAnswer out;
  if (!outside) {
    // Inside: the circle reaches −nearest_line + r past the nearest edge; r > 0, so penetrating.
    out.sign = -1;
    out.separation = nearest_double(mpf_class(nearest_line - mpf_class(r, kBits), kBits));
    return out;
  }
  const Q d2 = least_squared_distance(c, a);
  out.sign = sgn(d2 - r * r);
  if (out.sign != 0) {
    out.separation =
        nearest_double(mpf_class(sqrt(mpf_class(d2, kBits)) - mpf_class(r, kBits), kBits));
  }
  return out;
}

double exact_edge_overlap(const RawPolygonPair& p, bool of_a, int edge) {
  const QPolygon own = exact_polygon(of_a ? p.a : p.b);
  const QPolygon other = exact_polygon(of_a ? p.b : p.a);
  const bool ccw = sgn(twice_area(own)) > 0;
  const auto i = static_cast<std::size_t>(edge);
  return nearest_double(
      over_length(edge_overlap_numerator(own, i, ccw, other), outward_normal(own, i, ccw)));
}

double exact_edge_overlap(const RawPair& p, bool of_a, int edge) {
  return exact_edge_overlap(
      RawPolygonPair{RawPolygon::from_triangle(p.a), RawPolygon::from_triangle(p.b)}, of_a, edge);
}

double exact_edge_overlap(const RawCirclePair& p, int edge) {
  const QPolygon own = exact_polygon(p.a);
  const bool ccw = sgn(twice_area(own)) > 0;
  const auto i = static_cast<std::size_t>(edge);
  const QVec n = outward_normal(own, i, ccw);
  // The circle's deepest point along −n is its centre less r along n: r + n·(own_i − c) / |n|.
  mpf_class value = over_length(dot(n, sub(own[i], exact(p.b.center))), n);
  value += mpf_class(Q(p.b.radius), kBits);
  return nearest_double(value);
}

}  // namespace dyop::workloads
