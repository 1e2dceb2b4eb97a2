// make_triangle: a valid b2PolygonShape triangle, or an error naming the problem before Box2D
// asserts or silently turns the hull into a 1×1 box.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "dyop/box2d.hpp"
#include "support/worlds.hpp"

namespace dyop::box2d::testing {
namespace {

TEST(MakeTriangle, GivesBox2DsCounterClockwiseTriangleWhateverTheWinding) {
  for (bool clockwise : {false, true}) {
    const b2Vec2 p0(0.0f, 0.0f), p1(2.0f, 0.0f), p2(0.5f, 1.0f);
    const TriangleShape t = clockwise ? make_triangle(p0, p2, p1) : make_triangle(p0, p1, p2);
    ASSERT_TRUE(t.ok()) << t.message;
    EXPECT_EQ(t.error, ShapeError::None);
    const b2PolygonShape& s = t.shape;
    ASSERT_EQ(s.m_count, 3);
    EXPECT_EQ(s.m_radius, b2_polygonRadius);
    EXPECT_GT(b2Cross(s.m_vertices[1] - s.m_vertices[0], s.m_vertices[2] - s.m_vertices[0]), 0.0f);
    for (int i = 0; i < 3; ++i) {
      const b2Vec2 edge = s.m_vertices[(i + 1) % 3] - s.m_vertices[i];
      EXPECT_NEAR(s.m_normals[i].Length(), 1.0f, 1e-6f);
      EXPECT_NEAR(b2Dot(s.m_normals[i], edge), 0.0f, 1e-6f);
      EXPECT_LT(b2Dot(s.m_normals[i], s.m_centroid - s.m_vertices[i]), 0.0f) << "outward";
    }
  }
}

TEST(MakeTriangle, RejectsWhatTriangleMakeRejectsWithItsReason) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  const struct {
    b2Vec2 p0, p1, p2;
    TriangleError error;
  } cases[] = {
      {b2Vec2(nan, 0), b2Vec2(1, 0), b2Vec2(0, 1), TriangleError::NonFinite},
      {b2Vec2(0, 0), b2Vec2(inf, 0), b2Vec2(0, 1), TriangleError::NonFinite},
      {b2Vec2(0, 0), b2Vec2(1e30f, 0), b2Vec2(0, 1), TriangleError::TooLarge},
      {b2Vec2(0, 0), b2Vec2(1, 0), b2Vec2(1, 0), TriangleError::RepeatedVertex},
      {b2Vec2(0, 0), b2Vec2(1, 1), b2Vec2(2, 2), TriangleError::Degenerate},
  };
  for (const auto& c : cases) {
    const TriangleShape t = make_triangle(c.p0, c.p1, c.p2);
    EXPECT_EQ(t.error, ShapeError::Triangle);
    EXPECT_EQ(t.triangle_error, c.error) << t.message;
    EXPECT_STREQ(t.message, describe(c.error));
  }
}

// Box2D's own Set on the same points, to show what the checks prevent (its asserts are live in
// the Debian build).
void box2d_set(const b2Vec2& p0, const b2Vec2& p1, const b2Vec2& p2) {
  const b2Vec2 points[3] = {p0, p1, p2};
  b2PolygonShape shape;
  shape.Set(points, 3);
}

TEST(MakeTriangle, RejectsVerticesBox2DWouldWeld) {
  // 2 mm apart: under 0.5·b2_linearSlop, yet a fine triangle for the library (not degenerate).
  const b2Vec2 p0(0.0f, 0.0f), p1(0.002f, 0.0f), p2(0.0f, 1.0f);
  ASSERT_TRUE(
      Triangle<float>::make(Vec2<float>(0, 0), Vec2<float>(0.002f, 0), Vec2<float>(0, 1)).ok());
  const TriangleShape t = make_triangle(p0, p1, p2);
  EXPECT_EQ(t.error, ShapeError::VerticesTooClose);
  EXPECT_STREQ(t.message, describe(ShapeError::VerticesTooClose));
  EXPECT_NE(std::string(t.message).find("weld"), std::string::npos) << t.message;
  EXPECT_DEATH(box2d_set(p0, p1, p2), "Assertion") << "Box2D asserts on these points";
}

TEST(MakeTriangle, RejectsThinTrianglesWhoseAreaBox2DsCentroidAssertsOn) {
  // 10 cm long, 2 µm high: area 1e-7 m² < b2_epsilon, far from degenerate for the library.
  const b2Vec2 p0(0.0f, 0.0f), p1(0.1f, 0.0f), p2(0.05f, 2e-6f);
  const TriangleShape t = make_triangle(p0, p1, p2);
  EXPECT_EQ(t.error, ShapeError::AreaTooSmall);
  EXPECT_NE(std::string(t.message).find("area"), std::string::npos) << t.message;
  EXPECT_DEATH(box2d_set(p0, p1, p2), "ComputeCentroid") << "Box2D asserts on these points";
}

TEST(MakeTriangle, RejectsTrianglesWhoseInertiaWouldOverflowFloat) {
  // 1.3e10 m across (found by the stress shapes test): Box2D's inertia at density 1 is infinite.
  const b2Vec2 p0(0.0f, 0.0f), p1(4.1e9f, -3.1e9f), p2(1.3e10f, 1.2e9f);
  b2PolygonShape shape;
  const b2Vec2 points[3] = {p0, p1, p2};
  shape.Set(points, 3);
  b2MassData mass;
  shape.ComputeMass(&mass, 1.0f);
  ASSERT_FALSE(std::isfinite(mass.I)) << "Box2D's inertia of these points overflows";
  const TriangleShape t = make_triangle(p0, p1, p2);
  EXPECT_EQ(t.error, ShapeError::TooLarge);
  EXPECT_NE(std::string(t.message).find("inertia"), std::string::npos) << t.message;
  // At the limit the inertia is finite.
  const b2Vec2 q1(max_triangle_coordinate, 0.0f), q2(0.0f, max_triangle_coordinate);
  const TriangleShape ok = make_triangle(p0, q1, q2);
  ASSERT_TRUE(ok.ok()) << ok.message;
  ok.shape.ComputeMass(&mass, 100.0f);
  EXPECT_TRUE(std::isfinite(mass.I));
}

TEST(MakeTriangle, AcceptsSmallButSoundTriangles) {
  // 1 cm sides: every vertex 1 cm from the others, area 5e-5 m².
  const TriangleShape t = make_triangle(b2Vec2(0, 0), b2Vec2(0.01f, 0), b2Vec2(0, 0.01f));
  EXPECT_TRUE(t.ok()) << t.message;
}

}  // namespace
}  // namespace dyop::box2d::testing
