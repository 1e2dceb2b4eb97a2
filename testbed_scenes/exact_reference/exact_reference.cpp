#include "exact_reference/exact_reference.hpp"

#include <gmpxx.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace dyop::workloads {
namespace {

using Z = mpz_class;
struct ZVec {
  Z x, y;
};
ZVec sub(const ZVec& a, const ZVec& b) { return {a.x - b.x, a.y - b.y}; }
Z dot(const ZVec& a, const ZVec& b) { return a.x * b.x + a.y * b.y; }
Z cross(const ZVec& a, const ZVec& b) { return a.x * b.y - a.y * b.x; }

// 256 bits: the final rounding to double dominates every other error by 2^200.
constexpr unsigned kBits = 256;
// A double's significand: |f| in [0.5, 1) times 2^53 is an integer.
constexpr int kSignificandBits = std::numeric_limits<double>::digits;

// The pair's unit of length: 2^exponent, the least power of two of which every coordinate (and
// radius) of the pair is an integer multiple. Lengths in units are exact integers.
class Grid {
 public:
  void include(double v) {
    if (v == 0) return;
    int e = 0;
    std::frexp(v, &e);
    exponent_ = std::min(exponent_, e - kSignificandBits);
  }
  void include(const RawPolygon& p) {
    for (int i = 0; i < p.count; ++i) {
      include(p.v[static_cast<std::size_t>(i)].x());
      include(p.v[static_cast<std::size_t>(i)].y());
    }
  }
  // `v` in units, exactly.
  Z units(double v) const {
    if (v == 0) return 0;
    int e = 0;
    const double f = std::frexp(v, &e);
    Z z(std::ldexp(f, kSignificandBits));
    mpz_mul_2exp(z.get_mpz_t(), z.get_mpz_t(),
                 static_cast<mp_bitcnt_t>(e - kSignificandBits - exponent()));
    return z;
  }
  ZVec units(const Vec2<double>& v) const { return {units(v.x()), units(v.y())}; }
  // A length of `x` units in metres (exact: a change of exponent).
  mpf_class metres(const mpf_class& x) const {
    mpf_class m(x, kBits);
    if (exponent() >= 0) {
      mpf_mul_2exp(m.get_mpf_t(), m.get_mpf_t(), static_cast<mp_bitcnt_t>(exponent()));
    } else {
      mpf_div_2exp(m.get_mpf_t(), m.get_mpf_t(), static_cast<mp_bitcnt_t>(-exponent()));
    }
    return m;
  }

 private:
  int exponent() const { return exponent_ == INT_MAX ? 0 : exponent_; }  // all zero: any unit
  int exponent_ = INT_MAX;
};

using ZPolygon = std::vector<ZVec>;

// Twice the signed area (shoelace): positive for counter-clockwise vertices.
Z twice_area(const ZPolygon& q) {
  Z sum = 0;
  for (std::size_t i = 0; i < q.size(); ++i) sum += cross(q[i], q[(i + 1) % q.size()]);
  return sum;
}

// True when the caller's order of `q` is counter-clockwise; a segment's (two vertices) is taken as
// such: its edge 0's outward normal is to the right of vertex 0 → vertex 1.
bool counter_clockwise(const ZPolygon& q) { return q.size() == 2 || sgn(twice_area(q)) > 0; }

// The caller's vertices in units, in the caller's order.
ZPolygon on_grid(const RawPolygon& p, const Grid& grid) {
  ZPolygon q;
  q.reserve(static_cast<std::size_t>(p.count));
  for (int i = 0; i < p.count; ++i) q.push_back(grid.units(p.v[static_cast<std::size_t>(i)]));
  return q;
}

// The same vertices counter-clockwise.
ZPolygon ccw_on_grid(const RawPolygon& p, const Grid& grid) {
  ZPolygon q = on_grid(p, grid);
  if (sgn(twice_area(q)) < 0) std::reverse(q.begin() + 1, q.end());
  return q;
}

// The outward normal of edge i of `own` (length |e|: not normalised, so exact): to the right of
// the edge for counter-clockwise vertices, to the left otherwise.
ZVec outward_normal(const ZPolygon& own, std::size_t i, bool ccw) {
  const ZVec e = sub(own[(i + 1) % own.size()], own[i]);
  return ccw ? ZVec{e.y, -e.x} : ZVec{-e.y, e.x};
}

// A signed length along a normal: numerator / sqrt(squared_length), in units.
struct AlongNormal {
  Z numerator;
  Z squared_length;  // > 0
};

AlongNormal along(Z numerator, const ZVec& n) { return {std::move(numerator), dot(n, n)}; }

// a < b, exactly: by sign, then by the squares cross-multiplied.
bool less(const AlongNormal& a, const AlongNormal& b) {
  const int sa = sgn(a.numerator);
  const int sb = sgn(b.numerator);
  if (sa != sb) return sa < sb;
  if (sa == 0) return false;
  const Z left = a.numerator * a.numerator * b.squared_length;
  const Z right = b.numerator * b.numerator * a.squared_length;
  return sa > 0 ? left < right : left > right;
}

// The length as a 256-bit float, in units.
mpf_class value(const AlongNormal& a) {
  mpf_class v(a.numerator, kBits);
  v /= sqrt(mpf_class(a.squared_length, kBits));
  return v;
}

// How far `other` reaches past the line of edge i of `own` along its outward normal.
AlongNormal edge_overlap(const ZPolygon& own, std::size_t i, bool ccw, const ZPolygon& other) {
  const ZVec n = outward_normal(own, i, ccw);
  Z least = dot(n, other[0]);
  for (std::size_t k = 1; k < other.size(); ++k) {
    Z d = dot(n, other[k]);
    if (d < least) least = std::move(d);
  }
  return along(dot(n, own[i]) - least, n);
}

// Least overlap over `own`'s edge normals (both counter-clockwise).
AlongNormal least_overlap(const ZPolygon& own, const ZPolygon& other, bool& any_negative,
                          bool& any_zero) {
  AlongNormal best;
  for (std::size_t i = 0; i < own.size(); ++i) {
    AlongNormal o = edge_overlap(own, i, true, other);
    any_negative = any_negative || sgn(o.numerator) < 0;
    any_zero = any_zero || sgn(o.numerator) == 0;
    if (i == 0 || less(o, best)) best = std::move(o);
  }
  return best;
}

// An exact squared distance, numerator / denominator (> 0), in square units.
struct SquaredDistance {
  Z numerator;
  Z denominator;
};

bool less(const SquaredDistance& a, const SquaredDistance& b) {
  return a.numerator * b.denominator < b.numerator * a.denominator;
}

// Squared distance from `p` to the segment q0–q1.
SquaredDistance squared_distance(const ZVec& p, const ZVec& q0, const ZVec& q1) {
  const ZVec e = sub(q1, q0);
  const ZVec w = sub(p, q0);
  const Z t = dot(w, e);
  Z ee = dot(e, e);
  if (sgn(t) <= 0) return {dot(w, w), 1};
  if (t >= ee) return {dot(sub(p, q1), sub(p, q1)), 1};
  const Z c = cross(e, w);
  return {c * c, std::move(ee)};
}

// Least squared distance from `p` to the edges of `edges`.
SquaredDistance least_squared_distance(const ZVec& p, const ZPolygon& edges) {
  SquaredDistance best;
  for (std::size_t j = 0; j < edges.size(); ++j) {
    SquaredDistance d = squared_distance(p, edges[j], edges[(j + 1) % edges.size()]);
    if (j == 0 || less(d, best)) best = std::move(d);
  }
  return best;
}

// Least squared distance from `points` to the edges of `edges`.
SquaredDistance least_squared_distance(const ZPolygon& points, const ZPolygon& edges) {
  SquaredDistance best;
  for (std::size_t k = 0; k < points.size(); ++k) {
    SquaredDistance d = least_squared_distance(points[k], edges);
    if (k == 0 || less(d, best)) best = std::move(d);
  }
  return best;
}

// The distance as a 256-bit float, in units.
mpf_class root(const SquaredDistance& d) {
  mpf_class v(d.numerator, kBits);
  v /= mpf_class(d.denominator, kBits);
  return mpf_class(sqrt(v), kBits);
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

Grid grid_of(const RawPolygonPair& p) {
  Grid grid;
  grid.include(p.a);
  grid.include(p.b);
  return grid;
}

Grid grid_of(const RawCirclePair& p) {
  Grid grid;
  grid.include(p.a);
  grid.include(p.b.center.x());
  grid.include(p.b.center.y());
  grid.include(p.b.radius);
  return grid;
}

}  // namespace

ExactAnswer exact_separation(const RawPolygonPair& p) {
  const Grid grid = grid_of(p);
  const ZPolygon a = ccw_on_grid(p.a, grid);
  const ZPolygon b = ccw_on_grid(p.b, grid);
  bool any_negative = false;
  bool any_zero = false;
  const AlongNormal on_a = least_overlap(a, b, any_negative, any_zero);
  const AlongNormal on_b = least_overlap(b, a, any_negative, any_zero);
  ExactAnswer out;
  if (any_negative) {
    SquaredDistance d2 = least_squared_distance(a, b);
    SquaredDistance d2b = least_squared_distance(b, a);
    if (less(d2b, d2)) d2 = std::move(d2b);
    out.sign = 1;
    out.separation = nearest_double(grid.metres(root(d2)));
    return out;
  }
  const AlongNormal& least = less(on_b, on_a) ? on_b : on_a;
  out.sign = any_zero ? 0 : -1;
  out.separation = -nearest_double(grid.metres(value(least)));
  return out;
}

ExactAnswer exact_separation(const RawPair& p) {
  return exact_separation(
      RawPolygonPair{RawPolygon::from_triangle(p.a), RawPolygon::from_triangle(p.b)});
}

ExactAnswer exact_separation(const RawCirclePair& p) {
  const Grid grid = grid_of(p);
  const ZPolygon a = ccw_on_grid(p.a, grid);
  const ZVec c = grid.units(p.b.center);
  const Z r = grid.units(p.b.radius);
  // The centre's signed distance from each edge line: all at most 0 when it is inside (or on) the
  // polygon.
  bool outside = false;
  AlongNormal nearest_line;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const ZVec n = outward_normal(a, i, true);
    AlongNormal s = along(dot(n, sub(c, a[i])), n);
    outside = outside || sgn(s.numerator) > 0;
    if (i == 0 || less(nearest_line, s)) nearest_line = std::move(s);
  }
  ExactAnswer out;
  // A segment (two vertices) has no inside: a centre on its line is at its distance from it.
  if (!outside && a.size() > 2) {
    // Inside: the circle reaches −nearest_line + r past the nearest edge; r > 0, so penetrating.
    out.sign = -1;
    out.separation =
        nearest_double(grid.metres(mpf_class(value(nearest_line) - mpf_class(r, kBits), kBits)));
    return out;
  }
  const SquaredDistance d2 = least_squared_distance(c, a);
  out.sign = sgn(Z(d2.numerator - r * r * d2.denominator));
  if (out.sign != 0) {
    out.separation = nearest_double(grid.metres(mpf_class(root(d2) - mpf_class(r, kBits), kBits)));
  }
  return out;
}

double exact_edge_overlap(const RawPolygonPair& p, bool of_a, int edge) {
  const Grid grid = grid_of(p);
  const ZPolygon own = on_grid(of_a ? p.a : p.b, grid);
  const ZPolygon other = on_grid(of_a ? p.b : p.a, grid);
  const bool ccw = counter_clockwise(own);
  const auto i = static_cast<std::size_t>(edge);
  return nearest_double(grid.metres(value(edge_overlap(own, i, ccw, other))));
}

double exact_edge_overlap(const RawPair& p, bool of_a, int edge) {
  return exact_edge_overlap(
      RawPolygonPair{RawPolygon::from_triangle(p.a), RawPolygon::from_triangle(p.b)}, of_a, edge);
}

double exact_edge_overlap(const RawCirclePair& p, int edge) {
  const Grid grid = grid_of(p);
  const ZPolygon own = on_grid(p.a, grid);
  const bool ccw = counter_clockwise(own);
  const auto i = static_cast<std::size_t>(edge);
  const ZVec n = outward_normal(own, i, ccw);
  // The circle's deepest point along −n is its centre less r along n: r + n·(own_i − c) / |n|.
  mpf_class overlap = value(along(dot(n, sub(own[i], grid.units(p.b.center))), n));
  overlap += mpf_class(grid.units(p.b.radius), kBits);
  return nearest_double(grid.metres(overlap));
}

}  // namespace dyop::workloads
