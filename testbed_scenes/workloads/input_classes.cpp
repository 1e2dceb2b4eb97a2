#include "workloads/input_classes.hpp"

#include <algorithm>
#include <cmath>

#include "dyop/sat.hpp"
#include "workloads/random.hpp"

// Every draw is a statement of its own (or an element of a braced list, evaluated in order): the
// order in which a call's arguments or an operator's operands are evaluated is up to the compiler,
// and a seed must give the same pairs with any.

namespace dyop::workloads {
namespace {

using V = Vec2<double>;
using Tri = std::array<V, 3>;

// `length` in a random direction.
V random_offset(Random& g, double length) { return length * g.unit_vector(); }

// A random non-degenerate triangle of about `size` around `centre`, random winding.
Tri random_triangle(Random& g, const V& centre, double size) {
  for (;;) {
    Tri t;
    for (V& v : t) {
      const double r = g.uniform(0.3, 1.0);
      v = centre + size * r * g.unit_vector();
    }
    if (valid_in_double(t) &&
        std::abs((t[1] - t[0]).x() * (t[2] - t[0]).y() - (t[1] - t[0]).y() * (t[2] - t[0]).x()) >
            0.05 * size * size) {
      return t;
    }
  }
}

// A general pair's B: size 0.3 to 1.5 about a point within a unit of A's centre.
Tri general_b(Random& g) {
  const V centre = g.point_in(-1, 1);
  const double size = g.uniform(0.3, 1.5);
  return random_triangle(g, centre, size);
}

RawPair general(Random& g) {
  const Tri a = random_triangle(g, V::Zero(), 1.0);
  return {a, general_b(g)};
}

bool penetrating(const RawPair& p) {
  const auto t = build<double>(p);
  return sat(t.a.triangle, t.b.triangle, Query<double>{Level::Overlap}).status ==
         Status::Penetrating;
}

bool boxes_overlap(const RawPair& p) {
  const Vec2<double> lo_a = p.a[0].cwiseMin(p.a[1]).cwiseMin(p.a[2]);
  const Vec2<double> hi_a = p.a[0].cwiseMax(p.a[1]).cwiseMax(p.a[2]);
  const Vec2<double> lo_b = p.b[0].cwiseMin(p.b[1]).cwiseMin(p.b[2]);
  const Vec2<double> hi_b = p.b[0].cwiseMax(p.b[1]).cwiseMax(p.b[2]);
  return (lo_a.array() <= hi_b.array()).all() && (lo_b.array() <= hi_a.array()).all();
}

// The first general pair that `want` accepts.
template <class Want>
RawPair general_where(Random& g, Want want) {
  for (;;) {
    const RawPair p = general(g);
    if (want(p)) return p;
  }
}

// The `index`-th pair of class Mixed: a third penetrate, at positions picked by a hash (no period
// a branch predictor could learn), the others apart with overlapping boxes.
RawPair mixed(Random& g, int index) {
  const bool want_penetrating = (static_cast<std::uint32_t>(index) * 2654435761u >> 16) % 3 == 0;
  return general_where(
      g, [&](const RawPair& p) { return penetrating(p) == want_penetrating && boxes_overlap(p); });
}

RawPair apart(Random& g) {
  const Tri a = random_triangle(g, V::Zero(), 1.0);
  const V centre = random_offset(g, g.uniform(2.5, 10.0));
  const double size = g.uniform(0.3, 1.5);
  return {a, random_triangle(g, centre, size)};
}

// A right triangle with axis-parallel legs ±0.3 to ±1.5 long, its corner at `corner`.
Tri right_triangle(Random& g, const V& corner) {
  auto leg = [&] {
    const double sign = g.coin() ? 1.0 : -1.0;
    return sign * g.uniform(0.3, 1.5);
  };
  const double w = leg();
  const double h = leg();
  return g.shuffled({corner, corner + V(w, 0), corner + V(0, h)});
}

RawPair axis_aligned(Random& g) {
  const V c = g.point_in(-1, 1);
  // Half the time B's corner shares a coordinate with A's, so edges lie on one line.
  V d = g.point_in(-1, 1);
  if (g.coin()) d[g.below(2)] = 0;
  const Tri a = right_triangle(g, c);
  return {a, right_triangle(g, c + d)};
}

Tri sliver(Random& g, const V& centre) {
  const double aspect = g.log_uniform(-7, -1);
  const V dir = g.unit_vector();
  const V side(-dir.y(), dir.x());
  const double length = g.uniform(0.5, 2.0);
  const V p0 = centre - 0.5 * length * dir;
  const V p1 = centre + 0.5 * length * dir;
  const V p2 = centre + g.uniform(-0.4, 0.4) * length * dir + aspect * length * side;
  return g.shuffled({p0, p1, p2});
}

// B a sliver, and half the time A too; both valid in double.
RawPair sliver_pair(Random& g) {
  for (;;) {
    const Tri a = random_triangle(g, V::Zero(), 1.0);
    RawPair p{a, sliver(g, g.point_in(-1, 1))};
    if (g.coin()) p.a = sliver(g, g.point_in(-0.3, 0.3));
    if (valid_in_double(p.a) && valid_in_double(p.b)) return p;
  }
}

// B has an edge at a tiny angle to one of A's edges, just inside or just outside it.
RawPair near_parallel(Random& g) {
  for (;;) {
    const Tri a = random_triangle(g, V::Zero(), 1.0);
    const int i = g.below(3);
    const V p = a[i];
    const V q = a[(i + 1) % 3];
    const V r = a[(i + 2) % 3];
    const V e = (q - p).normalized();
    V out(e.y(), -e.x());
    if (out.dot(r - p) > 0) out = -out;  // pointing away from A's third vertex
    const double sign = g.coin() ? 1 : -1;
    const double angle = sign * g.log_uniform(-14, -3);
    const V f(std::cos(angle) * e.x() - std::sin(angle) * e.y(),
              std::sin(angle) * e.x() + std::cos(angle) * e.y());
    const double along = g.uniform(-0.2, 0.5);
    const V start = p + along * (q - p) + g.uniform(-1e-3, 1e-3) * out;
    const double length = g.uniform(0.3, 1.2);
    const V apex = start + 0.5 * length * f + g.uniform(0.3, 1.0) * out;
    const Tri shuffled_a = g.shuffled(a);
    RawPair pair{shuffled_a, g.shuffled({start, start + length * f, apex})};
    if (valid_in_double(pair.b)) return pair;
  }
}

RawPair moved(const RawPair& p, double scale, const V& offset) {
  RawPair out = p;
  for (V& v : out.a) v = scale * v + offset;
  for (V& v : out.b) v = scale * v + offset;
  return out;
}

V centroid(const Tri& t) { return (t[0] + t[1] + t[2]) / 3.0; }

Tri shrunk(const Tri& t, const V& about, double k) {
  return {about + k * (t[0] - about), about + k * (t[1] - about), about + k * (t[2] - about)};
}

RawPair far(Random& g, Precision precision) {
  const RawPair p = general(g);
  const double distance = g.log_uniform(0, std::log10(max_offset(precision)));
  return moved(p, 1.0, random_offset(g, distance));
}

RawPair scaled(Random& g) {
  RawPair p = general(g);
  if (g.below(4) == 0) p.b = shrunk(p.b, centroid(p.b), g.log_uniform(-6, 0));
  return moved(p, g.log_uniform(-8, 8), V::Zero());
}

// One triangle inside the other: shrunk about the centroid, about a vertex (a shared vertex and
// two edges on one line each) or about a point of an edge (an edge on the other's edge line).
RawPair contained(Random& g) {
  const Tri outer = random_triangle(g, V::Zero(), 1.0);
  const double k = g.uniform(0.05, 0.95);
  V about;
  switch (g.below(3)) {
    case 0:
      about = centroid(outer);
      break;
    case 1:
      about = outer[g.below(3)];
      break;
    default: {
      const int i = g.below(3);
      about = outer[i] + g.uniform(0.2, 0.8) * (outer[(i + 1) % 3] - outer[i]);
    }
  }
  const Tri a = g.shuffled(outer);
  RawPair p{a, g.shuffled(shrunk(outer, about, k))};
  if (g.coin()) std::swap(p.a, p.b);
  return p;
}

RawPair identical(Random& g) {
  const V centre = g.point_in(-2, 2);
  const Tri t = random_triangle(g, centre, 1.0);
  return {t, g.shuffled(t)};
}

// Exactly touching in double: a horizontal edge of A at height y0 and B resting on it, with a
// vertex on the edge or vertex on vertex; then a quarter-turn (exact) and an integer shift (exact).
RawPair touching(Random& g) {
  const double y0 = std::round(g.uniform(-4, 4));
  const double x0 = g.uniform(-1, 0);
  const double x1 = g.uniform(0.5, 1.5);
  const double apex_x = g.uniform(x0, x1);
  const double apex_y = y0 - g.uniform(0.3, 1.0);
  Tri a{V(x0, y0), V(x1, y0), V(apex_x, apex_y)};
  double xm = g.uniform(x0, x1);
  if (g.coin()) xm = g.coin() ? x0 : x1;
  Tri b;
  b[0] = V(xm, y0);
  for (int k = 1; k < 3; ++k) {
    const double dx = g.uniform(-1, 1);
    b[k] = V(xm + dx, y0 + g.uniform(0.3, 1.0));
  }
  if (g.coin()) b[1].y() = y0;  // edge on edge half of the time when B also has a flat bottom
  const int turns = g.below(4);
  const V shift = g.point_in(-8, 8).array().round().matrix();
  auto turn = [&](V v) {
    for (int t = 0; t < turns; ++t) v = V(-v.y(), v.x());
    return v + shift;
  };
  for (V& v : a) v = turn(v);
  for (V& v : b) v = turn(v);
  const Tri shuffled_a = g.shuffled(a);
  return {shuffled_a, g.shuffled(b)};
}

// The next value of `x` in precision `p`, `steps` ulps towards +infinity (negative: towards -inf).
double ulps_away(Precision p, double x, int steps) {
  const double towards = steps > 0 ? INFINITY : -INFINITY;
  for (int k = 0; k < std::abs(steps); ++k) {
    x = p == Precision::Float ? double(std::nextafter(float(x), float(towards)))
                              : std::nextafter(x, towards);
  }
  return x;
}

// B's vertex on A's edge, computed from A as the precision holds it and rounded, so it lies within
// an ulp of the edge's line; then 0 to 2 ulps further, in or out. A quarter of the time B's next
// vertex is on the same line too (edge on edge). Half the pairs sit up to 1e3 (float: 10) units
// from the origin, where an ulp is a larger fraction of the pair.
RawPair touching_ulp(Random& g, Precision precision) {
  const Tri base = random_triangle(g, V::Zero(), 1.0);
  const double far_exp = precision == Precision::Float ? 1 : 3;
  V shift = V::Zero();
  if (g.coin()) shift = random_offset(g, g.log_uniform(0, far_exp));
  Tri a;
  for (int i = 0; i < 3; ++i) a[i] = rounded_to(precision, base[i] + shift);
  const int i = g.below(3);
  const V& p = a[i];
  const V& q = a[(i + 1) % 3];
  const V& r = a[(i + 2) % 3];
  const V e = (q - p).normalized();
  V out(e.y(), -e.x());
  if (out.dot(r - p) > 0) out = -out;
  V x = rounded_to(precision, p + g.uniform(0.05, 0.95) * (q - p));
  const int axis = std::abs(out.x()) > std::abs(out.y()) ? 0 : 1;
  x[axis] = ulps_away(precision, x[axis], (g.below(5) - 2) * (out[axis] > 0 ? 1 : -1));
  const double length = g.uniform(0.3, 1.2) * (q - p).norm();
  // B's other vertices: `up` of `length` away from A, `across` of it along the edge.
  auto beside = [&](double up_lo) {
    const double up = g.uniform(up_lo, 1.0);
    const double across = g.uniform(-1, 1);
    return rounded_to(precision, x + length * (up * out + across * e));
  };
  Tri b;
  b[0] = x;
  b[1] = g.below(4) == 0 ? rounded_to(precision, p + g.uniform(-0.5, 1.5) * (q - p)) : beside(0.2);
  b[2] = beside(0.3);
  const Tri shuffled_a = g.shuffled(a);
  return {shuffled_a, g.shuffled(b)};
}

// A triangle `flatness` · longest² in twice its area: a base of random direction and an apex
// whose foot lies anywhere from half a base before it to half a base past it.
Tri flat_triangle(Random& g, const V& centre, double flatness) {
  const double length = g.uniform(0.5, 2.0);
  const V dir = g.unit_vector();
  const V side(-dir.y(), dir.x());
  const double foot = g.uniform(-0.5, 1.5);
  const double longest = std::max({1.0, std::abs(foot), std::abs(1 - foot)}) * length;
  const double height = flatness * longest * longest / length;
  const V p0 = centre - 0.5 * length * dir;
  return g.shuffled({p0, p0 + length * dir, p0 + foot * length * dir + height * side});
}

RawPair nearly_collinear(Random& g, Precision precision) {
  const double tolerance = precision == Precision::Float ? double(degenerate_tolerance<float>())
                                                         : degenerate_tolerance<double>();
  auto flat = [&](double reach) {
    const V centre = g.point_in(-reach, reach);
    return flat_triangle(g, centre, tolerance * g.log_uniform(-1, 3));
  };
  RawPair p{flat(1), general_b(g)};
  if (g.below(4) == 0) p.b = flat(0.5);
  return p;
}

// The `index`-th pair of class `c` for `precision`, before rounding.
RawPair make_one(InputClass c, Random& g, Precision precision, int index) {
  switch (c) {
    case InputClass::General:
      return general(g);
    case InputClass::Overlapping:
      return general_where(g, penetrating);
    case InputClass::Mixed:
      return mixed(g, index);
    case InputClass::Separated:
      return general_where(g, [](const RawPair& p) { return !penetrating(p) && boxes_overlap(p); });
    case InputClass::Apart:
      return apart(g);
    case InputClass::AxisAligned:
      return axis_aligned(g);
    case InputClass::Sliver:
      return sliver_pair(g);
    case InputClass::NearParallel:
      return near_parallel(g);
    case InputClass::Far:
      return far(g, precision);
    case InputClass::Scale:
      return scaled(g);
    case InputClass::Contained:
      return contained(g);
    case InputClass::Identical:
      return identical(g);
    case InputClass::Touching:
      return touching(g);
    case InputClass::TouchingUlp:
      return touching_ulp(g, precision);
    case InputClass::NearlyCollinear:
      return nearly_collinear(g, precision);
  }
  return general(g);
}

// `count` pairs of class `c` rounded to `precision`, those `keep` accepts.
template <class Keep>
std::vector<RawPair> draw(InputClass c, int count, std::uint64_t seed, Precision precision,
                          Keep keep) {
  Random g(seed * 1000003u + static_cast<std::uint64_t>(c));
  std::vector<RawPair> out;
  out.reserve(static_cast<std::size_t>(count));
  while (static_cast<int>(out.size()) < count) {
    const RawPair p =
        rounded_to(precision, make_one(c, g, precision, static_cast<int>(out.size())));
    if (keep(p)) out.push_back(p);
  }
  return out;
}

}  // namespace

const char* name(InputClass c) {
  switch (c) {
    case InputClass::General:
      return "general";
    case InputClass::Overlapping:
      return "overlapping";
    case InputClass::Mixed:
      return "mixed";
    case InputClass::Separated:
      return "separated";
    case InputClass::Apart:
      return "apart";
    case InputClass::AxisAligned:
      return "axis-aligned";
    case InputClass::Sliver:
      return "sliver";
    case InputClass::NearParallel:
      return "near-parallel";
    case InputClass::Far:
      return "far";
    case InputClass::Scale:
      return "scale";
    case InputClass::Contained:
      return "contained";
    case InputClass::Identical:
      return "identical";
    case InputClass::Touching:
      return "touching";
    case InputClass::TouchingUlp:
      return "touching-ulp";
    case InputClass::NearlyCollinear:
      return "nearly-collinear";
  }
  return "unknown";
}

double max_offset(Precision p) { return p == Precision::Float ? 1e4 : 1e7; }

std::vector<RawPair> make_pairs(InputClass c, int count, std::uint64_t seed, Precision precision) {
  return draw(c, count, seed, precision, [](const RawPair&) { return true; });
}

std::vector<RawPair> make_valid_pairs(InputClass c, int count, std::uint64_t seed) {
  return draw(c, count, seed, Precision::Double,
              [](const RawPair& p) { return valid_in_double(p); });
}

}  // namespace dyop::workloads
