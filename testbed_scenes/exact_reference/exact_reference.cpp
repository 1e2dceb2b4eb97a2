#include "exact_reference/exact_reference.hpp"

#include <gmpxx.h>

#include <array>

namespace dyop::workloads {
namespace {

using Q = mpq_class;
struct QVec {
  Q x, y;
};
QVec sub(const QVec& a, const QVec& b) { return {a.x - b.x, a.y - b.y}; }
Q dot(const QVec& a, const QVec& b) { return a.x * b.x + a.y * b.y; }
Q cross(const QVec& a, const QVec& b) { return a.x * b.y - a.y * b.x; }

// 256 bits: the final rounding to double dominates every other error by 2^200.
constexpr unsigned kBits = 256;

std::array<QVec, 3> exact_ccw(const std::array<Vec2<double>, 3>& v) {
  std::array<QVec, 3> q;
  for (int i = 0; i < 3; ++i) q[i] = {Q(v[i].x()), Q(v[i].y())};
  if (sgn(cross(sub(q[1], q[0]), sub(q[2], q[0]))) < 0) std::swap(q[1], q[2]);
  return q;
}

// Least overlap over `own`'s three edge normals: N/|e| with N exact, as a 256-bit float.
mpf_class least_overlap(const std::array<QVec, 3>& own, const std::array<QVec, 3>& other,
                        bool& any_negative, bool& any_zero) {
  mpf_class best(0, kBits);
  bool first = true;
  for (int i = 0; i < 3; ++i) {
    const QVec e = sub(own[(i + 1) % 3], own[i]);
    const QVec n{e.y, -e.x};
    Q least = dot(n, other[0]);
    for (int k = 1; k < 3; ++k) {
      const Q d = dot(n, other[k]);
      if (d < least) least = d;
    }
    const Q numerator = dot(n, own[i]) - least;
    any_negative = any_negative || sgn(numerator) < 0;
    any_zero = any_zero || sgn(numerator) == 0;
    mpf_class value(numerator, kBits);
    value /= sqrt(mpf_class(dot(e, e), kBits));
    if (first || value < best) best = value;
    first = false;
  }
  return best;
}

// Least squared distance from `points` to the edges of `edges` (exact).
Q least_squared_distance(const std::array<QVec, 3>& points, const std::array<QVec, 3>& edges) {
  Q best = -1;
  for (const QVec& p : points) {
    for (int j = 0; j < 3; ++j) {
      const QVec& q0 = edges[j];
      const QVec& q1 = edges[(j + 1) % 3];
      const QVec e = sub(q1, q0);
      const QVec w = sub(p, q0);
      const Q t = dot(w, e);
      const Q ee = dot(e, e);
      Q d;
      if (sgn(t) <= 0) {
        d = dot(w, w);
      } else if (t >= ee) {
        const QVec w1 = sub(p, q1);
        d = dot(w1, w1);
      } else {
        const Q c = cross(e, w);
        d = c * c / ee;
      }
      if (sgn(best) < 0 || d < best) best = d;
    }
  }
  return best;
}

}  // namespace

ExactAnswer exact_separation(const RawPair& p) {
  const std::array<QVec, 3> a = exact_ccw(p.a);
  const std::array<QVec, 3> b = exact_ccw(p.b);
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
    out.separation = mpf_class(sqrt(mpf_class(d2, kBits)), kBits).get_d();
    return out;
  }
  const mpf_class least = on_a < on_b ? on_a : on_b;
  out.sign = any_zero ? 0 : -1;
  out.separation = -least.get_d();
  return out;
}

double exact_edge_overlap(const RawPair& p, bool of_a, int edge) {
  const std::array<Vec2<double>, 3>& own_v = of_a ? p.a : p.b;
  const std::array<Vec2<double>, 3>& other_v = of_a ? p.b : p.a;
  std::array<QVec, 3> own;
  std::array<QVec, 3> other;
  for (int i = 0; i < 3; ++i) {
    own[i] = {Q(own_v[i].x()), Q(own_v[i].y())};
    other[i] = {Q(other_v[i].x()), Q(other_v[i].y())};
  }
  const QVec e = sub(own[(edge + 1) % 3], own[edge]);
  // Outward: to the right of the edge for counter-clockwise vertices, to the left otherwise.
  const bool ccw = sgn(cross(sub(own[1], own[0]), sub(own[2], own[0]))) > 0;
  const QVec n = ccw ? QVec{e.y, -e.x} : QVec{-e.y, e.x};
  Q least = dot(n, other[0]);
  for (int k = 1; k < 3; ++k) {
    const Q d = dot(n, other[k]);
    if (d < least) least = d;
  }
  mpf_class value(dot(n, own[edge]) - least, kBits);
  value /= sqrt(mpf_class(dot(e, e), kBits));
  return value.get_d();
}

}  // namespace dyop::workloads
