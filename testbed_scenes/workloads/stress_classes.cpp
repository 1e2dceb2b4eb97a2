#include "workloads/stress_classes.hpp"

#include <algorithm>
#include <cmath>

#include "workloads/seeded_random.hpp"

namespace dyop::workloads {
namespace {

using V = Vec2<double>;

using Rng = SeededRandom;

// Through a volatile float: GCC 12.2 at -O2 folds a vectorised double → float → double round trip
// of two coordinates into nothing (wrong code; found here, where the rounding went missing).
double rounded(Precision p, double x) {
  if (p == Precision::Double) return x;
  const volatile float f = static_cast<float>(x);
  return f;
}

V rounded(Precision p, const V& v) { return {rounded(p, v.x()), rounded(p, v.y())}; }

// The next value of `x` in precision `p`, `steps` ulps towards +infinity (negative: towards -inf).
double ulps_away(Precision p, double x, int steps) {
  for (; steps > 0; --steps) {
    x = p == Precision::Float ? double(std::nextafter(float(x), INFINITY)) : std::nextafter(x, INFINITY);
  }
  for (; steps < 0; ++steps) {
    x = p == Precision::Float ? double(std::nextafter(float(x), -INFINITY))
                              : std::nextafter(x, -INFINITY);
  }
  return x;
}

RawPair moved(const RawPair& p, double scale, const V& offset) {
  RawPair out = p;
  for (V& v : out.a) v = scale * v + offset;
  for (V& v : out.b) v = scale * v + offset;
  return out;
}

V centroid(const std::array<V, 3>& t) { return (t[0] + t[1] + t[2]) / 3.0; }

std::array<V, 3> shrunk(const std::array<V, 3>& t, const V& about, double k) {
  return {about + k * (t[0] - about), about + k * (t[1] - about), about + k * (t[2] - about)};
}

RawPair scale_pair(Rng& g, RawPair p) {
  if (g.below(4) == 0) p.b = shrunk(p.b, centroid(p.b), g.log_uniform(-6, 0));
  return moved(p, g.log_uniform(-8, 8), V::Zero());
}

// B's vertex on A's edge, computed from A as the precision holds it and rounded, so it lies within
// an ulp of the edge's line; then 0 to 2 ulps further, in or out. A quarter of the time B's next
// vertex is on the same line too (edge on edge). Half the pairs sit up to 1e3 (float: 10) units
// from the origin, where an ulp is a larger fraction of the pair.
RawPair touching_ulp(Rng& g, Precision precision, const RawPair& base) {
  const double far = precision == Precision::Float ? 1 : 3;
  V shift = V::Zero();
  if (g.coin()) shift = g.log_uniform(0, far) * g.unit_vector();
  std::array<V, 3> a;
  for (int i = 0; i < 3; ++i) a[i] = rounded(precision, base.a[i] + shift);
  const int i = g.below(3);
  const V& p = a[i];
  const V& q = a[(i + 1) % 3];
  const V& r = a[(i + 2) % 3];
  const V e = (q - p).normalized();
  V out(e.y(), -e.x());
  if (out.dot(r - p) > 0) out = -out;
  V x = rounded(precision, p + g.uniform(0.05, 0.95) * (q - p));
  const int axis = std::abs(out.x()) > std::abs(out.y()) ? 0 : 1;
  x[axis] = ulps_away(precision, x[axis], (g.below(5) - 2) * (out[axis] > 0 ? 1 : -1));
  const double length = g.uniform(0.3, 1.2) * (q - p).norm();
  std::array<V, 3> b;
  b[0] = x;
  if (g.below(4) == 0) {
    b[1] = rounded(precision, p + g.uniform(-0.5, 1.5) * (q - p));
  } else {
    b[1] = rounded(precision, x + length * (g.uniform(0.2, 1.0) * out + g.uniform(-1, 1) * e));
  }
  b[2] = rounded(precision, x + length * (g.uniform(0.3, 1.0) * out + g.uniform(-1, 1) * e));
  return {g.shuffled(a), g.shuffled(b)};
}

// One triangle inside the other: shrunk about the centroid, about a vertex (a shared vertex and
// two edges on one line each) or about a point of an edge (an edge on the other's edge line).
RawPair contained(Rng& g, const RawPair& base) {
  const std::array<V, 3>& outer = base.a;
  const double k = g.uniform(0.05, 0.95);
  V about;
  switch (g.below(3)) {
    case 0: about = centroid(outer); break;
    case 1: about = outer[g.below(3)]; break;
    default: {
      const int i = g.below(3);
      about = outer[i] + g.uniform(0.2, 0.8) * (outer[(i + 1) % 3] - outer[i]);
    }
  }
  RawPair p{g.shuffled(outer), g.shuffled(shrunk(outer, about, k))};
  if (g.coin()) std::swap(p.a, p.b);
  return p;
}

// A triangle `flatness` · longest² in twice its area: a base of random direction and an apex
// whose foot lies anywhere from half a base before it to half a base past it.
std::array<V, 3> flat_triangle(Rng& g, const V& centre, double flatness) {
  const double length = g.uniform(0.5, 2.0);
  const V dir = g.unit_vector();
  const V side(-dir.y(), dir.x());
  const double foot = g.uniform(-0.5, 1.5);
  const double longest = std::max({1.0, std::abs(foot), std::abs(1 - foot)}) * length;
  const double height = flatness * longest * longest / length;
  const V p0 = centre - 0.5 * length * dir;
  return g.shuffled({p0, p0 + length * dir, p0 + foot * length * dir + height * side});
}

RawPair nearly_collinear(Rng& g, Precision precision, const RawPair& base) {
  const double tolerance = precision == Precision::Float ? double(degenerate_tolerance<float>())
                                                         : degenerate_tolerance<double>();
  auto flat = [&](const V& centre) {
    return flat_triangle(g, centre, tolerance * g.log_uniform(-1, 3));
  };
  RawPair p{flat(V(g.uniform(-1, 1), g.uniform(-1, 1))), base.b};
  if (g.below(4) == 0) p.b = flat(V(g.uniform(-0.5, 0.5), g.uniform(-0.5, 0.5)));
  return p;
}

}  // namespace

const char* name(StressClass c) {
  switch (c) {
    case StressClass::Sliver: return "sliver";
    case StressClass::NearParallel: return "near-parallel";
    case StressClass::AxisAligned: return "axis-aligned";
    case StressClass::Scale: return "scale";
    case StressClass::Offset: return "offset";
    case StressClass::TouchingUlp: return "touching-ulp";
    case StressClass::Identical: return "identical";
    case StressClass::Contained: return "contained";
    case StressClass::NearlyCollinear: return "nearly-collinear";
  }
  return "unknown";
}

const char* name(Precision p) { return p == Precision::Float ? "float" : "double"; }

double max_offset(Precision p) { return p == Precision::Float ? 1e4 : 1e7; }

RawPair rounded_to_float(const RawPair& p) { return rounded_to(Precision::Float, p); }

RawPair rounded_to(Precision precision, const RawPair& p) {
  RawPair out = p;
  for (auto* t : {&out.a, &out.b}) {
    for (V& v : *t) v = rounded(precision, v);
  }
  return out;
}

std::vector<RawPair> make_stress_pairs(StressClass c, Precision precision, int count,
                                       std::uint64_t seed) {
  const std::uint64_t mixed = seed * 1000033u + static_cast<std::uint64_t>(c);
  // Classes that the shared generators already make, as they make them.
  switch (c) {
    case StressClass::Sliver:
    case StressClass::NearParallel:
    case StressClass::AxisAligned:
    case StressClass::Identical: {
      const PairClass same = c == StressClass::Sliver         ? PairClass::Sliver
                             : c == StressClass::NearParallel ? PairClass::NearParallel
                             : c == StressClass::AxisAligned  ? PairClass::AxisAligned
                                                              : PairClass::Identical;
      std::vector<RawPair> out = make_pairs(same, count, mixed);
      for (RawPair& p : out) p = rounded_to(precision, p);
      return out;
    }
    default: break;
  }
  // The others are built on general pairs (random triangles of size about 1 near the origin).
  Rng g(mixed);
  std::vector<RawPair> out;
  out.reserve(static_cast<std::size_t>(count));
  for (const RawPair& base : make_pairs(PairClass::General, count, mixed)) {
    RawPair p = base;
    switch (c) {
      case StressClass::Scale: p = scale_pair(g, base); break;
      case StressClass::Offset:
        p = moved(base, 1.0, g.log_uniform(0, std::log10(max_offset(precision))) * g.unit_vector());
        break;
      case StressClass::TouchingUlp: p = touching_ulp(g, precision, base); break;
      case StressClass::Contained: p = contained(g, base); break;
      case StressClass::NearlyCollinear: p = nearly_collinear(g, precision, base); break;
      default: break;
    }
    out.push_back(rounded_to(precision, p));
  }
  return out;
}

}  // namespace dyop::workloads
