// Debug drawing (dyop/box2d_draw.hpp) draws what the rule and the contacts hold: a triangulated
// square's shared diagonal as internal and its sides as outline, a chain's segments as outline
// with the flat joints closed, the fixed edge data of a level where it is fixed, and a touching
// contact's manifold points where `GetWorldManifold` puts them.
#include <gtest/gtest.h>

#include <box2d/box2d.h>

#include <cmath>
#include <vector>

#include "dyop/box2d.hpp"
#include "dyop/box2d_draw.hpp"
#include "dyop/box2d_internal_edges.hpp"
#include "support/worlds.hpp"

namespace dyop::box2d::testing {
namespace {

bool same_color(const b2Color& x, const b2Color& y) {
  return x.r == y.r && x.g == y.g && x.b == y.b;
}

// Records the segments and points drawn, by colour.
class DrawRecorder : public b2Draw {
 public:
  struct Segment {
    b2Vec2 p, q;
    b2Color color;
  };
  struct Point {
    b2Vec2 p;
    b2Color color;
  };
  std::vector<Segment> segments;
  std::vector<Point> points;

  int segments_of(const b2Color& c) const {
    int n = 0;
    for (const Segment& s : segments) n += same_color(s.color, c);
    return n;
  }
  int points_of(const b2Color& c) const {
    int n = 0;
    for (const Point& p : points) n += same_color(p.color, c);
    return n;
  }

  void DrawSegment(const b2Vec2& p, const b2Vec2& q, const b2Color& color) override {
    segments.push_back({p, q, color});
  }
  void DrawPoint(const b2Vec2& p, float, const b2Color& color) override {
    points.push_back({p, color});
  }
  void DrawPolygon(const b2Vec2*, int32, const b2Color&) override {}
  void DrawSolidPolygon(const b2Vec2*, int32, const b2Color&) override {}
  void DrawCircle(const b2Vec2&, float, const b2Color&) override {}
  void DrawSolidCircle(const b2Vec2&, float, const b2Vec2&, const b2Color&) override {}
  void DrawTransform(const b2Transform&) override {}
};

const DrawStyle kDrawStyle;

TEST(DebugDraw, ASquareOfTwoTrianglesDrawsItsDiagonalInternalAndItsSidesOutline) {
  World world;
  b2Body* ground = add_body(world, b2_staticBody, b2Vec2(10, 5));  // drawn in the world frame
  add_triangle(ground, b2Vec2(0, 0), b2Vec2(1, 0), b2Vec2(1, 1));
  add_triangle(ground, b2Vec2(0, 0), b2Vec2(1, 1), b2Vec2(0, 1));
  DrawRecorder draw;
  draw_internal_edges(world.get(), draw);
  ASSERT_EQ(draw.segments.size(), 6u);
  EXPECT_EQ(draw.segments_of(kDrawStyle.internal), 2);  // the diagonal, once per triangle
  EXPECT_EQ(draw.segments_of(kDrawStyle.outline), 4);
  for (const DrawRecorder::Segment& s : draw.segments) {
    if (!same_color(s.color, kDrawStyle.internal)) continue;
    const bool forward = s.p == b2Vec2(10, 5) && s.q == b2Vec2(11, 6);
    const bool backward = s.p == b2Vec2(11, 6) && s.q == b2Vec2(10, 5);
    EXPECT_TRUE(forward || backward);
  }
  EXPECT_EQ(draw.points_of(kDrawStyle.closed), 0);  // a square's corners are convex
}

TEST(DebugDraw, AFlatGroundClosesItsInnerVerticesAndFixedEdgeDataDrawsTheSame) {
  World world;
  b2Body* ground = add_triangle_ground(world, 2.0f);  // four unit cells, two triangles each
  DrawRecorder found;
  draw_internal_edges(world.get(), found);
  fix_internal_edges(*ground);
  DrawRecorder fixed;
  draw_internal_edges(world.get(), fixed);
  EXPECT_GT(found.points_of(kDrawStyle.closed), 0);  // the flat runs' inner vertices
  for (const DrawRecorder::Point& p : found.points) {
    EXPECT_LT(std::abs(p.p.x), 2.0f) << "a corner of the ground is convex: never closed";
  }
  ASSERT_EQ(found.segments.size(), fixed.segments.size());
  for (std::size_t i = 0; i < found.segments.size(); ++i) {
    EXPECT_TRUE(same_color(found.segments[i].color, fixed.segments[i].color)) << "segment " << i;
  }
  EXPECT_EQ(found.points.size(), fixed.points.size());
}

TEST(DebugDraw, AChainDrawsEachSegmentAsOutlineAndClosesItsFlatJoints) {
  World world;
  b2Body* ground = add_body(world, b2_staticBody, b2Vec2(0, 0));
  const b2Vec2 v[] = {{0, 0}, {1, 0}, {2, 0}, {3, 1}};  // flat at (1, 0), a slope from (2, 0)
  b2ChainShape chain;
  chain.CreateChain(v, 4, b2Vec2(-1, 0), b2Vec2(4, 2));
  ground->CreateFixture(&chain, 0);
  DrawRecorder draw;
  draw_internal_edges(world.get(), draw);
  EXPECT_EQ(draw.segments_of(kDrawStyle.outline), 3);
  EXPECT_EQ(draw.segments_of(kDrawStyle.internal), 0);
  bool flat_joint_closed = false;
  for (const DrawRecorder::Point& p : draw.points) flat_joint_closed |= p.p == b2Vec2(1, 0);
  EXPECT_TRUE(flat_joint_closed);
}

TEST(DebugDraw, ContactsDrawTheTouchingManifoldPointsWithTheirNormals) {
  ASSERT_TRUE(install(Backend::Dyop).ok());
  {
    World world;
    add_triangle_ground(world, 3.0f);
    add_split_box(world, b2Vec2(0.3f, 0.5f), 0.5f);
    for (int i = 0; i < 30; ++i) world.step();
    std::vector<b2Vec2> expected;
    for (const b2Contact* c = world->GetContactList(); c != nullptr; c = c->GetNext()) {
      if (!c->IsTouching()) continue;
      b2WorldManifold wm;
      c->GetWorldManifold(&wm);
      for (int i = 0; i < c->GetManifold()->pointCount; ++i) expected.push_back(wm.points[i]);
    }
    ASSERT_FALSE(expected.empty());
    DrawRecorder draw;
    draw_contacts(world.get(), draw);
    ASSERT_EQ(draw.points.size(), expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i) EXPECT_EQ(draw.points[i].p, expected[i]);
    EXPECT_EQ(draw.segments_of(kDrawStyle.normal), static_cast<int>(expected.size()));
    for (const DrawRecorder::Segment& s : draw.segments) {
      EXPECT_NEAR((s.q - s.p).Length(), kDrawStyle.normal_length, 1e-5f);
    }
  }
  uninstall();
}

}  // namespace
}  // namespace dyop::box2d::testing
