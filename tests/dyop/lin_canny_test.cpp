// Lin–Canny: hand-worked cases, agreement with the exact `sat` (distance exact, depth a local
// minimum never below sat's), warm starts from the cache, and the step bound.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

#include "dyop/lin_canny.hpp"
#include "dyop/sat.hpp"
#include "workloads/input_classes.hpp"
#include "workloads/random.hpp"
#include "support/make_triangle.hpp"
#include "support/result_checks.hpp"
#include "support/scalars.hpp"

namespace dyop::workloads {
namespace {

template <class T>
class LinCanny : public ::testing::Test {};
using test_support::ScalarNames;
using test_support::Scalars;
TYPED_TEST_SUITE(LinCanny, Scalars, ScalarNames);

using test_support::all_finite;
using test_support::has_features;
using test_support::tol;
using test_support::tri;

// Caller's vertex i of the triangle given as `t`'s CCW vertices through input_vertex.
template <class T>
Vec2<T> caller_vertex(const Triangle<T>& t, int caller_index) {
  for (int i = 0; i < 3; ++i) {
    if (t.input_vertex(i) == caller_index) return t.vertex(i);
  }
  return Vec2<T>::Zero();
}

// ---------------------------------------------------------------------------------------------
// Hand-worked cases

TYPED_TEST(LinCanny, VertexToEdgeDistanceIsAlongTheEdgeNormal) {
  using T = TypeParam;
  const auto a = tri<T>(0, 0, 2, 0, 1, -1);
  const auto b = tri<T>(1, 0.25, 2, 2, 0, 2);  // B's lowest vertex 0.25 above A's top edge
  const Result<T> r = lin_canny(a, b, {Level::Contact});
  EXPECT_EQ(r.status, Status::Separated);
  EXPECT_NEAR(r.separation, 0.25, tol<T>());
  EXPECT_EQ(r.depth, 0);
  EXPECT_EQ(r.normal, Vec2<T>(0, 1));  // A's edge normal itself, not a difference of points
  EXPECT_NEAR((r.witness_a - Vec2<T>(1, 0)).norm(), 0, tol<T>());
  EXPECT_NEAR((r.witness_b - Vec2<T>(1, 0.25)).norm(), 0, tol<T>());
  EXPECT_TRUE(has_features(r, {Feature::Type::Edge, 0}, {Feature::Type::Vertex, 0}));
}

TYPED_TEST(LinCanny, VertexToVertexDistanceAndWitnesses) {
  using T = TypeParam;
  const auto a = tri<T>(0, 0, -1, -2, -2, -1);  // corner at the origin, opening towards (-1, -1)
  const auto b = tri<T>(1, 1, 2, 3, 3, 2);      // corner at (1, 1), opening towards (1, 1)
  const Result<T> r = lin_canny(a, b, {Level::Contact});
  EXPECT_EQ(r.status, Status::Separated);
  EXPECT_NEAR(r.separation, std::sqrt(T(2)), tol<T>());
  EXPECT_NEAR((r.normal - Vec2<T>(1, 1) / std::sqrt(T(2))).norm(), 0, tol<T>());
  EXPECT_NEAR((r.witness_a - Vec2<T>(0, 0)).norm(), 0, tol<T>());
  EXPECT_NEAR((r.witness_b - Vec2<T>(1, 1)).norm(), 0, tol<T>());
  EXPECT_TRUE(has_features(r, {Feature::Type::Vertex, 0}, {Feature::Type::Vertex, 0}));
}

// A's top edge y = 0 faces B's bottom edge y = 0.25 over x in [0.5, 2]: every point of the overlap
// is a closest point, so only the gap and the normal are pinned, and the witnesses' consistency.
TYPED_TEST(LinCanny, ParallelEdgesGiveTheirGapAndTheCommonNormal) {
  using T = TypeParam;
  const auto a = tri<T>(0, 0, 2, 0, 1, -1);
  const auto b = tri<T>(0.5, 0.25, 2.5, 0.25, 1.5, 1);
  const Result<T> r = lin_canny(a, b, {Level::Contact});
  EXPECT_EQ(r.status, Status::Separated);
  EXPECT_NEAR(r.separation, 0.25, tol<T>());
  EXPECT_NEAR((r.normal - Vec2<T>(0, 1)).norm(), 0, tol<T>());
  EXPECT_NEAR(r.witness_a.y(), 0, tol<T>());
  EXPECT_NEAR(r.witness_b.y(), 0.25, tol<T>());
  EXPECT_NEAR(r.witness_a.x(), r.witness_b.x(), tol<T>());
  EXPECT_GE(r.witness_a.x(), 0.5 - tol<T>());
  EXPECT_LE(r.witness_a.x(), 2 + tol<T>());
}

// A's bottom edge (y = 0) is pierced 0.5 deep by B's top vertex (2, 0.5): the depth walk starts
// on the features that found the vertex inside A, and that axis is the global minimum.
TYPED_TEST(LinCanny, VertexIntoFaceGivesTheKnownDepth) {
  using T = TypeParam;
  const auto a = tri<T>(0, 0, 4, 0, 2, 4);
  const auto b = tri<T>(2, 0.5, 1, -2, 3, -2);
  for (Level level : {Level::Depth, Level::Contact, Level::Manifold}) {
    const Result<T> r = lin_canny(a, b, {level});
    EXPECT_EQ(r.status, Status::Penetrating);
    EXPECT_NEAR(r.depth, 0.5, tol<T>());
    EXPECT_NEAR(r.separation, -0.5, tol<T>());
    EXPECT_NEAR((r.normal - Vec2<T>(0, -1)).norm(), 0, tol<T>());  // B moves down, out of A
    if (level == Level::Depth) continue;
    EXPECT_NEAR((r.witness_b - Vec2<T>(2, 0.5)).norm(), 0, tol<T>());
    EXPECT_NEAR((r.witness_a - Vec2<T>(2, 0)).norm(), 0, tol<T>());
    EXPECT_TRUE(has_features(r, {Feature::Type::Edge, 0}, {Feature::Type::Vertex, 0}));
    if (level == Level::Manifold) {
      EXPECT_GE(r.manifold.point_count, 1);
    }
  }
}

// Identical right triangles: the overlap along each axis is the triangle's width across it, least
// across the hypotenuse (√2/2), and the cycle of axes has no other local minimum.
TYPED_TEST(LinCanny, IdenticalTrianglesPenetrateByTheLeastWidth) {
  using T = TypeParam;
  const auto a = tri<T>(0, 0, 1, 0, 0, 1);
  const auto b = tri<T>(0, 1, 1, 0, 0, 0);  // same triangle, clockwise
  const Result<T> r = lin_canny(a, b, {Level::Contact});
  EXPECT_EQ(r.status, Status::Penetrating);
  EXPECT_NEAR(r.depth, std::sqrt(T(0.5)), tol<T>());
  EXPECT_NEAR(std::abs(r.normal.dot(Vec2<T>(1, 1))), std::sqrt(T(2)), tol<T>());
}

// The star of David: no vertex of either triangle is inside the other, only edges cross.
TYPED_TEST(LinCanny, CrossingEdgesWithNoVertexInsideArePenetrating) {
  using T = TypeParam;
  const T h = std::sqrt(T(3)) / 2;
  const auto a = tri<T>(0, 1, -h, T(-0.5), h, T(-0.5));
  const auto b = tri<T>(0, -1, h, T(0.5), -h, T(0.5));
  const Result<T> r = lin_canny(a, b, {Level::Depth});
  const Result<T> s = sat(a, b, {Level::Depth});
  EXPECT_EQ(r.status, Status::Penetrating);
  EXPECT_GE(r.depth, s.depth);
  EXPECT_NEAR(r.depth, s.depth, tol<T>());  // all six overlaps are equal by symmetry
}

TYPED_TEST(LinCanny, ExactlyTouchingPairsAreTouching) {
  using T = TypeParam;
  const auto a = tri<T>(0, 0, 2, 0, 1, -1);
  const Triangle<T> touching[] = {
      tri<T>(1, 0, 2, 1, 0, 1),      // B's vertex on A's top edge
      tri<T>(0.5, 0, 1.5, 0, 1, 1),  // B's bottom edge on A's top edge
      tri<T>(2, 0, 3, 1, 3, -1),     // vertex on vertex
      tri<T>(-1, 0, 0, 0, -0.5, 1),  // end to end along one line
  };
  for (const Triangle<T>& b : touching) {
    for (Level level : {Level::Overlap, Level::Depth, Level::Contact}) {
      const Result<T> r = lin_canny(a, b, {level});
      EXPECT_EQ(r.status, Status::Touching);
      EXPECT_LE(std::abs(r.separation), tol<T>());
      EXPECT_TRUE(all_finite(r));
    }
  }
}

// The same pair given clockwise: features must name the caller's indices, which the witnesses
// (world points, independent of any order) pin down.
TYPED_TEST(LinCanny, FeaturesAreInTheCallersOrderForClockwiseInput) {
  using T = TypeParam;
  const auto a = tri<T>(1, -1, 0, 0, 2, 0);    // clockwise; caller's edge 1 is y = 0
  const auto b = tri<T>(2, 2, 1, 0.25, 0, 2);  // clockwise; caller's vertex 1 is the lowest
  ASSERT_TRUE(a.flipped());
  ASSERT_TRUE(b.flipped());
  const Result<T> r = lin_canny(a, b, {Level::Contact});
  EXPECT_EQ(r.status, Status::Separated);
  EXPECT_NEAR(r.separation, 0.25, tol<T>());
  EXPECT_TRUE(has_features(r, {Feature::Type::Edge, 1}, {Feature::Type::Vertex, 1}));
  EXPECT_EQ(r.witness_b, caller_vertex(b, 1));

  // Penetrating: the answer's features come from the depth axis, mapped the same way.
  const auto c = tri<T>(1, -2, 2, 0.5, 3, -2);  // clockwise; caller's vertex 1 pierces y = 0
  const auto d = tri<T>(2, 4, 4, 0, 0, 0);      // clockwise; caller's edge 1 is y = 0
  const Result<T> p = lin_canny(d, c, {Level::Contact});
  EXPECT_EQ(p.status, Status::Penetrating);
  EXPECT_NEAR(p.depth, 0.5, tol<T>());
  EXPECT_TRUE(has_features(p, {Feature::Type::Edge, 1}, {Feature::Type::Vertex, 1}));
  EXPECT_EQ(p.witness_b, caller_vertex(c, 1));
}

TYPED_TEST(LinCanny, OverlapLevelReturnsTheStatusOnly) {
  using T = TypeParam;
  const auto a = tri<T>(0, 0, 4, 0, 2, 4);
  const Triangle<T> others[] = {tri<T>(2, 0.5, 1, -2, 3, -2), tri<T>(2, -0.5, 1, -2, 3, -2),
                                tri<T>(1, 0.5, 3, 0.5, 2, 1)};
  for (const Triangle<T>& b : others) {
    const Result<T> r = lin_canny(a, b, {Level::Overlap});
    EXPECT_EQ(r.status, lin_canny(a, b, {Level::Depth}).status);
    EXPECT_EQ(r.separation, 0);
    EXPECT_EQ(r.normal, Vec2<T>::Zero());
    EXPECT_EQ(r.feature_a.type, Feature::Type::None);
    EXPECT_EQ(r.manifold.point_count, 0);
  }
}

TYPED_TEST(LinCanny, SeparatedPairWithinTheMarginGetsASpeculativeManifold) {
  using T = TypeParam;
  const auto a = tri<T>(0, 0, 2, 0, 1, -1);
  const auto b = tri<T>(0.5, 0.25, 2.5, 0.25, 1.5, 1);  // flat bottom 0.25 above A's top edge
  const Result<T> near = lin_canny(a, b, {Level::Manifold, T(0.5)});
  EXPECT_EQ(near.status, Status::Separated);
  ASSERT_EQ(near.manifold.point_count, 2);
  for (int i = 0; i < 2; ++i) EXPECT_NEAR(near.manifold.points[i].separation, 0.25, tol<T>());
  EXPECT_NEAR((near.manifold.normal - Vec2<T>(0, 1)).norm(), 0, tol<T>());
  const Result<T> far = lin_canny(a, b, {Level::Manifold, T(0.1)});
  EXPECT_EQ(far.manifold.point_count, 0);
}

TYPED_TEST(LinCanny, CacheOutOfRangeStartsColdAndIsOverwritten) {
  using T = TypeParam;
  const auto a = tri<T>(0, 0, 2, 0, 1, -1);
  const auto b = tri<T>(1, 0.25, 2, 2, 0, 2);
  LinCannyCache cache;
  cache.valid = true;
  cache.index_a = 7;
  cache.type_b = Feature::Type::None;
  cache.depth_axis = 200;
  const Result<T> warm = lin_canny(a, b, {Level::Contact}, &cache);
  const Result<T> cold = lin_canny(a, b, {Level::Contact});
  EXPECT_EQ(warm.separation, cold.separation);
  EXPECT_EQ(warm.iterations, cold.iterations);
  EXPECT_TRUE(cache.valid);
  EXPECT_LT(cache.index_a, 3);
  EXPECT_NE(cache.type_b, Feature::Type::None);
  EXPECT_LT(cache.depth_axis, 6);
}

// ---------------------------------------------------------------------------------------------
// Seeded random pairs of every class, against sat

constexpr int pairs_per_class = 2000;
constexpr std::uint64_t seed = 20240611;

// The six axes of the pair (A's normals, then B's negated ones) and the overlap on each, computed
// with A's first vertex as origin (as the library does), to check that a depth is a local minimum
// of the angular cycle.
struct AxisCycle {
  std::array<Vec2<double>, 6> axis;
  std::array<double, 6> overlap;
  std::array<int, 6> ring;  // axis indices sorted by angle
};

AxisCycle axis_cycle(const Triangle<double>& a, const Triangle<double>& b) {
  AxisCycle c;
  const Vec2<double> origin = a.vertex(0);
  for (int k = 0; k < 6; ++k) {
    const Vec2<double> u = k < 3 ? a.normal(k) : Vec2<double>(-b.normal(k - 3));
    double reach_a = -std::numeric_limits<double>::infinity();
    double reach_b = std::numeric_limits<double>::infinity();
    for (int i = 0; i < 3; ++i) {
      reach_a = std::max(reach_a, u.dot(a.vertex(i) - origin));
      reach_b = std::min(reach_b, u.dot(b.vertex(i) - origin));
    }
    c.axis[k] = u;
    c.overlap[k] = reach_a - reach_b;
    c.ring[k] = k;
  }
  std::sort(c.ring.begin(), c.ring.end(), [&](int i, int j) {
    return std::atan2(c.axis[i].y(), c.axis[i].x()) < std::atan2(c.axis[j].y(), c.axis[j].x());
  });
  return c;
}

// Rounding allowed on a difference of world points (witnesses): relative to the pair's size, plus
// the spacing of doubles at the pair's distance from the world origin.
double world_slack(const RawPair& p) {
  double reach = 0;
  for (const auto* t : {&p.a, &p.b}) {
    for (const Vec2<double>& v : *t) reach = std::max(reach, v.cwiseAbs().maxCoeff());
  }
  return 1e-12 * pair_size(p) + 8 * std::numeric_limits<double>::epsilon() * reach;
}

// True when the axis `r` settled on (its normal is that axis, bit for bit) has no neighbour in the
// angular cycle with a smaller overlap (beyond `slack`, for rounding).
bool is_local_minimum(const AxisCycle& c, const Result<double>& r, double slack) {
  for (int s = 0; s < 6; ++s) {
    const int k = c.ring[s];
    if (c.axis[k] != r.normal) continue;
    const double before = c.overlap[c.ring[(s + 5) % 6]];
    const double after = c.overlap[c.ring[(s + 1) % 6]];
    if (std::abs(c.overlap[k] - r.depth) <= slack && before >= r.depth - slack &&
        after >= r.depth - slack) {
      return true;
    }
  }
  return false;
}

TEST(LinCannyRandom, SeparatedDistanceEqualsSatsWithin1e12OfThePairSize) {
  int separated = 0;
  for (InputClass c : test_classes) {
    for (const RawPair& p : make_valid_pairs(c, pairs_per_class, seed)) {
      const auto t = build<double>(p);
      const Result<double> s = sat(t.a.triangle, t.b.triangle, {Level::Contact});
      if (s.status != Status::Separated) continue;
      ++separated;
      const Result<double> r = lin_canny(t.a.triangle, t.b.triangle, {Level::Contact});
      ASSERT_EQ(r.status, Status::Separated) << name(c);
      const double size = pair_size(p);
      EXPECT_NEAR(r.separation, s.separation, 1e-12 * size) << name(c);
      EXPECT_NEAR((r.witness_b - r.witness_a).norm(), r.separation, world_slack(p)) << name(c);
      EXPECT_NEAR((r.separation * r.normal - (r.witness_b - r.witness_a)).norm(), 0, world_slack(p))
          << name(c);
    }
  }
  EXPECT_GT(separated, pairs_per_class);
}

// A local minimum above the band where the global one is within it could differ; on these classes
// it never does.
TEST(LinCannyRandom, StatusEqualsSatsOnEveryClass) {
  for (InputClass c : test_classes) {
    for (const RawPair& p : make_valid_pairs(c, pairs_per_class, seed)) {
      const auto t = build<double>(p);
      EXPECT_EQ(lin_canny(t.a.triangle, t.b.triangle, {Level::Depth}).status,
                sat(t.a.triangle, t.b.triangle, {Level::Depth}).status)
          << name(c);
    }
  }
}

TEST(LinCannyRandom, DepthIsNeverBelowSatsAndIsALocalMinimumOfTheAxisCycle) {
  int penetrating = 0;
  for (InputClass c : test_classes) {
    for (const RawPair& p : make_valid_pairs(c, pairs_per_class, seed)) {
      const auto t = build<double>(p);
      const Result<double> s = sat(t.a.triangle, t.b.triangle, {Level::Contact});
      const Result<double> r = lin_canny(t.a.triangle, t.b.triangle, {Level::Contact});
      if (s.status != Status::Penetrating || r.status != Status::Penetrating) continue;
      ++penetrating;
      // One of sat's own six overlaps, computed the same way: never smaller, not even by rounding.
      EXPECT_GE(r.depth, s.depth) << name(c);
      EXPECT_TRUE(is_local_minimum(axis_cycle(t.a.triangle, t.b.triangle), r, 1e-12 * pair_size(p)))
          << name(c);
      EXPECT_NEAR((r.witness_a - r.witness_b - r.depth * r.normal).norm(), 0, world_slack(p))
          << name(c);
    }
  }
  EXPECT_GT(penetrating, pairs_per_class);
}

TEST(LinCannyRandom, ExactlyTouchingPairsAreTouchingAtEveryLevel) {
  for (const RawPair& p : make_valid_pairs(InputClass::Touching, pairs_per_class, seed)) {
    const auto t = build<double>(p);
    for (Level level : {Level::Overlap, Level::Depth, Level::Contact, Level::Manifold}) {
      EXPECT_EQ(lin_canny(t.a.triangle, t.b.triangle, {level}).status, Status::Touching);
    }
  }
}

TEST(LinCannyRandom, OverlapLevelAgreesWithTheDepthLevelStatus) {
  for (InputClass c : test_classes) {
    for (const RawPair& p : make_valid_pairs(c, pairs_per_class, seed)) {
      const auto t = build<double>(p);
      EXPECT_EQ(lin_canny(t.a.triangle, t.b.triangle, {Level::Overlap}).status,
                lin_canny(t.a.triangle, t.b.triangle, {Level::Depth}).status)
          << name(c);
    }
  }
}

// A cache left by an unrelated pair is a valid start like any other: the walk ends on the same
// distance.
TEST(LinCannyRandom, WarmStartFromAnotherPairGivesTheColdDistance) {
  for (InputClass c : test_classes) {
    LinCannyCache cache;
    for (const RawPair& p : make_valid_pairs(c, pairs_per_class, seed)) {
      const auto t = build<double>(p);
      const Result<double> cold = lin_canny(t.a.triangle, t.b.triangle, {Level::Contact});
      const Result<double> warm = lin_canny(t.a.triangle, t.b.triangle, {Level::Contact}, &cache);
      EXPECT_EQ(warm.status, cold.status) << name(c);
      if (cold.status == Status::Separated) {
        EXPECT_NEAR(warm.separation, cold.separation, 1e-12 * pair_size(p)) << name(c);
      }
    }
  }
}

// B moved rigidly by `step` of the pair's size, turned by `step` radians about its centroid.
RawPair moved(const RawPair& p, double step, Random& rng) {
  constexpr double pi = 3.14159265358979323846;
  const double heading = rng.uniform(0, 2 * pi);
  const Vec2<double> shift =
      step * pair_size(p) * Vec2<double>(std::cos(heading), std::sin(heading));
  const Vec2<double> centre = (p.b[0] + p.b[1] + p.b[2]) / 3;
  const double turn = rng.coin() ? step : -step;
  const double cs = std::cos(turn);
  const double sn = std::sin(turn);
  RawPair q = p;
  for (Vec2<double>& v : q.b) {
    const Vec2<double> r = v - centre;
    v = centre + Vec2<double>(cs * r.x() - sn * r.y(), sn * r.x() + cs * r.y()) + shift;
  }
  return q;
}

// After a small motion the cached pair is usually still the closest one and is confirmed in one
// step; when the motion changed it the walk goes on from there, and a cold start may be luckier on
// a single pair, but never over a class.
TEST(LinCannyRandom, WarmStartTakesNoMoreIterationsAfterASmallMotion) {
  Random rng(seed);
  for (InputClass c : {InputClass::General, InputClass::Apart, InputClass::Sliver,
                       InputClass::NearParallel, InputClass::Scale}) {
    long cold_total = 0;
    long warm_total = 0;
    for (const RawPair& p : make_valid_pairs(c, pairs_per_class, seed)) {
      const auto t = build<double>(p);
      LinCannyCache cache;
      if (lin_canny(t.a.triangle, t.b.triangle, {Level::Contact}, &cache).status !=
          Status::Separated) {
        continue;
      }
      const LinCannyCache before = cache;
      const RawPair q = moved(p, 1e-3, rng);
      const auto u = build<double>(q);
      ASSERT_TRUE(u.b.ok());
      const Result<double> cold = lin_canny(u.a.triangle, u.b.triangle, {Level::Contact});
      const Result<double> warm = lin_canny(u.a.triangle, u.b.triangle, {Level::Contact}, &cache);
      if (cold.status != Status::Separated) continue;
      EXPECT_NEAR(warm.separation, cold.separation, 1e-12 * pair_size(q)) << name(c);
      const bool same_pair = cache.type_a == before.type_a && cache.index_a == before.index_a &&
                             cache.type_b == before.type_b && cache.index_b == before.index_b;
      if (same_pair) {
        EXPECT_EQ(warm.iterations, 1) << name(c);
      }
      cold_total += cold.iterations;
      warm_total += warm.iterations;
    }
    EXPECT_LT(warm_total, cold_total) << name(c);
  }
}

TEST(LinCannyRandom, WarmStartOnAnUnchangedSeparatedPairConfirmsInOneStep) {
  for (const RawPair& p : make_valid_pairs(InputClass::Apart, pairs_per_class, seed)) {
    const auto t = build<double>(p);
    LinCannyCache cache;
    const Result<double> first = lin_canny(t.a.triangle, t.b.triangle, {Level::Contact}, &cache);
    const Result<double> again = lin_canny(t.a.triangle, t.b.triangle, {Level::Contact}, &cache);
    EXPECT_EQ(again.iterations, 1);
    EXPECT_EQ(again.separation, first.separation);
  }
}

// Float and double, cold and warm (the cache carried along the suite), every level.
TEST(LinCannyRandom, IterationsStayWithinTheStepBoundAndNoResultIsNanOrInf) {
  for (InputClass c : test_classes) {
    LinCannyCache cache_d;
    LinCannyCache cache_f;
    for (const RawPair& p : make_valid_pairs(c, pairs_per_class, seed)) {
      const auto d = build<double>(p);
      const auto f = build<float>(p);
      for (Level level : {Level::Overlap, Level::Depth, Level::Contact, Level::Manifold}) {
        const Query<double> q{level, 0.05 * pair_size(p)};
        for (LinCannyCache* cache : {static_cast<LinCannyCache*>(nullptr), &cache_d}) {
          const Result<double> r = lin_canny(d.a.triangle, d.b.triangle, q, cache);
          EXPECT_GE(r.iterations, 1) << name(c);
          EXPECT_LE(r.iterations, lin_canny_max_steps) << name(c);
          EXPECT_NE(r.status, Status::Invalid) << name(c);
          EXPECT_TRUE(all_finite(r)) << name(c);
        }
        if (!f.a.ok() || !f.b.ok()) continue;  // slivers too thin for float are not triangles
        const Query<float> qf{level, float(q.margin)};
        for (LinCannyCache* cache : {static_cast<LinCannyCache*>(nullptr), &cache_f}) {
          const Result<float> r = lin_canny(f.a.triangle, f.b.triangle, qf, cache);
          EXPECT_LE(r.iterations, lin_canny_max_steps) << name(c);
          EXPECT_NE(r.status, Status::Invalid) << name(c);
          EXPECT_TRUE(all_finite(r)) << name(c);
        }
      }
    }
  }
}

}  // namespace
}  // namespace dyop::workloads
