// GJK + EPA (`epa`): hand-worked cases at every level, feature mapping for clockwise input, and
// agreement with the exact reference `sat` on seeded random pairs of every input class.
#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "dyop/epa.hpp"
#include "dyop/sat.hpp"
#include "workloads/input_classes.hpp"
#include "support/make_triangle.hpp"
#include "support/overlap_along.hpp"
#include "support/result_checks.hpp"
#include "support/scalars.hpp"

namespace dyop {
namespace {

using test_support::all_finite;
using test_support::has_features;
using test_support::overlap_along;

template <class T>
class Epa : public ::testing::Test {};
using test_support::ScalarNames;
using test_support::Scalars;
TYPED_TEST_SUITE(Epa, Scalars, ScalarNames);

using test_support::tri;

// Hand-worked answers on triangles of size ~1-10: a few hundred eps of either scalar.
template <class T>
T hand_worked_tol() {
  return T(400) * Eigen::NumTraits<T>::epsilon();
}

// B's bottom edge y = 2 lies 1 above A's apex (1, 1): a vertex–edge distance.
TYPED_TEST(Epa, ApartPairGivesTheDistanceWitnessesAndFeatures) {
  using T = TypeParam;
  const auto a = tri<T>(0, 0, 2, 0, 1, 1);
  const auto b = tri<T>(-1, 2, 3, 2, 1, 4);
  const Result<T> r = epa(a, b, {Level::Contact});
  EXPECT_EQ(r.status, Status::Separated);
  EXPECT_NEAR(r.separation, 1, hand_worked_tol<T>());
  EXPECT_EQ(r.depth, 0);
  EXPECT_NEAR((r.normal - Vec2<T>(0, 1)).norm(), 0, hand_worked_tol<T>());
  EXPECT_NEAR((r.witness_a - Vec2<T>(1, 1)).norm(), 0, hand_worked_tol<T>());
  EXPECT_NEAR((r.witness_b - Vec2<T>(1, 2)).norm(), 0, hand_worked_tol<T>());
  EXPECT_TRUE(has_features(r, {Feature::Type::Vertex, 2}, {Feature::Type::Edge, 0}));
  EXPECT_GT(r.iterations, 0);
}

// Closest points are two vertices: (1, 0) of A and (2, 1) of B, distance √2 along (1, 1)/√2.
TYPED_TEST(Epa, VertexToVertexDistanceIsAlongTheJoiningLine) {
  using T = TypeParam;
  const auto a = tri<T>(0, 0, 1, 0, 0, -1);
  const auto b = tri<T>(2, 1, 3, 1, 2, 2);
  const Result<T> r = epa(a, b, {Level::Contact});
  EXPECT_EQ(r.status, Status::Separated);
  EXPECT_NEAR(r.separation, std::sqrt(T(2)), hand_worked_tol<T>());
  EXPECT_NEAR((r.normal - Vec2<T>(1, 1) / std::sqrt(T(2))).norm(), 0, hand_worked_tol<T>());
  EXPECT_TRUE(has_features(r, {Feature::Type::Vertex, 1}, {Feature::Type::Vertex, 0}));
}

// B's apex (1.5, 0.25) pierces A's bottom edge y = 0 by 0.25; every other axis overlaps ≥ 2.
TYPED_TEST(Epa, VertexIntoFaceGivesItsDepthNormalWitnessesAndFeatures) {
  using T = TypeParam;
  const auto a = tri<T>(0, 0, 4, 0, 0, 4);
  const auto b = tri<T>(1, -1, 2, -1, 1.5, 0.25);
  const Result<T> r = epa(a, b, {Level::Contact});
  EXPECT_EQ(r.status, Status::Penetrating);
  EXPECT_NEAR(r.depth, 0.25, hand_worked_tol<T>());
  EXPECT_NEAR(r.separation, -0.25, hand_worked_tol<T>());
  EXPECT_NEAR((r.normal - Vec2<T>(0, -1)).norm(), 0,
              hand_worked_tol<T>());  // B moves down, out of A
  EXPECT_NEAR((r.witness_b - Vec2<T>(1.5, 0.25)).norm(), 0, hand_worked_tol<T>());
  EXPECT_NEAR((r.witness_a - Vec2<T>(1.5, 0)).norm(), 0, hand_worked_tol<T>());
  EXPECT_TRUE(has_features(r, {Feature::Type::Edge, 0}, {Feature::Type::Vertex, 2}));
}

// Right triangles with axis-parallel legs: B's vertical leg x = 0.1 is 0.1 inside A's leg x = 0.
TYPED_TEST(Epa, AxisAlignedRightTrianglesOverlapByTheirLegs) {
  using T = TypeParam;
  const auto a = tri<T>(0, 0, 2, 0, 0, 2);
  const auto b = tri<T>(0.1, 0.5, -2, 0.5, 0.1, 1.5);
  const Result<T> r = epa(a, b, {Level::Contact});
  EXPECT_EQ(r.status, Status::Penetrating);
  EXPECT_NEAR(r.depth, 0.1, hand_worked_tol<T>());
  EXPECT_NEAR((r.normal - Vec2<T>(-1, 0)).norm(), 0, hand_worked_tol<T>());
}

// B (legs 1) sits inside A (legs 10): the shortest way out is 2 to the left (down is 2.5).
TYPED_TEST(Epa, ContainedTriangleDepthIsTheShortestWayOut) {
  using T = TypeParam;
  const auto a = tri<T>(0, 0, 10, 0, 0, 10);
  const auto b = tri<T>(1, 1.5, 2, 1.5, 1, 2.5);
  const Result<T> r = epa(a, b, {Level::Contact});
  EXPECT_EQ(r.status, Status::Penetrating);
  EXPECT_NEAR(r.depth, 2, hand_worked_tol<T>() * 10);
  EXPECT_NEAR((r.normal - Vec2<T>(-1, 0)).norm(), 0, hand_worked_tol<T>());
}

// A − A is symmetric: the depth is A's smallest altitude (1, over the base), in either direction.
TYPED_TEST(Epa, IdenticalTrianglesDepthIsTheSmallestAltitude) {
  using T = TypeParam;
  const auto a = tri<T>(0, 0, 2, 0, 1, 1);
  const auto b = tri<T>(1, 1, 2, 0, 0, 0);  // same triangle, clockwise
  const Result<T> r = epa(a, b, {Level::Manifold});
  ASSERT_TRUE(all_finite(r));
  EXPECT_EQ(r.status, Status::Penetrating);
  EXPECT_NEAR(r.depth, 1, hand_worked_tol<T>());
  EXPECT_NEAR(std::abs(r.normal.y()), 1, hand_worked_tol<T>());
}

// The origin of A − B on its boundary: vertex on edge, edge on edge, vertex on vertex.
TYPED_TEST(Epa, ExactContactIsTouchingWithZeroSeparation) {
  using T = TypeParam;
  const auto a = tri<T>(0, 0, 2, 0, 1, 1);
  const Triangle<T> bs[] = {tri<T>(1, 0, 0, -1, 2, -1), tri<T>(0.5, 0, 1, -1, 1.5, 0),
                            tri<T>(2, 0, 3, -1, 3, 1)};
  for (const Triangle<T>& b : bs) {
    for (Level level : {Level::Overlap, Level::Depth, Level::Manifold}) {
      const Result<T> r = epa(a, b, {level});
      ASSERT_TRUE(all_finite(r));
      EXPECT_EQ(r.status, Status::Touching);
      EXPECT_LE(std::abs(r.separation), touching_tolerance<T>() * 2);
    }
  }
}

// B rests on A's top edge: just apart, touching, deep (the status follows the signed depth).
TYPED_TEST(Epa, BoundaryTripleJustApartTouchingAndDeep) {
  using T = TypeParam;
  const auto a = tri<T>(-5, 0, 0, -5, 5, 0);
  const struct {
    T dy;
    Status status;
  } cases[] = {
      {T(1e-3), Status::Separated}, {0, Status::Touching}, {-T(0.75), Status::Penetrating}};
  for (const auto& c : cases) {
    const auto b = tri<T>(-1, c.dy, 1, c.dy, 0, 2 + c.dy);
    const Result<T> r = epa(a, b, {Level::Depth});
    EXPECT_EQ(r.status, c.status);
    EXPECT_NEAR(r.separation, c.dy, hand_worked_tol<T>() * 10);
    EXPECT_NEAR((r.normal - Vec2<T>(0, 1)).norm(), 0, T(1e-3));
  }
}

// The same pairs given clockwise: features come back in the caller's vertex order.
TYPED_TEST(Epa, ClockwiseInputReportsFeaturesInTheCallersOrder) {
  using T = TypeParam;
  {
    const auto a = tri<T>(0, 0, 1, 1, 2, 0);   // apex (1, 1) is the caller's vertex 1
    const auto b = tri<T>(-1, 2, 1, 4, 3, 2);  // bottom edge is caller's 2 (vertex 2 → 0)
    const Result<T> r = epa(a, b, {Level::Contact});
    EXPECT_EQ(r.status, Status::Separated);
    EXPECT_TRUE(has_features(r, {Feature::Type::Vertex, 1}, {Feature::Type::Edge, 2}));
  }
  {
    const auto a = tri<T>(0, 0, 0, 4, 4, 0);         // bottom edge is caller's 2 (vertex 2 → 0)
    const auto b = tri<T>(1.5, 0.25, 2, -1, 1, -1);  // apex is the caller's vertex 0
    const Result<T> r = epa(a, b, {Level::Contact});
    EXPECT_EQ(r.status, Status::Penetrating);
    EXPECT_NEAR(r.depth, 0.25, hand_worked_tol<T>());
    EXPECT_TRUE(has_features(r, {Feature::Type::Edge, 2}, {Feature::Type::Vertex, 0}));
  }
}

TYPED_TEST(Epa, EachLevelLeavesTheFieldsOfHigherLevelsUntouched) {
  using T = TypeParam;
  const auto a = tri<T>(0, 0, 4, 0, 0, 4);
  const auto b = tri<T>(1, -1, 2, -1, 1.5, 0.25);
  const Result<T> overlap = epa(a, b, {Level::Overlap});
  EXPECT_EQ(overlap.status, Status::Penetrating);
  EXPECT_EQ(overlap.separation, 0);
  EXPECT_TRUE(overlap.normal.isZero());
  const Result<T> depth = epa(a, b, {Level::Depth});
  EXPECT_NEAR(depth.depth, 0.25, hand_worked_tol<T>());
  EXPECT_TRUE(depth.witness_a.isZero());
  EXPECT_EQ(depth.feature_a.type, Feature::Type::None);
  const Result<T> contact = epa(a, b, {Level::Contact});
  EXPECT_EQ(contact.manifold.point_count, 0);
  // At Overlap the pair is settled by GJK's enclosing simplex alone, before any EPA step.
  EXPECT_LE(overlap.iterations, depth.iterations);
}

TYPED_TEST(Epa, OverlapLevelOnApartPairSaysSeparatedWithoutDistance) {
  using T = TypeParam;
  const auto a = tri<T>(0, 0, 1, 0, 0, 1);
  const auto b = tri<T>(3, 0, 4, 0, 3, 1);
  const Result<T> r = epa(a, b, {Level::Overlap});
  EXPECT_EQ(r.status, Status::Separated);
  EXPECT_EQ(r.separation, 0);
  EXPECT_EQ(r.iterations, 1);  // the first support point already proves it
}

// The manifold is built on the face nearest EPA's normal: on an unambiguous axis it is sat's.
TYPED_TEST(Epa, ManifoldOnAnUnambiguousAxisIsSats) {
  using T = TypeParam;
  const auto a = tri<T>(-5, 0, 0, -5, 5, 0);
  const auto b = tri<T>(-1, -0.25, 1, -0.25, 0, 2);
  for (T margin : {T(0), T(0.5)}) {
    const Query<T> q{Level::Manifold, margin};
    const Result<T> e = epa(a, b, q);
    const Result<T> s = sat(a, b, q);
    ASSERT_EQ(e.manifold.point_count, 2);
    ASSERT_EQ(e.manifold.point_count, s.manifold.point_count);
    EXPECT_EQ(e.manifold.reference_is_a, s.manifold.reference_is_a);
    EXPECT_EQ(e.manifold.reference_edge, s.manifold.reference_edge);
    EXPECT_EQ(e.manifold.incident_edge, s.manifold.incident_edge);
    for (int i = 0; i < 2; ++i) {
      EXPECT_EQ(e.manifold.points[i].key, s.manifold.points[i].key);
      EXPECT_NEAR((e.manifold.points[i].point - s.manifold.points[i].point).norm(), 0,
                  hand_worked_tol<T>());
      EXPECT_NEAR(e.manifold.points[i].separation, -0.25, hand_worked_tol<T>());
    }
  }
  // Apart by 0.1: a speculative manifold within a margin of 0.5, none without one.
  const auto above = tri<T>(-1, 0.1, 1, 0.1, 0, 2);
  EXPECT_EQ(epa(a, above, {Level::Manifold, T(0.5)}).manifold.point_count, 2);
  EXPECT_EQ(epa(a, above, {Level::Manifold, T(0)}).manifold.point_count, 0);
}

// Translation by 1e6 and scaling to 1e-6 and 1e6: the local frame keeps the error relative.
TYPED_TEST(Epa, AccuracyIsRelativeToSizeNotToDistanceFromTheOrigin) {
  using T = TypeParam;
  for (T offset : {T(0), T(1e3), T(1e6)}) {
    const auto a = tri<T>(offset, offset, offset + 4, offset, offset, offset + 4);
    const auto b =
        tri<T>(offset + 1, offset - 1, offset + 2, offset - 1, offset + 1.5, offset + T(0.25));
    const Result<T> r = epa(a, b, {Level::Contact});
    EXPECT_EQ(r.status, Status::Penetrating);
    EXPECT_NEAR(r.depth, 0.25,
                hand_worked_tol<T>() * std::max(T(1), offset * Eigen::NumTraits<T>::epsilon()));
  }
  for (T s : {T(1e-6), T(1e6)}) {
    const auto a = tri<T>(0, 0, 4 * s, 0, 0, 4 * s);
    const auto b = tri<T>(s, -s, 2 * s, -s, 1.5f * s, T(0.25) * s);
    const Result<T> r = epa(a, b, {Level::Depth});
    EXPECT_EQ(r.status, Status::Penetrating);
    EXPECT_NEAR(r.depth / s, 0.25, hand_worked_tol<T>());
  }
}

// Swapping A and B keeps the separation and reverses the normal.
TYPED_TEST(Epa, SwappingTheTrianglesReversesTheNormal) {
  using T = TypeParam;
  const auto a = tri<T>(0, 0, 4, 0, 0, 4);
  const Triangle<T> bs[] = {tri<T>(1, -1, 2, -1, 1.5, 0.25), tri<T>(5, 5, 6, 5, 5, 6)};
  for (const Triangle<T>& b : bs) {
    const Result<T> ab = epa(a, b);
    const Result<T> ba = epa(b, a);
    EXPECT_EQ(ab.status, ba.status);
    EXPECT_NEAR(ab.separation, ba.separation, hand_worked_tol<T>());
    EXPECT_NEAR((ab.normal + ba.normal).norm(), 0, hand_worked_tol<T>());
  }
}

// ---------------------------------------------------------------------------------------------
// Randomized agreement with `sat` (double).

using workloads::build;
using workloads::InputClass;
using workloads::RawPair;
using workloads::test_classes;

// |epa − sat| / pair size on the separation. Measured (the summary this test prints, and 10 ×
// 100 000 pairs on other seeds): at most 4e-16 in every class but near-parallel, 3.2e-15 there,
// where GJK/EPA may stop on an edge that cuts across two nearly collinear edges of A − B, within
// their 16-eps tolerance (3.6e-15). 1e-12 keeps a 300× margin over that and still catches any
// real error: a wrong edge or a stopped-early iteration is off by far more.
constexpr double kSeparationBound = 1e-12;
// Angle between the two normals of a penetrating pair (radians). Both are unit normals of the same
// edge, from the same vertices: measured at most 1.3e-15, except near-parallel pairs (up to 5e-13,
// an edge of A − B across two nearly collinear ones). A larger angle must be a tie: EPA's normal
// then has to give the same depth as sat's.
constexpr double kNormalBound = 1e-12;

struct Figures {
  int pairs = 0;
  int penetrating = 0;
  int separated = 0;
  int status_disagreements = 0;  // outside the touching band
  int band_disagreements = 0;    // within it, where either answer is right
  int ties = 0;                  // normals differ but both axes give the depth
  double max_pen_error = 0;
  double sum_pen_error = 0;
  double max_sep_error = 0;
  double sum_sep_error = 0;
  double max_angle = 0;
  long sum_iterations = 0;
  int max_iterations = 0;
};

class EpaAgreesWithSat : public ::testing::TestWithParam<InputClass> {};

TEST_P(EpaAgreesWithSat, SeparationStatusAndNormalAgreeOnRandomPairs) {
  const std::vector<RawPair> pairs = workloads::make_valid_pairs(GetParam(), 3000, 20240611);
  Figures fig;
  for (const RawPair& p : pairs) {
    const auto t = build<double>(p);
    ASSERT_TRUE(t.a.ok() && t.b.ok());
    const double size = workloads::pair_size(p);
    const Result<double> e = epa(t.a.triangle, t.b.triangle, {Level::Contact});
    const Result<double> s = sat(t.a.triangle, t.b.triangle, {Level::Contact});
    ASSERT_TRUE(all_finite(e));
    ASSERT_LE(e.iterations, 2 * epa_max_iterations);
    ++fig.pairs;
    fig.sum_iterations += e.iterations;
    fig.max_iterations = std::max(fig.max_iterations, e.iterations);

    const double band = touching_tolerance<double>() * size;
    // Witnesses are world points: rounded at the scale of their coordinates, not of the pair.
    const double witness_tol = 1e-12 * size + 8 * DBL_EPSILON * e.witness_a.cwiseAbs().maxCoeff();
    if (e.status != s.status) {
      ++(std::abs(s.separation) > band ? fig.status_disagreements : fig.band_disagreements);
    }
    const double error = std::abs(e.separation - s.separation) / size;
    EXPECT_LE(error, kSeparationBound) << "epa " << e.separation << " sat " << s.separation;
    if (s.status == Status::Separated) {
      ++fig.separated;
      fig.max_sep_error = std::max(fig.max_sep_error, error);
      fig.sum_sep_error += error;
      EXPECT_NEAR((e.witness_b - e.witness_a).norm(), e.separation, witness_tol);
    }
    if (s.status == Status::Penetrating) {
      ++fig.penetrating;
      fig.max_pen_error = std::max(fig.max_pen_error, error);
      fig.sum_pen_error += error;
      const double angle = std::atan2(std::abs(cross(e.normal, s.normal)), e.normal.dot(s.normal));
      if (angle <= kNormalBound) {
        fig.max_angle = std::max(fig.max_angle, angle);
      } else {
        // Two axes tie: EPA's normal must then be a minimum-translation axis as well.
        ++fig.ties;
        EXPECT_LE(std::abs(overlap_along(p, e.normal) - s.depth), kSeparationBound * size);
      }
      EXPECT_NEAR((e.witness_a - e.witness_b - e.depth * e.normal).norm(), 0, witness_tol);
    }
    // Overlap level: the same status from GJK alone (or EPA's first polygon).
    EXPECT_EQ(epa(t.a.triangle, t.b.triangle, {Level::Overlap}).status, e.status);
  }
  EXPECT_EQ(fig.status_disagreements, 0);
  std::printf(
      "%-16s pen %4d err max %.1e mean %.1e | sep %4d err max %.1e mean %.1e | status %d+%d | "
      "angle max %.1e ties %d | iterations mean %.2f max %d\n",
      workloads::name(GetParam()), fig.penetrating, fig.max_pen_error,
      fig.penetrating ? fig.sum_pen_error / fig.penetrating : 0.0, fig.separated, fig.max_sep_error,
      fig.separated ? fig.sum_sep_error / fig.separated : 0.0, fig.status_disagreements,
      fig.band_disagreements, fig.max_angle, fig.ties,
      static_cast<double>(fig.sum_iterations) / fig.pairs, fig.max_iterations);
}

INSTANTIATE_TEST_SUITE_P(EveryClass, EpaAgreesWithSat, ::testing::ValuesIn(test_classes),
                         [](const ::testing::TestParamInfo<InputClass>& info) {
                           std::string n = workloads::name(info.param);
                           std::replace(n.begin(), n.end(), '-', '_');
                           return n;
                         });

// Float: same classes, a looser bound (float's eps is 2^-23), and never a NaN.
TEST(EpaFloat, AgreesWithSatInFloatOnRandomPairs) {
  for (InputClass c : test_classes) {
    for (const RawPair& p : workloads::make_valid_pairs(c, 500, 7)) {
      const auto t = build<float>(p);
      if (!t.a.ok() || !t.b.ok()) continue;  // a double sliver may be flat in float
      const Result<float> e = epa(t.a.triangle, t.b.triangle, {Level::Manifold});
      const Result<float> s = sat(t.a.triangle, t.b.triangle, {Level::Depth});
      ASSERT_TRUE(all_finite(e)) << workloads::name(c);
      EXPECT_LE(e.iterations, 2 * epa_max_iterations);
      const double size = workloads::pair_size(p);
      EXPECT_LE(std::abs(e.separation - s.separation), 1e-5 * size) << workloads::name(c);
    }
  }
}

}  // namespace
}  // namespace dyop
