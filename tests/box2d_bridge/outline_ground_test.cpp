// `add_outline`: an outline with holes triangulated so that the triangles cover exactly the
// polygon, every triangle valid for Box2D with its edge data fixed as the rule finds it and every
// edge inside the ground internal; hostile outlines refused with their reason and nothing
// created, or triangulated; and everyday bodies gliding over a triangulated outline.
#include <gtest/gtest.h>

#include <box2d/box2d.h>

#include <cmath>
#include <vector>

#include "dyop/box2d.hpp"
#include "dyop/box2d_internal_edges.hpp"
#include "dyop/box2d_outline.hpp"
#include "support/rings.hpp"
#include "support/worlds.hpp"

namespace dyop::box2d::testing {
namespace {

double ring_area(const Ring& ring) {
  double sum = 0;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const b2Vec2& p = ring[i];
    const b2Vec2& q = ring[(i + 1) % ring.size()];
    sum += static_cast<double>(p.x) * q.y - static_cast<double>(q.x) * p.y;
  }
  return std::abs(sum) / 2;
}

Ring shifted(Ring ring, const b2Vec2& by) {
  for (b2Vec2& p : ring) p += by;
  return ring;
}

// How far a point of a cell's piece may move (metres): rounded to a grid of 1/256 m
// (`add_outline`).
constexpr double kCellRounding = 0.5 * 1.4143 / 256;

// The outline's triangles cover its area (the outline's less its holes'), each with fixed edge
// data equal to what the rule finds; the edges not internal run along the rings (their lengths
// sum to the rings' perimeter) and, for one triangulation of the whole outline (`ring_edges` ≥ 0),
// are the rings' edges (counted by hand after the simplification). `moved`: how far a point may
// have moved (0: not at all; `kCellRounding` in cells).
void expect_exact_ground(const OutlineResult& r, const std::vector<Ring>& rings,
                         int ring_edges = -1, double moved = kCellRounding) {
  ASSERT_TRUE(r.ok()) << r.message;
  double area = ring_area(rings[0]);
  for (std::size_t i = 1; i < rings.size(); ++i) area -= ring_area(rings[i]);
  double covered = 0;
  double outer_length = 0;
  int outer_edges = 0;
  for (const b2Fixture* f : r.mesh.fixtures) {
    ASSERT_EQ(f->GetType(), b2Shape::e_polygon);
    const auto* shape = static_cast<const b2PolygonShape*>(f->GetShape());
    ASSERT_EQ(shape->m_count, 3);
    covered += ring_area({shape->m_vertices[0], shape->m_vertices[1], shape->m_vertices[2]});
    const std::optional<ShapeMasks> fixed = fixed_polygon_edges(*f);
    ASSERT_TRUE(fixed.has_value());
    EXPECT_EQ(*fixed, polygon_internal_edges(*f));
    for (int e = 0; e < 3; ++e) {
      if ((fixed->edges >> e) & 1) continue;
      ++outer_edges;
      outer_length += (shape->m_vertices[(e + 1) % 3] - shape->m_vertices[e]).Length();
    }
  }
  EXPECT_NEAR(covered, area, 1e-5 * area + moved * perimeter(rings));
  EXPECT_NEAR(outer_length, perimeter(rings), 1e-4 * perimeter(rings) + 2 * moved * outer_edges);
  if (ring_edges >= 0) {
    EXPECT_EQ(outer_edges, ring_edges);
  }
}

// One triangulation of the whole outline (no cells): its counts are worked by hand.
OutlineOptions whole(float simplify = b2_linearSlop) {
  OutlineOptions o;
  o.simplify = simplify;
  o.cell = 0;
  return o;
}

TEST(OutlineGround, AnOutlineWithCavesIsCoveredExactlyWithEveryInnerEdgeInternal) {
  World world;
  b2Body* ground = add_body(world, b2_staticBody, b2Vec2(0, 0));
  const std::vector<Ring> rings = {
      {{0, 0}, {20, 0}, {20, 4}, {14, 6}, {8, 4}, {0, 5}},  // clockwise or not: either winding
      rectangle(2, 1, 4, 2),
      {{10, 1}, {12, 3}, {9, 2.5f}}};
  const OutlineResult r = add_outline(*ground, rings, whole());
  expect_exact_ground(r, rings, 6 + 4 + 3, 0);
  EXPECT_EQ(r.vertices, 6 + 4 + 3);
  EXPECT_EQ(static_cast<int>(r.mesh.fixtures.size()), 6 + 4 + 3 + 2 * 2 - 2);  // V + 2H - 2
  // In 2 m cells (the default), a hole's vertex on a cell's side among them.
  b2Body* cells = add_body(world, b2_staticBody, b2Vec2(0, 30));
  expect_exact_ground(add_outline(*cells, rings), rings);
}

TEST(OutlineGround, HostileOutlinesAreTriangulatedExactly) {
  struct Case {
    const char* name;
    std::vector<Ring> rings;
    float simplify;
    int vertices;    // distinct vertices triangulated
    int ring_edges;  // the rings' edges once simplified
  };
  Ring collinear;  // a straight top of 0.1 m steps, and a bump that is one float step high
  for (int i = 0; i <= 100; ++i) collinear.push_back({10.0f - 0.1f * static_cast<float>(i), 2});
  collinear.insert(collinear.end(), {{0, 0}, {10, 0}});
  Ring tiny = rectangle(0, 0, 4, 2);
  tiny.insert(tiny.begin() + 2, {4.0f, 1.0f});
  tiny.insert(tiny.begin() + 3, {4.0001f, 1.0001f});  // an edge of 0.14 mm
  const std::vector<Case> cases = {
      {"collinear run, simplified", {collinear}, b2_linearSlop, 4, 4},
      {"collinear run, every vertex kept", {collinear}, 0, 103, 103},
      {"tiny edge", {tiny}, b2_linearSlop, 4, 4},
      {"hole touching the outline at a vertex",
       {rectangle(0, 0, 6, 3), {{0, 0}, {2, 1}, {1, 2}}},
       b2_linearSlop,
       6,
       7},
      {"holes touching each other at a vertex",
       {rectangle(0, 0, 8, 4), rectangle(1, 1, 3, 3), {{3, 3}, {5, 2}, {4, 3.5f}}},
       b2_linearSlop,
       10,
       11},
      {"1e4 m from the origin",
       {shifted(rectangle(0, 0, 40, 6), {1e4f, 1e4f}),
        shifted(rectangle(10, 2, 14, 4), {1e4f, 1e4f})},
       b2_linearSlop,
       8,
       8},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    World world;
    b2Body* ground = add_body(world, b2_staticBody, b2Vec2(0, 0));
    const OutlineResult r = add_outline(*ground, c.rings, whole(c.simplify));
    expect_exact_ground(r, c.rings, c.ring_edges, 0);
    EXPECT_EQ(r.vertices, c.vertices);
    OutlineOptions in_cells;
    in_cells.simplify = c.simplify;
    b2Body* cells = add_body(world, b2_staticBody, b2Vec2(0, 0));
    expect_exact_ground(add_outline(*cells, c.rings, in_cells), c.rings);
  }
}

TEST(OutlineGround, RefusedOutlinesSayWhyAndCreateNothing) {
  const float nan = std::nanf("");
  struct Case {
    std::vector<Ring> rings;
    OutlineError error;
    int ring;
  };
  const Ring outline = rectangle(0, 0, 10, 10);
  const std::vector<Case> cases = {
      {{}, OutlineError::NoRings, -1},
      {{outline, {{1, 1}, {2, 1}, {nan, 2}}}, OutlineError::NotFinite, 1},
      {{{{0, 0}, {1, 0}, {1, 0}, {0, 0}}}, OutlineError::TooFewPoints, 0},
      {{{{0, 0}, {1, 1}, {2, 2}, {3, 3}}}, OutlineError::ZeroArea, 0},
      {{{{0, 0}, {4, 4}, {4, 0}, {0, 6}}}, OutlineError::SelfIntersection, -1},  // a bow tie
      {{outline, rectangle(8, 8, 12, 9)}, OutlineError::SelfIntersection, -1},   // crosses
      {{outline, rectangle(20, 20, 22, 22)}, OutlineError::HoleOutside, -1},
      {{outline, rectangle(1, 1, 9, 9), rectangle(3, 3, 4, 4)}, OutlineError::NestedHoles, -1},
      // A diamond touching the middle of each side: the ground in four corners.
      {{outline, {{5, 0}, {10, 5}, {5, 10}, {0, 5}}}, OutlineError::SplitInterior, -1},
  };
  for (const Case& c : cases) {
    World world;
    b2Body* ground = add_body(world, b2_staticBody, b2Vec2(0, 0));
    const OutlineResult r = add_outline(*ground, c.rings);
    EXPECT_EQ(r.error, c.error) << r.message;
    EXPECT_EQ(r.ring, c.ring) << describe(c.error);
    EXPECT_STREQ(r.message, describe(c.error));
    EXPECT_EQ(ground->GetFixtureList(), nullptr) << describe(c.error);
  }
}

// A box, a hexagon, a ball and a box of two triangles pushed at 4 m/s along the flat top of a
// triangulated outline with a cave under it, every vertex of the top kept (0.1 m apart): they
// glide, as over Box2D's chain, with the plug-in installed.
TEST(OutlineGround, EverydayBodiesGlideOverATriangulatedOutline) {
  ASSERT_TRUE(install(Backend::Dyop).ok());
  Ring outline;
  for (int i = 0; i <= 200; ++i) outline.push_back({20.0f - 0.1f * static_cast<float>(i), 0});
  outline.insert(outline.end(), {{0, -3}, {20, -3}});
  const std::vector<Ring> rings = {outline, rectangle(3, -2, 15, -0.5f)};
  b2PolygonShape box;
  box.SetAsBox(0.25f, 0.3f);
  b2PolygonShape hexagon;
  b2Vec2 corners[6];
  for (int i = 0; i < 6; ++i) {
    const float a = static_cast<float>(i) * b2_pi / 3;
    corners[i] = {0.3f * std::cos(a), 0.3f * std::sin(a)};
  }
  hexagon.Set(corners, 6);
  b2CircleShape ball;
  ball.m_radius = 0.3f;
  const b2Shape* bodies[] = {&box, &hexagon, &ball, nullptr};  // nullptr: a box of 2 triangles
  for (const b2Shape* shape : bodies) {
    World world;
    b2Body* ground = add_body(world, b2_staticBody, b2Vec2(0, 0));
    OutlineOptions options;
    options.simplify = 0;
    ASSERT_TRUE(add_outline(*ground, rings, options).ok());
    // Resting on the ground, 5 mm above it.
    b2AABB box_of;
    if (shape) shape->ComputeAABB(&box_of, b2Transform(b2Vec2(0, 0), b2Rot(0)), 0);
    const b2Vec2 start(1, (shape ? -box_of.lowerBound.y : 0.3f) + 0.005f);
    b2Body* glider =
        shape ? add_body(world, b2_dynamicBody, start) : add_split_box(world, start, 0.3f, kIce);
    if (shape) {
      b2FixtureDef def;
      def.friction = 0;
      def.density = 1;
      def.shape = shape;
      glider->CreateFixture(&def);
    }
    glider->SetLinearVelocity(b2Vec2(4.0f, 0));
    float max_vertical = 0;
    for (int i = 0; i < 3 * kStepsPerSecond; ++i) {
      world.step();
      if (i > 0) max_vertical = std::max(max_vertical, std::abs(glider->GetLinearVelocity().y));
    }
    const char* name = shape == &box       ? "box"
                       : shape == &hexagon ? "hexagon"
                       : shape             ? "ball"
                                           : "triangles";
    EXPECT_LE(max_vertical, 0.05f) << name;
    EXPECT_GE(glider->GetPosition().x - 1, 0.98f * 4.0f * 3.0f) << name;
  }
  ASSERT_TRUE(uninstall().ok());
}

// An L of three 0.25 m squares (six triangles, its bottom two squares long) pushed at 6 m/s along
// a 78 m outline with a vertex every 0.25 m, built with the defaults (the top simplified to 2 m
// edges, triangles within 2 m cells): where the L's bottom straddles a cell's corner, its closed
// middle vertex and the ground's closed corner are the deepest along each other's faces; the flat
// outline edges there keep the pair's support. It glides (it was thrown up at 0.089 m/s when
// those vertices alone decided).
TEST(OutlineGround, LOfSixTrianglesGlidesOverTheDefaultSimplifiedTop) {
  ASSERT_TRUE(install(Backend::Dyop).ok());
  Ring outline;
  for (int i = 0; i <= 312; ++i) outline.push_back({-15.0f + 0.25f * static_cast<float>(i), 0});
  outline.insert(outline.end(), {{63, -4}, {-15, -4}});
  World world;
  b2Body* ground = add_body(world, b2_staticBody, b2Vec2(0, 0));
  ASSERT_TRUE(add_outline(*ground, {outline}).ok());
  b2Body* l = add_body(world, b2_dynamicBody, b2Vec2(0, 0));
  const float squares[3][2] = {{0, 0}, {0.25f, 0}, {0, 0.25f}};
  for (const auto& c : squares) {
    const b2Vec2 bl(c[0], c[1]);
    add_triangle(l, bl, bl + b2Vec2(0.25f, 0), bl + b2Vec2(0.25f, 0.25f), kIce);
    add_triangle(l, bl, bl + b2Vec2(0.25f, 0.25f), bl + b2Vec2(0, 0.25f), kIce);
  }
  l->SetLinearVelocity(b2Vec2(6.0f, 0));
  float max_vertical = 0;
  for (int i = 0; i < 6 * kStepsPerSecond; ++i) {
    world.step();
    if (i > 2) max_vertical = std::max(max_vertical, std::abs(l->GetLinearVelocity().y));
  }
  EXPECT_LE(max_vertical, 0.05f);
  EXPECT_GE(l->GetPosition().x, 0.98f * 6.0f * 6.0f);
  ASSERT_TRUE(uninstall().ok());
}

}  // namespace
}  // namespace dyop::box2d::testing
