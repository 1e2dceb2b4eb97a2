// The convex pairs beyond two triangles (`collide`: polygon–polygon and polygon–circle, and the
// same with A a segment) against the exact rational reference, per convex input class and
// precision: the separation within the
// exact bound of the pair's size, the status, the normal, the manifold's points and the answer's
// independence from winding. The error figures are recorded as test properties
// (`--gtest_output=xml:FILE` shows them).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <initializer_list>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

#include "dyop/convex_pair.hpp"
#include "exact_reference/exact_reference.hpp"
#include "support/result_checks.hpp"
#include "workloads/convex_classes.hpp"

namespace dyop::workloads {
namespace {

constexpr int kConvexPairsPerClass = 1000;
constexpr std::uint64_t kConvexSeed = 45;
// The manifold's margin relative to the pair's size: Box2D's two polygon skins (2 × 0.01 m) on a
// pair about a metre across.
constexpr double kConvexMarginPerSize = 0.02;

template <class Pair>
constexpr bool kCirclePair = std::is_same_v<Pair, RawCirclePair>;

template <class Pair>
const char* kind_name() {
  return kCirclePair<Pair> ? "polygon-circle" : "polygon-polygon";
}

// A's kind in a class's name: its pairs' `kind_name`, or with A a segment.
template <class Pair>
const char* kind_name(bool segment) {
  if (!segment) return kind_name<Pair>();
  return kCirclePair<Pair> ? "segment-circle" : "segment-polygon";
}

template <class T>
const char* scalar_name() {
  return name(precision_of<T>());
}

// The class's pairs; `segment`: with A a segment.
template <class T, class Pair>
std::vector<Pair> convex_pairs(ConvexClass c, bool segment = false) {
  const Precision precision = precision_of<T>();
  if constexpr (kCirclePair<Pair>) {
    return segment ? make_segment_circle_pairs(c, kConvexPairsPerClass, kConvexSeed, precision)
                   : make_circle_pairs(c, kConvexPairsPerClass, kConvexSeed, precision);
  } else {
    return segment ? make_segment_pairs(c, kConvexPairsPerClass, kConvexSeed, precision)
                   : make_polygon_pairs(c, kConvexPairsPerClass, kConvexSeed, precision);
  }
}

template <class T, class Pair>
Result<T> solve(const Pair& p, const ConvexQuery<T>& q) {
  EXPECT_TRUE(valid_in<T>(p));
  return collide_raw(p, q);
}

// The pair's numbers, to replay a failure.
std::string spelled(const RawPolygon& p) {
  std::string s = "{";
  char buf[64];
  for (int i = 0; i < p.count; ++i) {
    const Vec2<double>& v = p.v[static_cast<std::size_t>(i)];
    std::snprintf(buf, sizeof buf, "%s(%.17g, %.17g)", i ? ", " : "", v.x(), v.y());
    s += buf;
  }
  return s + "}";
}
std::string spelled(const RawPolygonPair& p) { return spelled(p.a) + " " + spelled(p.b); }
std::string spelled(const RawCirclePair& p) {
  char buf[96];
  std::snprintf(buf, sizeof buf, " centre (%.17g, %.17g) radius %.17g", p.b.center.x(),
                p.b.center.y(), p.b.radius);
  return spelled(p.a) + buf;
}

// The status band: 4 touching tolerances of the pair's size, as the triangle pairs' accuracy test
// takes it. The solver's band is one tolerance of the larger shape, never more than the pair's
// size; four leave room for the separation's own rounding.
template <class T>
double status_band(double size) {
  return 4 * double(touching_tolerance<T>()) * size;
}

Status exact_status(int sign) {
  return sign < 0 ? Status::Penetrating : sign > 0 ? Status::Separated : Status::Touching;
}

// A class's tally: how many pairs, how many broke the property, the first that did, the worst
// error (relative to the pair's size) when the check measures one, and the exact signs met.
struct Tally {
  int pairs = 0;
  int failures = 0;
  std::string first_failure;
  double worst = 0;
  int signs[3] = {0, 0, 0};  // penetrating, touching, apart
  bool measured = false;     // `worst` is an error this check measures

  void measure(double error) {
    measured = true;
    worst = std::max(worst, error);
  }

  template <class Pair>
  void fail(const Pair& p, const std::string& what) {
    if (failures++ == 0) first_failure = what + " on " + spelled(p);
  }
  std::string figures() const {
    std::ostringstream s;
    s << "pairs " << pairs << " (penetrating " << signs[0] << ", touching " << signs[1]
      << ", apart " << signs[2] << ")";
    if (measured) s << ", max |error|/size " << worst;
    return s.str();
  }
};

// Runs `check(class, pair, exact, size, tally)` on every pair of every class, A a polygon and A a
// segment, expects no failure and records each class's figures under `property`.
template <class T, class Pair, class Check>
void over_every_class(const char* property, Check check) {
  for (const bool segment : {false, true}) {
    for (ConvexClass c : convex_classes) {
      Tally tally;
      for (const Pair& p : convex_pairs<T, Pair>(c, segment)) {
        const ExactAnswer exact = exact_separation(p);
        ++tally.pairs;
        ++tally.signs[exact.sign + 1];
        check(c, p, exact, pair_size(p), tally);
      }
      const std::string where =
          std::string(kind_name<Pair>(segment)) + "." + scalar_name<T>() + "." + name(c);
      EXPECT_EQ(tally.failures, 0) << where << ": first " << tally.first_failure;
      ::testing::Test::RecordProperty(std::string(property) + "." + where, tally.figures());
    }
  }
}

// Each test runs on both kinds of pair in both precisions.
template <class Scalar, class PairType>
struct Combo {
  using T = Scalar;
  using Pair = PairType;
};
using ConvexCombos = ::testing::Types<Combo<double, RawPolygonPair>, Combo<double, RawCirclePair>,
                                      Combo<float, RawPolygonPair>, Combo<float, RawCirclePair>>;
struct ComboNames {
  template <class C>
  static std::string GetName(int) {
    std::string n = std::string(scalar_name<typename C::T>()) + "_" + kind_name<typename C::Pair>();
    std::replace(n.begin(), n.end(), '-', '_');
    return n;
  }
};

template <class C>
class ConvexPairAccuracy : public ::testing::Test {};
TYPED_TEST_SUITE(ConvexPairAccuracy, ConvexCombos, ComboNames);

template <class C>
class ConvexInputClasses : public ::testing::Test {};
TYPED_TEST_SUITE(ConvexInputClasses, ConvexCombos, ComboNames);

template <class T, class Pair>
void expect_separation_within_exact_bound() {
  const double bound = exact_bound(precision_of<T>());
  over_every_class<T, Pair>("separation", [&](ConvexClass, const Pair& p, const ExactAnswer& exact,
                                              double size, Tally& tally) {
    const Result<T> r = solve<T>(p, ConvexQuery<T>{Level::Depth});
    const double error = std::abs(double(r.separation) - exact.separation) / size;
    tally.measure(error);
    if (!(error <= bound)) {
      tally.fail(p, "separation " + std::to_string(double(r.separation)) + ", exact " +
                        std::to_string(exact.separation));
    }
  });
}

// Double within 1e-12 of the pair's size; float, on input rounded to float, within the triangle
// pairs' bound (`exact_bound`: 1e-5).
TYPED_TEST(ConvexPairAccuracy, SeparationWithinTheTrianglePairsExactBoundInEveryClass) {
  expect_separation_within_exact_bound<typename TypeParam::T, typename TypeParam::Pair>();
}

// Outside the band the status is the exact sign's; inside it, Touching or the exact sign's; an
// exact contact is Touching.
template <class T, class Pair>
void expect_exact_status() {
  over_every_class<T, Pair>("status", [&](ConvexClass, const Pair& p, const ExactAnswer& exact,
                                          double size, Tally& tally) {
    const Status got = solve<T>(p, ConvexQuery<T>{Level::Overlap}).status;
    const Status want = exact_status(exact.sign);
    const bool in_band = std::abs(exact.separation) <= status_band<T>(size);
    const bool ok = got == want || (in_band && exact.sign != 0 && got == Status::Touching);
    if (!ok) {
      tally.fail(p, "status " + std::to_string(int(got)) + ", exact sign " +
                        std::to_string(exact.sign) + ", exact separation " +
                        std::to_string(exact.separation));
    }
  });
}

TYPED_TEST(ConvexPairAccuracy, StatusIsTheExactSignOutsideTheTouchingBandAndExactContactTouches) {
  expect_exact_status<typename TypeParam::T, typename TypeParam::Pair>();
}

// `p` in a frame on A's first vertex, B moved by `offset` in it: the move adds no rounding of the
// pair's distance from the origin (a far pair's coordinates near 1e7 have an ulp of 2e-9).
RawPolygonPair local_with_b_moved(const RawPolygonPair& p, const Vec2<double>& offset) {
  RawPolygonPair out = p;
  const Vec2<double> origin = p.a.v[0];
  for (int i = 0; i < p.a.count; ++i) out.a.v[static_cast<std::size_t>(i)] -= origin;
  for (int i = 0; i < p.b.count; ++i) {
    Vec2<double>& v = out.b.v[static_cast<std::size_t>(i)];
    v = (v - origin) + offset;
  }
  return out;
}
RawCirclePair local_with_b_moved(const RawCirclePair& p, const Vec2<double>& offset) {
  RawCirclePair out = p;
  const Vec2<double> origin = p.a.v[0];
  for (int i = 0; i < p.a.count; ++i) out.a.v[static_cast<std::size_t>(i)] -= origin;
  out.b.center = (p.b.center - origin) + offset;
  return out;
}

// The normal is unit, and B moved by −separation · normal (penetrating: depth · normal, out; apart:
// the distance back along it) touches A: the exact separation after the move is zero within the
// exact bound. A wrong axis or direction leaves the pair overlapping or apart.
template <class T, class Pair>
void expect_normal_unit_and_consistent() {
  const double bound = exact_bound(precision_of<T>());
  const double unit_tolerance = double(test_support::tol<T>());
  over_every_class<T, Pair>("normal", [&](ConvexClass, const Pair& p, const ExactAnswer&,
                                          double size, Tally& tally) {
    const Result<T> r = solve<T>(p, ConvexQuery<T>{Level::Depth});
    const Vec2<double> n(double(r.normal.x()), double(r.normal.y()));
    if (!(std::abs(n.norm() - 1) <= unit_tolerance)) {
      tally.fail(p, "normal of length " + std::to_string(n.norm()));
      return;
    }
    const ExactAnswer after = exact_separation(local_with_b_moved(p, -double(r.separation) * n));
    const double error = std::abs(after.separation) / size;
    tally.measure(error);
    if (!(error <= bound)) {
      tally.fail(p, "after the move the exact separation is " + std::to_string(after.separation));
    }
  });
}

TYPED_TEST(ConvexPairAccuracy, NormalIsUnitAndMovingBAlongItBringsTheExactSeparationToZero) {
  expect_normal_unit_and_consistent<typename TypeParam::T, typename TypeParam::Pair>();
}

// The gap along the pair's best axis, exactly: minus the least overlap over both shapes' edge
// normals (a circle pair: its exact distance, which its reference face's normal measures).
double exact_axis_gap(const RawPolygonPair& p) {
  double least = HUGE_VAL;
  for (const bool of_a : {true, false}) {
    for (int e = 0; e < (of_a ? p.a.count : p.b.count); ++e) {
      least = std::min(least, exact_edge_overlap(p, of_a, e));
    }
  }
  return -least;
}
double exact_axis_gap(const RawCirclePair& p) { return exact_separation(p).separation; }

// At Level::Manifold with a margin: at most two points (a circle: one), each within the margin and
// no deeper than the pair (the reference face is the least axis: hysteresis 0); a pair penetrating
// beyond the band has a point, a pair apart along its best axis beyond the margin none (apart by
// less along it, speculative points may lie beyond the margin from the other shape's corner, as
// Box2D's do); the manifold's normal is unit.
template <class T, class Pair>
void expect_manifold_within_margin() {
  const double bound = exact_bound(precision_of<T>());
  over_every_class<T, Pair>("manifold", [&](ConvexClass, const Pair& p, const ExactAnswer& exact,
                                            double size, Tally& tally) {
    ConvexQuery<T> q{Level::Manifold};
    q.margin = T(kConvexMarginPerSize * size);
    const Result<T> r = solve<T>(p, q);
    const Manifold<T>& m = r.manifold;
    const double tolerance = bound * size;
    const double band = status_band<T>(size);
    const int most = kCirclePair<Pair> ? 1 : 2;
    if (m.point_count < 0 || m.point_count > most) {
      tally.fail(p, std::to_string(m.point_count) + " points");
      return;
    }
    if (exact.separation < -band && m.point_count == 0) tally.fail(p, "penetrating, no point");
    if (exact.separation > double(q.margin) + band && m.point_count != 0 &&
        exact_axis_gap(p) > double(q.margin) + band) {
      tally.fail(p, "apart beyond the margin, with points");
    }
    if (m.point_count > 0 && !(std::abs(double(m.normal.norm()) - 1) <= 1e-5)) {
      tally.fail(p, "manifold normal not unit");
    }
    for (int i = 0; i < m.point_count; ++i) {
      const double s = double(m.points[static_cast<std::size_t>(i)].separation);
      tally.measure(std::max(0.0, std::min(exact.separation, 0.0) - s) / size);
      if (s > double(q.margin) + tolerance) {
        tally.fail(p, "point beyond the margin: " + std::to_string(s));
      }
      if (s < std::min(exact.separation, 0.0) - tolerance) {
        tally.fail(p, "point deeper than the pair: " + std::to_string(s) + ", exact " +
                          std::to_string(exact.separation));
      }
    }
  });
}

TYPED_TEST(ConvexPairAccuracy, ManifoldPointsLieWithinTheMarginAndNoDeeperThanThePair) {
  expect_manifold_within_margin<typename TypeParam::T, typename TypeParam::Pair>();
}

// A circle centre at distance 0 from a vertex as T computes it, where `collide` took the centre
// for one outside, nearest that vertex, and divided by the distance (a NaN or infinite normal). The
// nested class found the first (the centre on A's vertex 2, which rounding puts a hair outside the
// line of the edge ending there), fuzz_convex the others (a centre 3.8e-270 from A's vertex 0,
// whose square underflows; a centre 7.4e6 from A's vertex 2 in a triangle of size 8e136, the same
// point in the frame on A's vertex 0). Exact answer: the separation and a unit normal that moves
// the circle clear.
TEST(ConvexPairRegression, CircleCentredOnAVertexGetsAUnitNormal) {
  const auto triangle_or_pentagon = [](std::initializer_list<Vec2<double>> points) {
    RawPolygon a;
    for (const Vec2<double>& v : points) a.v[static_cast<std::size_t>(a.count++)] = v;
    return a;
  };
  const RawCirclePair pairs[] = {
      {triangle_or_pentagon({{-0.091678444619576249, 0.99576171284801929},
                             {0.4206529926796051, 0.78780345723685474},
                             {0.70446939409688425, 0.26522967083317373},
                             {-0.47929728392457294, -0.72343504612692933},
                             {-0.3507104674979124, 0.90678761144236664}}),
       RawCircle{{0.70446939409688425, 0.26522967083317373}, 1.1732167951305705}},
      {triangle_or_pentagon({{5.840959477380826e-308, 3.7857679388292641e-270},
                             {4.7641351903414685e-308, 1.817901781506239e-130},
                             {1.817901558950338e-130, 1.4190125215845418e-312}}),
       RawCircle{{4.7641351902119601e-308, 3.632672055258255e-310}, 136908592157728}},
      {triangle_or_pentagon({{8.2454865162444373e+136, 8.2454953887874585e+136},
                             {8.2454865162444373e+136, 8.2454865162444373e+136},
                             {7434609.4431372546, 1.0576403555761307e-307}}),
       RawCircle{{4.7876742615803951e-299, 2.5915867606650499e-318}, 8.2454865162200154e+136}},
  };
  for (const RawCirclePair& p : pairs) {
    const Result<double> r = solve<double>(p, ConvexQuery<double>{Level::Manifold});
    const double size = pair_size(p);
    EXPECT_NEAR(r.separation, exact_separation(p).separation,
                exact_bound(Precision::Double) * size);
    EXPECT_NEAR(r.normal.norm(), 1.0, test_support::tol<double>()) << spelled(p);
    EXPECT_EQ(r.manifold.point_count, 1);
    EXPECT_TRUE(r.manifold.points[0].point.allFinite());
    if (!r.normal.allFinite()) continue;  // the exact reference takes no NaN
    const ExactAnswer after = exact_separation(local_with_b_moved(p, -r.separation * r.normal));
    EXPECT_NEAR(after.separation, 0.0, exact_bound(Precision::Double) * size);
  }
}

// The distance from `c` to the segment from `p` to `q` (double: only to tell whether a circle
// clearly reaches an edge).
double segment_distance(const Vec2<double>& c, const Vec2<double>& p, const Vec2<double>& q) {
  const Vec2<double> e = q - p;
  const double t = std::clamp((c - p).dot(e) / e.squaredNorm(), 0.0, 1.0);
  return (c - (p + t * e)).norm();
}

// The internal-edge rule on a circle centred inside the polygon, every edge of A internal but one,
// k. The push is along k's normal by the circle's exact overlap past k's line
// (`exact_edge_overlap`) when k is the plain answer's face (the least overlap) or the circle
// reaches k; otherwise no allowed face is usable: the plain separation and no manifold point.
// Pairs within a hair of a tie or of reaching k are passed by (which side they fall on is
// rounding).
template <class T>
void expect_masked_circle_pushed_along_the_allowed_face() {
  const double bound = exact_bound(precision_of<T>());
  int replaced = 0;
  int unusable = 0;
  int k = 0;
  for (const RawCirclePair& p : convex_pairs<T, RawCirclePair>(ConvexClass::Nested)) {
    k = (k + 1) % p.a.count;
    const double size = pair_size(p);
    const double hair = 1e-6 * size;
    const double gap = segment_distance(p.b.center, p.a.v[static_cast<std::size_t>(k)],
                                        p.a.v[static_cast<std::size_t>((k + 1) % p.a.count)]) -
                       p.b.radius;
    const double along_k = exact_edge_overlap(p, k);
    double least_other = HUGE_VAL;
    for (int e = 0; e < p.a.count; ++e) {
      if (e != k) least_other = std::min(least_other, exact_edge_overlap(p, e));
    }
    if (std::abs(gap) < hair || std::abs(along_k - least_other) < hair) continue;
    const bool usable = along_k < least_other || gap < 0;
    ConvexQuery<T> q{Level::Manifold};
    q.masks_a.edges = static_cast<std::uint8_t>(((1u << p.a.count) - 1) & ~(1u << k));
    const Result<T> r = solve<T>(p, q);
    const double want = usable ? -along_k : exact_separation(p).separation;
    EXPECT_NEAR(double(r.separation), want, bound * size)
        << "allowed edge " << k << (usable ? ", usable" : ", unusable") << " on " << spelled(p);
    if (usable) {
      replaced += along_k < least_other ? 0 : 1;
      EXPECT_EQ(r.manifold.point_count, 1) << spelled(p);
      EXPECT_EQ(int(r.manifold.reference_edge), k) << spelled(p);
    } else {
      ++unusable;
      EXPECT_EQ(r.manifold.point_count, 0) << spelled(p);
    }
  }
  // Neither case is vacuous.
  EXPECT_GT(replaced, kConvexPairsPerClass / 10);
  EXPECT_GT(unusable, kConvexPairsPerClass / 10);
}

TEST(ConvexInternalEdges, MaskedCircleIsPushedOutAlongTheAllowedFaceByItsExactOverlap) {
  expect_masked_circle_pushed_along_the_allowed_face<double>();
  expect_masked_circle_pushed_along_the_allowed_face<float>();
}

// A box sliding over the seam of a tile map: A a tile [0, 1] × [−1, 0] as `SetAsBox` orders it,
// its right edge (1) shared with the next tile (internal) and its right vertices (1, 2) closed
// (the outline is flat there); B a box 0.02 into the top and 0.01 past the seam. The plain answer
// pushes B back along the seam's normal by 0.01; the rule pushes it up, by the exact overlap
// along the least usable axis: A's top or B's bottom (B's left edge's axis has a closed vertex of
// A deepest, A's other edges B does not reach, B's other edges A does not reach).
template <class T>
void expect_box_over_a_seam_pushed_up() {
  auto box = [](double x0, double y0, double x1, double y1) {
    RawPolygon b;
    b.count = 4;
    b.v[0] = {x0, y0};
    b.v[1] = {x1, y0};
    b.v[2] = {x1, y1};
    b.v[3] = {x0, y1};
    return b;
  };
  const RawPolygonPair p =
      rounded_to(precision_of<T>(), RawPolygonPair{box(0, -1, 1, 0), box(0.99, -0.02, 1.49, 0.48)});
  const double tolerance = exact_bound(precision_of<T>()) * pair_size(p);
  const Result<T> plain = solve<T>(p, ConvexQuery<T>{Level::Manifold});
  EXPECT_NEAR(double(plain.separation), -exact_edge_overlap(p, true, 1), tolerance);
  ConvexQuery<T> q{Level::Manifold};
  q.masks_a = {0b0010, 0b0110};
  const Result<T> r = solve<T>(p, q);
  const double up = std::min(exact_edge_overlap(p, true, 2), exact_edge_overlap(p, false, 0));
  EXPECT_EQ(r.status, Status::Penetrating);
  EXPECT_NEAR(double(r.separation), -up, tolerance);
  EXPECT_NEAR(double(r.normal.x()), 0.0, tolerance);
  EXPECT_NEAR(double(r.normal.y()), 1.0, tolerance);
  EXPECT_EQ(r.manifold.point_count, 2);
}

TEST(ConvexInternalEdges, BoxOverATileSeamIsPushedUpByTheExactOverlapPastTheTop) {
  expect_box_over_a_seam_pushed_up<double>();
  expect_box_over_a_seam_pushed_up<float>();
}

// The centre on A's vertex 2 (A clockwise), which rounding puts a hair outside the line of one of
// its two edges, 1 and 2; every edge internal but edge 4, which the circle reaches. The plain push,
// along edge 2's normal, is along an internal edge's: it must be replaced by the push along edge
// 4's, by the circle's exact overlap past it, as for a centre a hair inside (found by the nested
// class: `collide` kept edge 2's normal, as if the push came from the vertex, which is not closed).
TEST(ConvexInternalEdges, MaskedCircleOnAVertexIsNotPushedAlongAnInternalFace) {
  RawCirclePair p;
  for (const Vec2<double>& v : {Vec2<double>(-0.091678444619576249, 0.99576171284801929),
                                Vec2<double>(0.4206529926796051, 0.78780345723685474),
                                Vec2<double>(0.70446939409688425, 0.26522967083317373),
                                Vec2<double>(-0.47929728392457294, -0.72343504612692933),
                                Vec2<double>(-0.3507104674979124, 0.90678761144236664)}) {
    p.a.v[static_cast<std::size_t>(p.a.count++)] = v;
  }
  p.b = RawCircle{p.a.v[2], 1.1732167951305705};
  ConvexQuery<double> q{Level::Manifold};
  q.masks_a.edges = 0b01111;
  const Result<double> r = solve<double>(p, q);
  EXPECT_NEAR(r.separation, -exact_edge_overlap(p, 4),
              exact_bound(Precision::Double) * pair_size(p));
  EXPECT_EQ(int(r.manifold.reference_edge), 4);
  EXPECT_EQ(r.manifold.point_count, 1);
}

// Caller's index in `p` of what is index `k` of `reversed(p)`.
std::uint8_t unreversed(Feature f, int count) {
  const int k = f.index;
  if (f.type == Feature::Type::Vertex) return static_cast<std::uint8_t>((count - k) % count);
  if (f.type == Feature::Type::Edge) return static_cast<std::uint8_t>(count - 1 - k);
  return f.index;
}

template <class T>
bool same_bits(const Vec2<T>& x, const Vec2<T>& y) {
  return std::memcmp(&x, &y, sizeof x) == 0;
}

// Everything `collide` reports, `r` for the pair and `w` for it with A's winding reversed when
// `a_reversed` and B's when `b_reversed`: the same numbers bit for bit (both windings store one
// counter-clockwise polygon) and the same features, named in each caller's order.
template <class T>
bool same_answer(const Result<T>& r, const Result<T>& w, int count_a, int count_b, bool a_reversed,
                 bool b_reversed) {
  auto same_feature = [](Feature x, Feature y, int count, bool rev) {
    return x.type == y.type && x.index == (rev ? unreversed(y, count) : y.index);
  };
  bool same = r.status == w.status && std::memcmp(&r.separation, &w.separation, sizeof(T)) == 0 &&
              same_bits(r.normal, w.normal) && same_bits(r.witness_a, w.witness_a) &&
              same_bits(r.witness_b, w.witness_b) &&
              same_feature(r.feature_a, w.feature_a, count_a, a_reversed) &&
              same_feature(r.feature_b, w.feature_b, count_b, b_reversed);
  const Manifold<T>& m = r.manifold;
  const Manifold<T>& n = w.manifold;
  const bool ref_reversed = m.reference_is_a ? a_reversed : b_reversed;
  const int ref_count = m.reference_is_a ? count_a : count_b;
  same = same && m.point_count == n.point_count && m.reference_is_a == n.reference_is_a &&
         same_feature({Feature::Type::Edge, m.reference_edge},
                      {Feature::Type::Edge, n.reference_edge}, ref_count, ref_reversed) &&
         same_bits(m.normal, n.normal);
  for (int i = 0; same && i < m.point_count; ++i) {
    const auto k = static_cast<std::size_t>(i);
    same = same_bits(m.points[k].point, n.points[k].point) &&
           std::memcmp(&m.points[k].separation, &n.points[k].separation, sizeof(T)) == 0;
  }
  return same;
}

template <class T, class Pair>
void expect_winding_invariance() {
  over_every_class<T, Pair>(
      "winding", [&](ConvexClass, const Pair& p, const ExactAnswer&, double size, Tally& tally) {
        ConvexQuery<T> q{Level::Manifold};
        q.margin = T(kConvexMarginPerSize * size);
        const Result<T> r = solve<T>(p, q);
        const int count_b = kCirclePair<Pair> ? 1 : 0;
        for (int flips = 1; flips < (kCirclePair<Pair> ? 2 : 4); ++flips) {
          Pair w = p;
          // A segment has no winding (`reversed` keeps its vertex 0 first: the same segment).
          const bool a_reversed = (flips & 1) != 0 && p.a.count > 2;
          const bool b_reversed = (flips & 2) != 0;
          if (a_reversed) w.a = reversed(p.a);
          if constexpr (!kCirclePair<Pair>) {
            if (b_reversed) w.b = reversed(p.b);
            if (!same_answer(r, solve<T>(w, q), p.a.count, p.b.count, a_reversed, b_reversed)) {
              tally.fail(p, "reversing " + std::to_string(flips) + " changes the answer");
            }
          } else if (!same_answer(r, solve<T>(w, q), p.a.count, count_b, a_reversed, false)) {
            tally.fail(p, "reversing A changes the answer");
          }
        }
      });
}

TYPED_TEST(ConvexPairAccuracy, ReversedWindingGivesTheSameAnswerBitForBit) {
  expect_winding_invariance<typename TypeParam::T, typename TypeParam::Pair>();
}

// What each class promises of its pairs, by the exact reference: touching pairs touch exactly,
// nested and overlapping pairs penetrate, separated pairs are apart; in both precisions.
template <class T, class Pair>
void expect_classes_hold_their_name() {
  over_every_class<T, Pair>(
      "class", [&](ConvexClass c, const Pair& p, const ExactAnswer& exact, double, Tally& tally) {
        int want = 0;
        switch (c) {
          case ConvexClass::Overlapping:
          case ConvexClass::Nested:
            want = -1;
            break;
          case ConvexClass::Separated:
            want = 1;
            break;
          case ConvexClass::Touching:
            want = 0;
            break;
          default:
            return;  // either way
        }
        if (exact.sign != want) tally.fail(p, "exact sign " + std::to_string(exact.sign));
      });
}

TYPED_TEST(ConvexInputClasses, TouchingNestedOverlappingAndSeparatedPairsAreSoExactly) {
  expect_classes_hold_their_name<typename TypeParam::T, typename TypeParam::Pair>();
}

}  // namespace
}  // namespace dyop::workloads
