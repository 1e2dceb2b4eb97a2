#include "workloads/pair_classes.hpp"

#include <algorithm>
#include <cmath>

#include "workloads/seeded_random.hpp"

namespace dyop::workloads {
namespace {

using V = Vec2<double>;

using Gen = SeededRandom;

bool valid(const std::array<V, 3>& t) { return Triangle<double>::make(t[0], t[1], t[2]).ok(); }

// A random non-degenerate triangle of about `size` around `centre`, random winding.
std::array<V, 3> random_triangle(Gen& g, const V& centre, double size) {
  for (;;) {
    std::array<V, 3> t;
    for (V& v : t) v = centre + size * g.uniform(0.3, 1.0) * g.unit_vector();
    if (valid(t) && std::abs((t[1] - t[0]).x() * (t[2] - t[0]).y() -
                             (t[1] - t[0]).y() * (t[2] - t[0]).x()) > 0.05 * size * size) {
      return t;
    }
  }
}

RawPair general(Gen& g) {
  return {random_triangle(g, V::Zero(), 1.0),
          random_triangle(g, V(g.uniform(-1, 1), g.uniform(-1, 1)), g.uniform(0.3, 1.5))};
}

// A right triangle with axis-parallel legs, corner at c, legs w (along x) and h (along y).
std::array<V, 3> right_triangle(Gen& g, const V& c, double w, double h) {
  return g.shuffled({c, c + V(w, 0), c + V(0, h)});
}

RawPair axis_aligned(Gen& g) {
  auto leg = [&] { return (g.coin() ? 1.0 : -1.0) * g.uniform(0.3, 1.5); };
  const V c(g.uniform(-1, 1), g.uniform(-1, 1));
  // Half the time B's corner shares a coordinate with A's, so edges lie on one line.
  V d(g.uniform(-1, 1), g.uniform(-1, 1));
  if (g.coin()) d[g.below(2)] = 0;
  return {right_triangle(g, c, leg(), leg()), right_triangle(g, c + d, leg(), leg())};
}

std::array<V, 3> sliver(Gen& g, const V& centre) {
  const double aspect = g.log_uniform(-7, -1);
  const V dir = g.unit_vector();
  const V side(-dir.y(), dir.x());
  const double length = g.uniform(0.5, 2.0);
  const V p0 = centre - 0.5 * length * dir;
  const V p1 = centre + 0.5 * length * dir;
  const V p2 = centre + g.uniform(-0.4, 0.4) * length * dir + aspect * length * side;
  return g.shuffled({p0, p1, p2});
}

RawPair sliver_pair(Gen& g) {
  for (;;) {
    RawPair p{random_triangle(g, V::Zero(), 1.0), sliver(g, V(g.uniform(-1, 1), g.uniform(-1, 1)))};
    if (g.coin()) p.a = sliver(g, V(g.uniform(-0.3, 0.3), g.uniform(-0.3, 0.3)));
    if (valid(p.a) && valid(p.b)) return p;
  }
}

// B has an edge at a tiny angle to one of A's edges, just inside or just outside it.
RawPair near_parallel(Gen& g) {
  for (;;) {
    const std::array<V, 3> a = random_triangle(g, V::Zero(), 1.0);
    const int i = g.below(3);
    const V p = a[i];
    const V q = a[(i + 1) % 3];
    const V r = a[(i + 2) % 3];
    const V e = (q - p).normalized();
    V out(e.y(), -e.x());
    if (out.dot(r - p) > 0) out = -out;  // pointing away from A's third vertex
    const double angle = (g.coin() ? 1 : -1) * g.log_uniform(-14, -3);
    const V f(std::cos(angle) * e.x() - std::sin(angle) * e.y(),
              std::sin(angle) * e.x() + std::cos(angle) * e.y());
    const V start = p + g.uniform(-0.2, 0.5) * (q - p) + g.uniform(-1e-3, 1e-3) * out;
    const double length = g.uniform(0.3, 1.2);
    const V apex = start + 0.5 * length * f + g.uniform(0.3, 1.0) * out;
    RawPair pair{g.shuffled(a), g.shuffled({start, start + length * f, apex})};
    if (valid(pair.b)) return pair;
  }
}

RawPair scaled(const RawPair& p, double s, const V& offset) {
  RawPair out = p;
  for (V& v : out.a) v = s * v + offset;
  for (V& v : out.b) v = s * v + offset;
  return out;
}

RawPair containment(Gen& g) {
  const std::array<V, 3> outer = random_triangle(g, V::Zero(), 1.0);
  const V centroid = (outer[0] + outer[1] + outer[2]) / 3.0;
  const double k = g.uniform(0.1, 0.9);
  std::array<V, 3> inner;
  for (int i = 0; i < 3; ++i) inner[i] = centroid + k * (outer[i] - centroid);
  RawPair p{outer, g.shuffled(inner)};
  if (g.coin()) std::swap(p.a, p.b);
  return p;
}

// Exactly touching in double: a horizontal edge of A at height y0 and B resting on it, with a
// vertex on the edge or vertex on vertex; then a quarter-turn (exact) and an integer shift (exact).
RawPair touching(Gen& g) {
  const double y0 = std::round(g.uniform(-4, 4));
  const double x0 = g.uniform(-1, 0);
  const double x1 = g.uniform(0.5, 1.5);
  std::array<V, 3> a{V(x0, y0), V(x1, y0), V(g.uniform(x0, x1), y0 - g.uniform(0.3, 1.0))};
  const double xm = g.coin() ? g.uniform(x0, x1) : (g.coin() ? x0 : x1);
  std::array<V, 3> b{V(xm, y0), V(xm + g.uniform(-1, 1), y0 + g.uniform(0.3, 1.0)),
                     V(xm + g.uniform(-1, 1), y0 + g.uniform(0.3, 1.0))};
  if (g.coin()) b[1].y() = y0;  // edge on edge half of the time when B also has a flat bottom
  const int turns = g.below(4);
  const V shift(std::round(g.uniform(-8, 8)), std::round(g.uniform(-8, 8)));
  auto turn = [&](V v) {
    for (int t = 0; t < turns; ++t) v = V(-v.y(), v.x());
    return v + shift;
  };
  for (V& v : a) v = turn(v);
  for (V& v : b) v = turn(v);
  return {g.shuffled(a), g.shuffled(b)};
}

RawPair apart(Gen& g) {
  const V dir = g.unit_vector();
  return {random_triangle(g, V::Zero(), 1.0),
          random_triangle(g, g.uniform(2.5, 10.0) * dir, g.uniform(0.3, 1.5))};
}

RawPair make_one(PairClass c, Gen& g) {
  switch (c) {
    case PairClass::General: return general(g);
    case PairClass::AxisAligned: return axis_aligned(g);
    case PairClass::Sliver: return sliver_pair(g);
    case PairClass::NearParallel: return near_parallel(g);
    case PairClass::FarFromOrigin:
      return scaled(general(g), 1.0, g.log_uniform(0, 6) * g.unit_vector());
    case PairClass::TinyAndHuge: return scaled(general(g), g.log_uniform(-6, 6), V::Zero());
    case PairClass::Containment: return containment(g);
    case PairClass::Identical: {
      const std::array<V, 3> t = random_triangle(g, V(g.uniform(-2, 2), g.uniform(-2, 2)), 1.0);
      return {t, g.shuffled(t)};
    }
    case PairClass::Touching: return touching(g);
    case PairClass::Apart: return apart(g);
  }
  return general(g);
}

}  // namespace

const char* name(PairClass c) {
  switch (c) {
    case PairClass::General: return "general";
    case PairClass::AxisAligned: return "axis-aligned";
    case PairClass::Sliver: return "sliver";
    case PairClass::NearParallel: return "near-parallel";
    case PairClass::FarFromOrigin: return "far-from-origin";
    case PairClass::TinyAndHuge: return "tiny-and-huge";
    case PairClass::Containment: return "containment";
    case PairClass::Identical: return "identical";
    case PairClass::Touching: return "touching";
    case PairClass::Apart: return "apart";
  }
  return "unknown";
}

std::vector<RawPair> make_pairs(PairClass c, int count, std::uint64_t seed) {
  Gen g(seed * 1000003u + static_cast<std::uint64_t>(c));
  std::vector<RawPair> out;
  out.reserve(static_cast<std::size_t>(count));
  while (static_cast<int>(out.size()) < count) {
    RawPair p = make_one(c, g);
    if (valid(p.a) && valid(p.b)) out.push_back(p);
  }
  return out;
}

PairBox pair_box(const RawPair& p) {
  PairBox box{p.a[0], p.a[0]};
  for (const auto* t : {&p.a, &p.b}) {
    for (const V& v : *t) {
      box.lo = box.lo.cwiseMin(v);
      box.hi = box.hi.cwiseMax(v);
    }
  }
  return box;
}

double pair_size(const RawPair& p) {
  const PairBox box = pair_box(p);
  return (box.hi - box.lo).norm();
}

}  // namespace dyop::workloads
