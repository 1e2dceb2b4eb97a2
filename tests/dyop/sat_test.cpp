// The exact reference `sat` on cases with answers worked by hand, at every query level.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "dyop/sat.hpp"
#include "support/make_triangle.hpp"
#include "support/result_checks.hpp"
#include "support/scalars.hpp"

namespace dyop {
namespace {

template <class T>
class Sat : public ::testing::Test {};
using test_support::ScalarNames;
using test_support::Scalars;
TYPED_TEST_SUITE(Sat, Scalars, ScalarNames);

using test_support::has_features;
using test_support::tol;
using test_support::tri;

// A's bottom edge (y = 0) is pierced 0.5 deep by B's top vertex (2, 0.5).
TYPED_TEST(Sat, VertexIntoFaceGivesItsDepthNormalWitnessesAndFeatures) {
  using T = TypeParam;
  const auto a = tri<T>(0, 0, 4, 0, 2, 4);
  const auto b = tri<T>(2, 0.5, 1, -2, 3, -2);
  const Result<T> r = sat(a, b, {Level::Contact});
  EXPECT_EQ(r.status, Status::Penetrating);
  EXPECT_NEAR(r.depth, 0.5, tol<T>());
  EXPECT_NEAR(r.separation, -0.5, tol<T>());
  EXPECT_NEAR(r.normal.x(), 0, tol<T>());
  EXPECT_NEAR(r.normal.y(), -1, tol<T>());  // B moves down, out of A
  EXPECT_NEAR((r.witness_b - Vec2<T>(2, 0.5)).norm(), 0, tol<T>());
  EXPECT_NEAR((r.witness_a - Vec2<T>(2, 0)).norm(), 0, tol<T>());
  EXPECT_TRUE(has_features(r, {Feature::Type::Edge, 0}, {Feature::Type::Vertex, 0}));
}

// The same pair's manifold: the next least overlap is along B's slanted faces, normals
// (±2.5, 1)/√7.25: 5.5/√7.25 against the reference face's 0.5.
TYPED_TEST(Sat, ManifoldLeadIsTheNextLeastOverlapBeyondTheReferenceFace) {
  using T = TypeParam;
  const auto a = tri<T>(0, 0, 4, 0, 2, 4);
  const auto b = tri<T>(2, 0.5, 1, -2, 3, -2);
  const Result<T> r = sat(a, b, {Level::Manifold});
  ASSERT_EQ(r.manifold.point_count, 1);
  EXPECT_NEAR(r.manifold.lead, 5.5 / std::sqrt(7.25) - 0.5, tol<T>());
  const auto apart = tri<T>(2, -1.5, 1, -4, 3, -4);
  EXPECT_EQ(sat(a, apart, {Level::Manifold}).manifold.lead, std::numeric_limits<T>::infinity())
      << "no points, no lead";
}

TYPED_TEST(Sat, ApartPairGivesTheEuclideanDistanceAndClosestPoints) {
  using T = TypeParam;
  const auto a = tri<T>(0, 0, 1, 0, 0, 1);
  const auto b = tri<T>(2, 0, 3, 0, 2, 1);
  const Result<T> r = sat(a, b, {Level::Contact});
  EXPECT_EQ(r.status, Status::Separated);
  EXPECT_NEAR(r.separation, 1, tol<T>());
  EXPECT_EQ(r.depth, 0);
  EXPECT_NEAR((r.normal - Vec2<T>(1, 0)).norm(), 0, tol<T>());
  EXPECT_NEAR((r.witness_a - Vec2<T>(1, 0)).norm(), 0, tol<T>());
  EXPECT_NEAR((r.witness_b - Vec2<T>(2, 0)).norm(), 0, tol<T>());
}

TYPED_TEST(Sat, DistanceToAnEdgeInteriorIsAlongTheEdgeNormal) {
  using T = TypeParam;
  const auto a = tri<T>(0, 0, 2, 0, 1, -1);
  const auto b = tri<T>(1, 0.25, 2, 2, 0, 2);  // B's lowest vertex 0.25 above A's top edge
  const Result<T> r = sat(a, b, {Level::Contact});
  EXPECT_EQ(r.status, Status::Separated);
  EXPECT_NEAR(r.separation, 0.25, tol<T>());
  EXPECT_NEAR((r.normal - Vec2<T>(0, 1)).norm(), 0, tol<T>());
  EXPECT_EQ(r.feature_a.type, Feature::Type::Edge);
  EXPECT_EQ(r.feature_b.type, Feature::Type::Vertex);
  EXPECT_EQ(r.feature_b.index, 0);
}

// B rests on A's top edge y = 0 by its flat bottom: just apart, touching, deep.
TYPED_TEST(Sat, BoundaryTripleJustApartTouchingAndDeep) {
  using T = TypeParam;
  const auto a = tri<T>(-5, 0, 0, -5, 5, 0);
  const T gap = T(1e-3);
  const struct {
    T dy;
    Status status;
  } cases[] = {{gap, Status::Separated}, {0, Status::Touching}, {-T(0.75), Status::Penetrating}};
  for (const auto& c : cases) {
    const auto b = tri<T>(-1, c.dy, 1, c.dy, 0, 2 + c.dy);
    const Result<T> r = sat(a, b);
    EXPECT_EQ(r.status, c.status) << c.dy;
    EXPECT_NEAR(r.separation, c.dy, tol<T>()) << c.dy;
    EXPECT_NEAR(r.depth, c.dy < 0 ? -c.dy : 0, tol<T>());
    EXPECT_NEAR((r.normal - Vec2<T>(0, 1)).norm(), 0, tol<T>()) << c.dy;
  }
}

TYPED_TEST(Sat, FlatFaceOnFaceGivesTwoManifoldPointsWithTheirSeparations) {
  using T = TypeParam;
  const auto a = tri<T>(-5, 0, 0, -5, 5, 0);
  const auto b = tri<T>(-1, -0.1, 1, -0.1, 0, 2);
  const Result<T> r = sat(a, b, {Level::Manifold});
  ASSERT_EQ(r.status, Status::Penetrating);
  const Manifold<T>& m = r.manifold;
  ASSERT_EQ(m.point_count, 2);
  EXPECT_TRUE(m.reference_is_a);
  EXPECT_EQ(m.reference_edge, 2);  // A's edge from (5, 0) to (-5, 0)
  EXPECT_EQ(m.incident_edge, 0);   // B's edge from (-1, -0.1) to (1, -0.1)
  EXPECT_NEAR((m.normal - Vec2<T>(0, 1)).norm(), 0, tol<T>());
  for (int i = 0; i < 2; ++i) {
    EXPECT_NEAR(m.points[i].separation, -0.1, tol<T>());
    EXPECT_NEAR(m.points[i].point.y(), -0.1, tol<T>());
  }
  EXPECT_NE(m.points[0].key, m.points[1].key);
  // B's bottom lies flush with the reference face (0.1 too) and does not count; next are A's
  // slanted faces, 7/√2.
  EXPECT_NEAR(m.lead, 7 / std::sqrt(2.0) - 0.1, tol<T>());
}

TYPED_TEST(Sat, ManifoldClipsTheIncidentEdgeToTheReferenceFace) {
  using T = TypeParam;
  const auto a = tri<T>(-1, 0, 0, -5, 1, 0);       // top face y = 0, x in [-1, 1]
  const auto b = tri<T>(-3, -0.1, 3, -0.1, 0, 3);  // bottom face y = -0.1, x in [-3, 3]
  const Result<T> r = sat(a, b, {Level::Manifold});
  ASSERT_EQ(r.status, Status::Penetrating);
  const Manifold<T>& m = r.manifold;
  ASSERT_EQ(m.point_count, 2);
  // The two faces overlap 0.1 along y, a tie, and B's face is the reference only when it beats
  // A's by more than the hysteresis: A's top is the reference, B's bottom the incident edge.
  // Clipped to the reference face's side lines x = ±1, B's edge keeps x in [-1, 1]: the points
  // are (±1, -0.1), 0.1 deep. Unclipped they would be B's ends, x = ±3.
  EXPECT_TRUE(m.reference_is_a);
  for (int i = 0; i < m.point_count; ++i) {
    EXPECT_NEAR(std::abs(m.points[i].point.x()), 1, tol<T>()) << "point " << i;
    EXPECT_NEAR(m.points[i].point.y(), -0.1, tol<T>()) << "point " << i;
    EXPECT_NEAR(m.points[i].separation, -0.1, tol<T>()) << "point " << i;
  }
  EXPECT_NEAR(m.points[0].point.x() + m.points[1].point.x(), 0, tol<T>()) << "one at each end";
}

TYPED_TEST(Sat, ManifoldKeepsSpeculativePointsWithinTheMargin) {
  using T = TypeParam;
  const auto a = tri<T>(-5, 0, 0, -5, 5, 0);
  const auto b = tri<T>(-1, 0.01, 1, 0.01, 0, 2);  // 0.01 above A
  EXPECT_EQ(sat(a, b, {Level::Manifold}).manifold.point_count, 0);
  const Result<T> r = sat(a, b, {Level::Manifold, T(0.02)});
  EXPECT_EQ(r.status, Status::Separated);
  ASSERT_EQ(r.manifold.point_count, 2);
  EXPECT_NEAR(r.manifold.points[0].separation, 0.01, tol<T>());
}

TYPED_TEST(Sat, EachLevelLeavesTheFieldsOfHigherLevelsUntouched) {
  using T = TypeParam;
  const auto a = tri<T>(0, 0, 4, 0, 2, 4);
  const auto b = tri<T>(2, 0.5, 1, -2, 3, -2);
  const Result<T> overlap = sat(a, b, {Level::Overlap});
  EXPECT_EQ(overlap.status, Status::Penetrating);
  EXPECT_EQ(overlap.depth, 0);
  EXPECT_TRUE(overlap.normal.isZero());
  const Result<T> depth = sat(a, b, {Level::Depth});
  EXPECT_GT(depth.depth, 0);
  EXPECT_TRUE(depth.witness_a.isZero());
  EXPECT_EQ(depth.feature_a.type, Feature::Type::None);
  const Result<T> contact = sat(a, b, {Level::Contact});
  EXPECT_EQ(contact.feature_a.type, Feature::Type::Edge);
  EXPECT_EQ(contact.manifold.point_count, 0);
}

TYPED_TEST(Sat, OverlapLevelOnApartPairSaysSeparatedWithoutDistance) {
  using T = TypeParam;
  const auto a = tri<T>(0, 0, 1, 0, 0, 1);
  const auto b = tri<T>(5, 5, 6, 5, 5, 6);
  const Result<T> r = sat(a, b, {Level::Overlap});
  EXPECT_EQ(r.status, Status::Separated);
  EXPECT_EQ(r.separation, 0);  // not computed at this level
}

TYPED_TEST(Sat, ContainedTriangleDepthIsTheShortestWayOut) {
  using T = TypeParam;
  const auto a = tri<T>(0, 0, 10, 0, 0, 10);
  const auto b = tri<T>(1, 1, 2, 1, 1, 2);
  const Result<T> r = sat(a, b);
  EXPECT_EQ(r.status, Status::Penetrating);
  // B leaves through A's left or bottom edge: it must travel its own extent plus 1.
  EXPECT_NEAR(r.depth, 2, tol<T>());
}

}  // namespace
}  // namespace dyop
