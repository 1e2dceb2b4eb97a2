// Triangle validation and winding normalisation.
#include <gtest/gtest.h>

#include <limits>

#include "dyop/triangle.hpp"

namespace dyop {
namespace {

using V = Vec2<double>;

TEST(Triangle, NonFiniteCoordinateIsRejectedByName) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(Triangle<double>::make(V(nan, 0), V(1, 0), V(0, 1)).error, TriangleError::NonFinite);
  EXPECT_EQ(Triangle<double>::make(V(0, 0), V(1, inf), V(0, 1)).error, TriangleError::NonFinite);
  EXPECT_EQ(Triangle<float>::make(Vec2<float>(0, 0), Vec2<float>(1, 0),
                                  Vec2<float>(0, -std::numeric_limits<float>::infinity()))
                .error,
            TriangleError::NonFinite);
  EXPECT_NE(std::string(describe(TriangleError::NonFinite)).find("non-finite"), std::string::npos);
}

TEST(Triangle, RepeatedVertexIsRejectedByName) {
  EXPECT_EQ(Triangle<double>::make(V(0, 0), V(0, 0), V(0, 1)).error, TriangleError::RepeatedVertex);
  EXPECT_EQ(Triangle<double>::make(V(0, 0), V(1, 0), V(0, 0)).error, TriangleError::RepeatedVertex);
  EXPECT_NE(std::string(describe(TriangleError::RepeatedVertex)).find("repeated"),
            std::string::npos);
}

TEST(Triangle, CollinearAndNearlyCollinearAreDegenerate) {
  EXPECT_EQ(Triangle<double>::make(V(0, 0), V(1, 1), V(2, 2)).error, TriangleError::Degenerate);
  // Height 1e-15 over a unit base: below the 64·eps flatness tolerance (1.4e-14).
  EXPECT_EQ(Triangle<double>::make(V(0, 0), V(1, 0), V(0.5, 1e-15)).error,
            TriangleError::Degenerate);
  // Height 1e-13: above it, a valid (thin) triangle.
  EXPECT_TRUE(Triangle<double>::make(V(0, 0), V(1, 0), V(0.5, 1e-13)).ok());
  // Float's tolerance is 7.6e-6: 1e-6 is degenerate in float, 1e-4 is not.
  using F = Vec2<float>;
  EXPECT_EQ(Triangle<float>::make(F(0, 0), F(1, 0), F(0.5f, 1e-6f)).error,
            TriangleError::Degenerate);
  EXPECT_TRUE(Triangle<float>::make(F(0, 0), F(1, 0), F(0.5f, 1e-4f)).ok());
}

TEST(Triangle, FlatnessIsJudgedRelativeToSizeNotAbsolutely) {
  // The same shape at 1e-9 and at 1e9 scale, and a million units from the origin.
  for (double s : {1e-9, 1.0, 1e9}) {
    EXPECT_TRUE(Triangle<double>::make(V(0, 0), V(s, 0), V(0.5 * s, 1e-6 * s)).ok()) << s;
  }
  const V o(1e6, -1e6);
  EXPECT_TRUE(Triangle<double>::make(o + V(0, 0), o + V(1, 0), o + V(0.5, 1e-6)).ok());
}

TEST(Triangle, CoordinatesWhoseSquaresWouldOverflowAreRejectedAsTooLarge) {
  const double big = std::numeric_limits<double>::max() / 2;
  EXPECT_EQ(Triangle<double>::make(V(-big, 0), V(1, 0), V(0, 1)).error, TriangleError::TooLarge);
  EXPECT_TRUE(Triangle<double>::make(V(-1e150, 0), V(1e150, 0), V(0, 1e150)).ok());
  using F = Vec2<float>;
  EXPECT_EQ(Triangle<float>::make(F(0, 0), F(1e19f, 0), F(0, 1)).error, TriangleError::TooLarge);
  EXPECT_TRUE(Triangle<float>::make(F(0, 0), F(1e18f, 0), F(0, 1e18f)).ok());
}

TEST(Triangle, TrianglesWhoseSquaredLengthsWouldUnderflowAreRejectedAsTooSmall) {
  // Float: a 1e-23 edge squares to zero; the whole triangle is far below min_size (9.1e-13).
  using F = Vec2<float>;
  EXPECT_EQ(Triangle<float>::make(F(0, 0), F(1e-23f, 0), F(5e-20f, 1e-19f)).error,
            TriangleError::TooSmall);
  EXPECT_EQ(Triangle<double>::make(V(0, 0), V(1e-162, 0), V(5e-156, 1e-155)).error,
            TriangleError::TooSmall);
  EXPECT_TRUE(Triangle<float>::make(F(0, 0), F(1e-12f, 0), F(0, 1e-12f)).ok());
  EXPECT_TRUE(Triangle<double>::make(V(0, 0), V(1e-138, 0), V(0, 1e-138)).ok());
  EXPECT_NE(std::string(describe(TriangleError::TooSmall)).find("too small"), std::string::npos);
}

TEST(Triangle, CounterClockwiseInputIsKeptInOrder) {
  const auto t = Triangle<double>::make(V(0, 0), V(2, 0), V(0, 1));
  ASSERT_TRUE(t.ok());
  EXPECT_FALSE(t.triangle.flipped());
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(t.triangle.input_vertex(i), i);
    EXPECT_EQ(t.triangle.input_edge(i), i);
  }
  EXPECT_DOUBLE_EQ(t.triangle.size(), std::sqrt(5.0));
}

TEST(Triangle, ClockwiseInputIsStoredCounterClockwiseAndIndicesMapBack) {
  const V p[3] = {V(0, 0), V(0, 1), V(2, 0)};  // clockwise
  const auto t = Triangle<double>::make(p[0], p[1], p[2]);
  ASSERT_TRUE(t.ok());
  EXPECT_TRUE(t.triangle.flipped());
  for (int i = 0; i < 3; ++i) {
    // Every stored vertex is the caller's vertex it maps to.
    EXPECT_EQ(t.triangle.vertex(i), p[t.triangle.input_vertex(i)]);
    // Stored edge i joins the caller's vertices of caller edge input_edge(i), reversed.
    const int e = t.triangle.input_edge(i);
    EXPECT_EQ(t.triangle.vertex(i), p[(e + 1) % 3]);
    EXPECT_EQ(t.triangle.vertex((i + 1) % 3), p[e]);
  }
}

TEST(Triangle, NormalsAreUnitAndPointOutward) {
  const auto t = Triangle<double>::make(V(0.3, -1), V(-2, 0.7), V(4, 2));
  ASSERT_TRUE(t.ok());
  const V centroid = (t.triangle.vertex(0) + t.triangle.vertex(1) + t.triangle.vertex(2)) / 3;
  for (int i = 0; i < 3; ++i) {
    const V& n = t.triangle.normal(i);
    EXPECT_NEAR(n.norm(), 1.0, 1e-15);
    EXPECT_NEAR(n.dot(t.triangle.vertex((i + 1) % 3) - t.triangle.vertex(i)), 0.0, 1e-14);
    EXPECT_GT(n.dot(t.triangle.vertex(i) - centroid), 0.0);
  }
}

TEST(Triangle, MovedRotatesVerticesAndNormalsAndKeepsTheRest) {
  const auto t = Triangle<double>::make(V(0, 0), V(0, 1), V(2, 0));  // clockwise
  ASSERT_TRUE(t.ok());
  const double angle = 0.7;
  const Triangle<double> m = t.triangle.moved(std::cos(angle), std::sin(angle), V(10, -3));
  const auto remade = Triangle<double>::make(m.vertex(0), m.vertex(1), m.vertex(2));
  ASSERT_TRUE(remade.ok());
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR((m.normal(i) - remade.triangle.normal(i)).norm(), 0, 1e-15);
    EXPECT_EQ(m.edge_length(i), t.triangle.edge_length(i));
    EXPECT_EQ(m.input_vertex(i), t.triangle.input_vertex(i));
  }
  EXPECT_EQ(m.size(), t.triangle.size());
  EXPECT_NEAR((m.vertex(0) - V(10, -3)).norm(), 0, 1e-15);
}

}  // namespace
}  // namespace dyop
