#include "workloads/convex_classes.hpp"

#include <algorithm>
#include <cmath>
#include <type_traits>

#include "dyop/convex_pair.hpp"
#include "workloads/input_classes.hpp"
#include "workloads/random.hpp"

// As in input_classes.cpp, every draw is a statement of its own (or an element of a braced list):
// the order in which a call's arguments are evaluated is up to the compiler, and a seed must give
// the same pairs with any.

namespace dyop::workloads {
namespace {

using V = Vec2<double>;
constexpr double kConvexPi = 3.14159265358979323846;

// `(x, y)` turned by the rotation of cosine `c` and sine `s`.
V turned_by(double c, double s, double x, double y) { return {c * x - s * y, s * x + c * y}; }

// `count` vertices at sorted random angles on an ellipse of semi-axes `size` and `aspect`·`size`
// turned by a random angle about `centre`, counter-clockwise. Points on an ellipse are in strictly
// convex position; angles at least a fifth of the even spacing apart keep every vertex clear of
// its neighbours' line.
RawPolygon on_ellipse(Random& g, const V& centre, double size, double aspect, int count) {
  // A vector, not an array of the largest count: GCC 12 at -O2 with the sanitizers warns that its
  // insertion sort (16 elements unrolled) reads past an 8-element array it never reaches.
  const auto n = static_cast<std::size_t>(count);
  std::vector<double> angle(n);
  for (;;) {
    for (std::size_t i = 0; i < n; ++i) angle[i] = g.uniform(0, 2 * kConvexPi);
    std::sort(angle.begin(), angle.end());
    double least_gap = angle[0] + 2 * kConvexPi - angle[n - 1];
    for (std::size_t i = 1; i < n; ++i) least_gap = std::min(least_gap, angle[i] - angle[i - 1]);
    if (least_gap > 0.2 * 2 * kConvexPi / count) break;
  }
  const double turn = g.uniform(0, 2 * kConvexPi);
  RawPolygon p;
  p.count = count;
  for (std::size_t i = 0; i < n; ++i) {
    p.v[i] = centre + turned_by(std::cos(turn), std::sin(turn), size * std::cos(angle[i]),
                                aspect * size * std::sin(angle[i]));
  }
  return p;
}

// A box as `b2PolygonShape::SetAsBox(hx, hy, centre, angle)` makes it: the corners from (−hx, −hy)
// counter-clockwise, turned by `angle` (0: exactly axis-aligned) and moved to `centre`.
RawPolygon set_as_box(const V& centre, double hx, double hy, double angle) {
  const double c = std::cos(angle);
  const double s = std::sin(angle);
  const V corners[4] = {V(-hx, -hy), V(hx, -hy), V(hx, hy), V(-hx, hy)};
  RawPolygon p;
  p.count = 4;
  for (std::size_t i = 0; i < 4; ++i)
    p.v[i] = centre + turned_by(c, s, corners[i].x(), corners[i].y());
  return p;
}

// A box whose half-widths are `size` times 0.3 to 1 and `aspect` times that, axis-aligned half the
// time.
RawPolygon random_box(Random& g, const V& centre, double size, double aspect) {
  const double hx = size * g.uniform(0.3, 1.0);
  const double hy = aspect * hx;
  const double angle = g.coin() ? 0.0 : g.uniform(0, kConvexPi);
  return set_as_box(centre, hx, hy, angle);
}

// A polygon of about `size` around `centre`: a quarter boxes (`SetAsBox`), the rest 3 to 8
// vertices on an ellipse of aspect 0.3 to 1 in a random winding from a random first vertex.
RawPolygon random_convex(Random& g, const V& centre, double size) {
  if (g.below(4) == 0) {
    const double aspect = g.uniform(0.3, 1.0);
    return random_box(g, centre, size, aspect);
  }
  const int count = 3 + g.below(max_polygon_vertices - 2);
  const double aspect = g.uniform(0.3, 1.0);
  RawPolygon p = on_ellipse(g, centre, size, aspect, count);
  g.shuffle(p.v.data(), count);
  return p;
}

// A thin polygon of length 1 to 2: a third boxes, the rest on an ellipse; aspect 1e-6 to 1e-1.
RawPolygon thin_convex(Random& g, const V& centre) {
  const double aspect = g.log_uniform(-6, -1);
  const double size = g.uniform(0.5, 1.0);
  if (g.below(3) == 0) return random_box(g, centre, size, aspect);
  const int count = 3 + g.below(max_polygon_vertices - 2);
  RawPolygon p = on_ellipse(g, centre, size, aspect, count);
  g.shuffle(p.v.data(), count);
  return p;
}

// A segment between two of `p`'s vertices (a chord, or one of its edges), either way round: a
// segment of about the polygon's size, inside it.
RawPolygon chord_of(Random& g, const RawPolygon& p) {
  const int i = g.below(p.count);
  const int j = (i + 1 + g.below(p.count - 1)) % p.count;
  RawPolygon s;
  s.count = 2;
  s.v[0] = p.v[static_cast<std::size_t>(i)];
  s.v[1] = p.v[static_cast<std::size_t>(j)];
  return s;
}

// A of a pair: `a` itself, or a chord of it for a segment pair.
RawPolygon a_shape(Random& g, const RawPolygon& a, bool segment) {
  return segment ? chord_of(g, a) : a;
}

RawCircle random_circle(Random& g, const V& centre, double size) {
  const double r = size * g.uniform(0.3, 1.0);
  return {centre, r};
}

template <class Pair>
constexpr bool kIsCirclePair = std::is_same_v<Pair, RawCirclePair>;

// B of a general pair: a polygon or a circle of about `size` around `centre`.
template <class Pair>
auto random_b(Random& g, const V& centre, double size) {
  if constexpr (kIsCirclePair<Pair>) {
    return random_circle(g, centre, size);
  } else {
    return random_convex(g, centre, size);
  }
}

// A of size 1 about the origin (a chord of it for a segment pair), B of size 0.3 to 1.5 about a
// point within a unit of it.
template <class Pair>
Pair convex_general(Random& g, bool segment) {
  const RawPolygon a = a_shape(g, random_convex(g, V::Zero(), 1.0), segment);
  const V centre = g.point_in(-1, 1);
  const double size = g.uniform(0.3, 1.5);
  return {a, random_b<Pair>(g, centre, size)};
}

template <class Pair>
Status status_in_double(const Pair& p) {
  if (!valid_in<double>(p)) return Status::Invalid;
  return collide_raw(p, ConvexQuery<double>{Level::Overlap}).status;
}

// The first general pair with status `want` whose boxes meet.
template <class Pair>
Pair convex_general_where(Random& g, Status want, bool segment) {
  for (;;) {
    const Pair p = convex_general<Pair>(g, segment);
    if (status_in_double(p) == want && boxes_meet(bounding_box(p.a), bounding_box(p.b))) return p;
  }
}

// x ↦ scale·x + offset.
RawPolygon convex_moved(RawPolygon p, double scale, const V& offset) {
  for (V& v : p.v) v = scale * v + offset;
  return p;
}
RawCircle convex_moved(const RawCircle& c, double scale, const V& offset) {
  return {scale * c.center + offset, scale * c.radius};
}
template <class Pair>
Pair convex_moved(const Pair& p, double scale, const V& offset) {
  return {convex_moved(p.a, scale, offset), convex_moved(p.b, scale, offset)};
}

V vertex_mean(const RawPolygon& p) {
  V sum = V::Zero();
  for (int i = 0; i < p.count; ++i) sum += p.v[static_cast<std::size_t>(i)];
  return sum / p.count;
}

// `p` shrunk by `k` about `about`.
RawPolygon shrunk_about(const RawPolygon& p, const V& about, double k) {
  return convex_moved(p, k, (1 - k) * about);
}

template <class Pair>
Pair convex_scaled(Random& g, bool segment) {
  Pair p = convex_general<Pair>(g, segment);
  if (g.below(4) == 0) {
    const double k = g.log_uniform(-3, 0);
    if constexpr (kIsCirclePair<Pair>) {
      p.b.radius *= k;
    } else {
      p.b = shrunk_about(p.b, vertex_mean(p.b), k);
    }
  }
  const double scale = g.log_uniform(-6, 6);
  return convex_moved(p, scale, V::Zero());
}

template <class Pair>
Pair convex_far(Random& g, Precision precision, bool segment) {
  const Pair p = convex_general<Pair>(g, segment);
  const double top = std::log10(max_offset(precision));
  const double distance = g.log_uniform(top - 3, top);
  return convex_moved(p, 1.0, distance * g.unit_vector());
}

template <class Pair>
Pair convex_sliver(Random& g, bool segment) {
  if constexpr (kIsCirclePair<Pair>) {
    const RawPolygon a = thin_convex(g, g.point_in(-0.3, 0.3));
    const V centre = g.point_in(-1, 1);
    const double size = g.uniform(0.3, 1.5);
    return {a_shape(g, a, segment), random_circle(g, centre, size)};
  } else {
    const RawPolygon a = random_convex(g, V::Zero(), 1.0);
    Pair p{a, thin_convex(g, g.point_in(-1, 1))};
    if (g.coin()) p.a = thin_convex(g, g.point_in(-0.3, 0.3));
    p.a = a_shape(g, p.a, segment);
    return p;
  }
}

// A dyadic number of 8 fractional bits near `x`: exact in float too, and sums of a few of them are.
double dyadic(double x) { return std::round(x * 256) / 256; }

// A polygon whose top edge runs from (x1, y) to (x0, y), the rest below: a third boxes, the others
// 1 to 6 more vertices on the lower half of the ellipse through both ends, counter-clockwise from
// (x1, y).
RawPolygon flat_topped(Random& g, double x0, double x1, double y) {
  const double depth = g.uniform(0.3, 1.0);
  RawPolygon p;
  if (g.below(3) == 0) {
    p.count = 4;
    p.v[0] = V(x1, y);
    p.v[1] = V(x0, y);
    p.v[2] = V(x0, y - depth);
    p.v[3] = V(x1, y - depth);
    return p;
  }
  const int lower = 1 + g.below(max_polygon_vertices - 2);
  p.count = lower + 2;
  p.v[0] = V(x1, y);
  p.v[1] = V(x0, y);
  const double spacing = kConvexPi / (lower + 1);
  for (int i = 0; i < lower; ++i) {
    const double t = kConvexPi + spacing * (i + 1 + g.uniform(-0.3, 0.3));
    p.v[static_cast<std::size_t>(i + 2)] =
        V(0.5 * (x0 + x1) + 0.5 * (x1 - x0) * std::cos(t), y + depth * std::sin(t));
  }
  return p;
}

// A polygon resting on the line at height `y`, touching it over [x0, x1]: half the time an
// axis-aligned box whose bottom edge overlaps that span (edge on edge), otherwise a random polygon
// whose lowest vertex is on the span (on its ends a quarter of the time: vertex on vertex).
RawPolygon resting_polygon(Random& g, double x0, double x1, double y) {
  double xm = g.uniform(x0, x1);
  if (g.coin()) xm = g.coin() ? x0 : x1;
  if (g.coin()) {
    const double w = g.uniform(0.3, 1.2);
    const double h = g.uniform(0.3, 1.0);
    const double left = xm - w * g.unit();
    RawPolygon p;
    p.count = 4;
    p.v[0] = V(left, y);
    p.v[1] = V(left + w, y);
    p.v[2] = V(left + w, y + h);
    p.v[3] = V(left, y + h);
    return p;
  }
  const double size = g.uniform(0.3, 1.0);
  RawPolygon p = random_convex(g, V::Zero(), size);
  const V lowest = *std::min_element(p.v.begin(), p.v.begin() + p.count,
                                     [](const V& u, const V& w) { return u.y() < w.y(); });
  // The lowest vertex lands on (xm, y) exactly (it moves by 0 from there); the others stay above.
  for (V& v : p.v) v = V(xm + (v.x() - lowest.x()), y + (v.y() - lowest.y()));
  return p;
}

// A circle on the line at height `y` over [x0, x1], or (a quarter) tangent to the polygon at its
// vertex (x1, y) along (3, 4)/5, a direction between the top edge's normal and the next edge's.
// The radius is a multiple of 5/256, so that the centre is exact.
RawCircle resting_circle(Random& g, double x0, double x1, double y) {
  const double r = 5 * std::round(g.uniform(0.2, 1.0) * 256 / 5) / 256;
  if (g.below(4) == 0) return {V(x1 + 0.6 * r, y + 0.8 * r), r};
  const double x = g.uniform(x0, x1);
  return {V(x, y + r), r};
}

V quarter_turns(V v, int turns, const V& shift) {
  for (int t = 0; t < turns; ++t) v = V(-v.y(), v.x());
  return v + shift;
}

// Exactly touching in double and in float: integer or dyadic coordinates where the shapes meet,
// then quarter-turns and an integer shift (both exact). A segment pair's A is the top edge, B on
// its front, or (half the time, the edge given the other way round) on its back.
template <class Pair>
Pair convex_touching(Random& g, bool segment) {
  const double y = std::round(g.uniform(-4, 4));
  const double x0 = dyadic(g.uniform(-1, 0));
  const double x1 = dyadic(g.uniform(0.5, 1.5));
  Pair p;
  p.a = flat_topped(g, x0, x1, y);
  if constexpr (kIsCirclePair<Pair>) {
    p.b = resting_circle(g, x0, x1, y);
  } else {
    p.b = resting_polygon(g, x0, x1, y);
  }
  const int turns = g.below(4);
  const V shift = g.point_in(-8, 8).array().round().matrix();
  for (V& v : p.a.v) v = quarter_turns(v, turns, shift);
  if (segment) {
    p.a.count = 2;  // v[0] = (x1, y), v[1] = (x0, y): the front up, before the turns
    std::fill(p.a.v.begin() + 2, p.a.v.end(), V::Zero());
    if (g.coin()) std::swap(p.a.v[0], p.a.v[1]);
  } else {
    g.shuffle(p.a.v.data(), p.a.count);
  }
  if constexpr (kIsCirclePair<Pair>) {
    p.b.center = quarter_turns(p.b.center, turns, shift);
  } else {
    for (V& v : p.b.v) v = quarter_turns(v, turns, shift);
    g.shuffle(p.b.v.data(), p.b.count);
  }
  return p;
}

// A point of `p`: its vertex mean, one of its vertices, or a point of one of its edges.
V point_of(Random& g, const RawPolygon& p) {
  const int i = g.below(p.count);
  const V& v = p.v[static_cast<std::size_t>(i)];
  switch (g.below(3)) {
    case 0:
      return vertex_mean(p);
    case 1:
      return v;
    default:
      return v + g.uniform(0.2, 0.8) * (p.v[static_cast<std::size_t>((i + 1) % p.count)] - v);
  }
}

// One shape inside the other. A segment pair: a chord of a polygon shrunk inside B, or the
// circle's centre on the segment (a quarter of the time on an end).
template <class Pair>
Pair convex_nested(Random& g, bool segment) {
  const RawPolygon outer = random_convex(g, V::Zero(), 1.0);
  if (segment) {
    if constexpr (kIsCirclePair<Pair>) {
      const RawPolygon s = chord_of(g, outer);
      const double t = g.below(4) == 0 ? 0.0 : g.unit();
      const double r = g.uniform(0.05, 1.5);
      return {s, RawCircle{s.v[0] + t * (s.v[1] - s.v[0]), r}};
    } else {
      // About an inner point: the chord then lies inside B, off its outline.
      const RawPolygon inner = shrunk_about(outer, vertex_mean(outer), g.uniform(0.05, 0.95));
      return {chord_of(g, inner), outer};
    }
  }
  if constexpr (kIsCirclePair<Pair>) {
    // The centre on a vertex a quarter of the time, otherwise a weighted mean of the vertices.
    V centre = outer.v[static_cast<std::size_t>(g.below(outer.count))];
    if (g.below(4) != 0) {
      V sum = V::Zero();
      double total = 0;
      for (int i = 0; i < outer.count; ++i) {
        const double w = g.uniform(0.1, 1.0);
        sum += w * outer.v[static_cast<std::size_t>(i)];
        total += w;
      }
      centre = sum / total;
    }
    const double r = g.uniform(0.05, 1.5);
    return {outer, RawCircle{centre, r}};
  } else {
    const V about = point_of(g, outer);
    const double k = g.uniform(0.05, 0.95);
    Pair p{outer, shrunk_about(outer, about, k)};
    if (g.coin()) std::swap(p.a, p.b);
    return p;
  }
}

// `segment`: A is a segment (2 vertices).
template <class Pair>
Pair make_one_convex(ConvexClass c, Random& g, Precision precision, bool segment) {
  switch (c) {
    case ConvexClass::Overlapping:
      return convex_general_where<Pair>(g, Status::Penetrating, segment);
    case ConvexClass::Separated:
      return convex_general_where<Pair>(g, Status::Separated, segment);
    case ConvexClass::Scale:
      return convex_scaled<Pair>(g, segment);
    case ConvexClass::Far:
      return convex_far<Pair>(g, precision, segment);
    case ConvexClass::Sliver:
      return convex_sliver<Pair>(g, segment);
    case ConvexClass::Touching:
      return convex_touching<Pair>(g, segment);
    case ConvexClass::Nested:
      return convex_nested<Pair>(g, segment);
  }
  return convex_general<Pair>(g, segment);
}

template <class Pair>
std::vector<Pair> draw_convex(ConvexClass c, int count, std::uint64_t seed, Precision precision,
                              bool segment) {
  // Seeds apart from the triangle classes' and between the four kinds of pair.
  const std::uint64_t stream = (kIsCirclePair<Pair> ? 200 : 100) + (segment ? 200 : 0);
  Random g(seed * 1000003u + stream + static_cast<std::uint64_t>(c));
  std::vector<Pair> out;
  out.reserve(static_cast<std::size_t>(count));
  while (static_cast<int>(out.size()) < count) {
    const Pair p = rounded_to(precision, make_one_convex<Pair>(c, g, precision, segment));
    const bool valid = precision == Precision::Float ? valid_in<float>(p) : valid_in<double>(p);
    if (valid) out.push_back(p);
  }
  return out;
}

}  // namespace

const char* name(ConvexClass c) {
  switch (c) {
    case ConvexClass::Overlapping:
      return "overlapping";
    case ConvexClass::Separated:
      return "separated";
    case ConvexClass::Scale:
      return "scale";
    case ConvexClass::Far:
      return "far";
    case ConvexClass::Sliver:
      return "sliver";
    case ConvexClass::Touching:
      return "touching";
    case ConvexClass::Nested:
      return "nested";
  }
  return "unknown";
}

std::vector<RawPolygonPair> make_polygon_pairs(ConvexClass c, int count, std::uint64_t seed,
                                               Precision precision) {
  return draw_convex<RawPolygonPair>(c, count, seed, precision, false);
}

std::vector<RawCirclePair> make_circle_pairs(ConvexClass c, int count, std::uint64_t seed,
                                             Precision precision) {
  return draw_convex<RawCirclePair>(c, count, seed, precision, false);
}

std::vector<RawPolygonPair> make_segment_pairs(ConvexClass c, int count, std::uint64_t seed,
                                               Precision precision) {
  return draw_convex<RawPolygonPair>(c, count, seed, precision, true);
}

std::vector<RawCirclePair> make_segment_circle_pairs(ConvexClass c, int count, std::uint64_t seed,
                                                     Precision precision) {
  return draw_convex<RawCirclePair>(c, count, seed, precision, true);
}

}  // namespace dyop::workloads
