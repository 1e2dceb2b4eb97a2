// make_triangle: a valid b2PolygonShape triangle, or an error naming the problem before Box2D
// asserts or silently turns the hull into a 2×2 box (2.4.1) or leaves it empty (2.4.2); the same
// shape, in 2.4.1's order, under both releases. What Box2D itself does with the points depends on
// the release and on whether its asserts are live: each test says which it expects.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <utility>

#include "dyop/box2d.hpp"
#include "dyop/box2d_release.hpp"
#include "support/box2d_library.hpp"
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

// Box2D's own Set on the same points, to show what the checks prevent: under 2.4.1 it asserts (its
// asserts are live in Debian's build) or, without asserts, makes a 2×2 box; under 2.4.2 it refuses
// more than make_triangle does and leaves the shape empty. (Under 2.4.2 the tests call it only in
// branches discarded at compile time: [[maybe_unused]].)
[[maybe_unused]] void box2d_set(const b2Vec2& p0, const b2Vec2& p1, const b2Vec2& p2) {
  const b2Vec2 points[3] = {p0, p1, p2};
  b2PolygonShape shape;
  testing::box2d_set(shape, points, 3);
}

// The vertices of `shape` are exactly `expected`, in that order.
void expect_vertices(const b2PolygonShape& shape, const std::array<b2Vec2, 3>& expected) {
  ASSERT_EQ(shape.m_count, 3);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(shape.m_vertices[i].x, expected[i].x) << "vertex " << i;
    EXPECT_EQ(shape.m_vertices[i].y, expected[i].y) << "vertex " << i;
  }
}

// Under 2.4.1 Box2D stores a 2×2 box (SetAsBox(1, 1)) where it cannot make the hull.
[[maybe_unused]] bool is_box2d_fallback_box(const b2PolygonShape& s) {
  return s.m_count == 4 && s.m_vertices[0].x == -1.0f && s.m_vertices[0].y == -1.0f &&
         s.m_vertices[2].x == 1.0f && s.m_vertices[2].y == 1.0f;
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
  const b2Vec2 points[3] = {p0, p1, p2};
  b2PolygonShape shape;
  if constexpr (box2d_release == Box2DRelease::V2_4_2) {
    EXPECT_FALSE(testing::box2d_set(shape, points, 3)) << "Box2D 2.4.2 refuses these points";
    EXPECT_EQ(shape.m_count, 0) << "and leaves its shape empty";
  } else if (box2d_asserts()) {
    EXPECT_DEATH(box2d_set(p0, p1, p2), "Assertion") << "Box2D 2.4.1 asserts on these points";
  } else {
    testing::box2d_set(shape, points, 3);
    EXPECT_TRUE(is_box2d_fallback_box(shape)) << "Box2D 2.4.1 without asserts makes a 2×2 box";
  }
}

TEST(MakeTriangle, RejectsThinTrianglesWhoseAreaBox2DsCentroidAssertsOn) {
  // 10 cm long, 2 µm high: area 1e-7 m² < b2_epsilon, far from degenerate for the library.
  const b2Vec2 p0(0.0f, 0.0f), p1(0.1f, 0.0f), p2(0.05f, 2e-6f);
  const TriangleShape t = make_triangle(p0, p1, p2);
  EXPECT_EQ(t.error, ShapeError::AreaTooSmall);
  EXPECT_NE(std::string(t.message).find("area"), std::string::npos) << t.message;
  if constexpr (box2d_release == Box2DRelease::V2_4_2) {
    const b2Vec2 points[3] = {p0, p1, p2};
    b2PolygonShape shape;
    EXPECT_FALSE(testing::box2d_set(shape, points, 3)) << "its quickhull drops p2: 2 µm off";
  }
  // Through the entry make_triangle builds with (2.4.1's Set, 2.4.2's Set(b2Hull)), in 2.4.1's
  // order (the rightmost first, CCW), Box2D's centroid asserts.
  if (!box2d_asserts()) GTEST_SKIP() << kNoAsserts;
  const b2Vec2 ordered[3] = {p1, p2, p0};
  b2PolygonShape shape;
  EXPECT_DEATH(box2d_set_hull(shape, ordered, 3), "ComputeCentroid");
}

TEST(MakeTriangle, RejectsTrianglesWhoseInertiaWouldOverflowFloat) {
  // 1.3e10 m across (found by the stress shapes test): Box2D's inertia at density 1 is infinite.
  // Built as make_triangle would (Box2D 2.4.2's own Set recurses without end on these points).
  const b2Vec2 p0(0.0f, 0.0f), p1(4.1e9f, -3.1e9f), p2(1.3e10f, 1.2e9f);
  b2PolygonShape shape;
  const b2Vec2 ordered[3] = {p2, p0, p1};  // the rightmost first, CCW
  box2d_set_hull(shape, ordered, 3);
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

TEST(MakeTriangle, AcceptsSmallButSoundTrianglesUnderEveryRelease) {
  // 1 cm sides: every vertex 1 cm from the others, area 5e-5 m². Box2D 2.4.2's own Set welds
  // them (its weld distance is 2 cm) and leaves its shape empty; make_triangle's is 2.4.1's.
  const b2Vec2 p0(0, 0), p1(0.01f, 0), p2(0, 0.01f);
  const TriangleShape t = make_triangle(p0, p1, p2);
  ASSERT_TRUE(t.ok()) << t.message;
  expect_vertices(t.shape, {p1, p2, p0});
  b2MassData mass;
  t.shape.ComputeMass(&mass, 1.0f);
  EXPECT_NEAR(mass.mass, 5e-5f, 1e-9f);
  const b2Vec2 points[3] = {p0, p1, p2};
  b2PolygonShape own;
  EXPECT_EQ(testing::box2d_set(own, points, 3), box2d_release == Box2DRelease::V2_4_1)
      << "Box2D " << name(box2d_release);
}

// The order Box2D 2.4.1's Set stores a counter-clockwise triangle in, from its rule: the point of
// greatest x (of two, the lower) first, then counter-clockwise.
std::array<b2Vec2, 3> box2d_241_order(std::array<b2Vec2, 3> p) {
  const double twice_area = (double(p[1].x) - p[0].x) * (double(p[2].y) - p[0].y) -
                            (double(p[1].y) - p[0].y) * (double(p[2].x) - p[0].x);
  if (twice_area < 0) std::swap(p[1], p[2]);
  int first = 0;
  for (int i = 1; i < 3; ++i) {
    if (p[i].x > p[first].x || (p[i].x == p[first].x && p[i].y < p[first].y)) first = i;
  }
  return {p[first], p[(first + 1) % 3], p[(first + 2) % 3]};
}

TEST(MakeTriangle, StoresTheVerticesInBox2D241sOrderUnderEveryRelease) {
  // Triangles from 1 cm to 10 km, on a 0.25 m grid (equal x or y coordinates: ties in the rule)
  // and anywhere, and slivers just above Triangle<float>::make's flatness tolerance, where Box2D
  // 2.4.1's float cross products come nearest to their rounding. Under 2.4.1 the shape is also bit
  // for bit Box2D's own Set of the same points (normals and centroid too); under 2.4.2 it is
  // what 2.4.1 makes, so that worlds and answers are the same.
  std::mt19937 rng(64);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  int accepted = 0;
  for (int k = 0; k < 20000; ++k) {
    const float scale = std::pow(10.0f, std::uniform_real_distribution<float>(-2.0f, 4.0f)(rng));
    std::array<b2Vec2, 3> p;
    for (b2Vec2& q : p) {
      q = b2Vec2(scale * unit(rng), scale * unit(rng));
      if (k % 3 == 0) q = b2Vec2(0.25f * std::round(4 * q.x), 0.25f * std::round(4 * q.y));
    }
    if (k % 3 == 1) {  // a sliver just above Triangle<float>::make's flatness tolerance
      const b2Vec2 d = p[1] - p[0];
      const float h = degenerate_tolerance<float>() * (1.0f + 8.0f * std::abs(unit(rng)));
      const float along = 0.5f + 0.6f * unit(rng);  // beyond an end too: another rightmost point
      p[2] = p[0] + along * d + (unit(rng) < 0 ? -h : h) * b2Vec2(-d.y, d.x);
    }
    const TriangleShape t = make_triangle(p[0], p[1], p[2]);
    if (!t.ok()) continue;
    ++accepted;
    SCOPED_TRACE(::testing::Message() << "triangle " << k);
    expect_vertices(t.shape, box2d_241_order(p));
    if constexpr (box2d_release == Box2DRelease::V2_4_1) {
      b2PolygonShape own;
      testing::box2d_set(own, p.data(), 3);
      for (int i = 0; i < 3; ++i) {
        EXPECT_EQ(t.shape.m_normals[i].x, own.m_normals[i].x);
        EXPECT_EQ(t.shape.m_normals[i].y, own.m_normals[i].y);
      }
      EXPECT_EQ(t.shape.m_centroid.x, own.m_centroid.x);
      EXPECT_EQ(t.shape.m_centroid.y, own.m_centroid.y);
    }
    if (HasFailure()) break;
  }
  EXPECT_GT(accepted, 15000);
}

}  // namespace
}  // namespace dyop::box2d::testing
