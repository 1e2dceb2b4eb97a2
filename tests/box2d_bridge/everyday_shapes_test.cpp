// The bodies games are made of — a `SetAsBox` box, a hexagon, a ball, a box of two triangles —
// glide without ghost collisions over a triangulated ground and over tile maps (tiles of two
// triangles, or a `SetAsBox` fixture per tile) with the plug-in installed by its defaults, where
// Box2D's own contact trips them; `Config::triangles_only` and `Backend::Box2D` keep Box2D's own
// answers for them.
#include <gtest/gtest.h>

#include <box2d/box2d.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "dyop/box2d.hpp"
#include "dyop/box2d_internal_edges.hpp"
#include "dyop/box2d_mesh.hpp"
#include "support/level_gliders.hpp"
#include "support/worlds.hpp"

namespace dyop::box2d::testing {
namespace {

constexpr float kShapePushSpeed = kLevelPushSpeed;  // m/s, frictionless
constexpr float kShapeGlideSeconds = 4.0f;
// The bounds for a glide: vertical speed after the push, and the share of the free
// travel (speed · time) a body makes.
constexpr float kShapeGlideVertical = 0.05f;
constexpr float kShapeGlideTravel = 0.98f;

enum class ShapeGround { TriangleGrid, TriangleTiles, BoxTiles };
using ShapeBody = LevelBody;
// The bodies' dimensions here: boxes 0.5 m on a side, a hexagon of circumradius 0.5 m.
constexpr GliderSize kShapeSize{0.5f, 0.5f, 0.5f, 0.3f};

const char* name(ShapeGround g) {
  switch (g) {
    case ShapeGround::TriangleGrid:
      return "a 0.25 m grid of triangles (add_triangles)";
    case ShapeGround::TriangleTiles:
      return "tiles of two triangles, fixture by fixture";
    case ShapeGround::BoxTiles:
      return "a SetAsBox fixture per tile";
  }
  return "";
}

const char* shape_name(ShapeBody b) {
  switch (b) {
    case ShapeBody::TriangleBox:
      return "box of two triangles";
    case ShapeBody::Box:
      return "SetAsBox box";
    case ShapeBody::Hexagon:
      return "hexagon r = 0.5 m";
    case ShapeBody::Ball:
      return "circle r = 0.3 m";
  }
  return "";
}

// A static ground whose top is y = 0 over [x0, x0 + length], two cells deep.
void add_shape_ground(World& world, ShapeGround kind, float x0, float length) {
  b2Body* ground = add_body(world, b2_staticBody, b2Vec2(0, 0));
  const float cell = kind == ShapeGround::TriangleGrid ? 0.25f : 0.5f;
  const int columns = static_cast<int>(std::lround(length / cell));
  if (kind == ShapeGround::TriangleGrid) {
    std::vector<b2Vec2> vertices;
    std::vector<int> indices;
    for (int row = 0; row <= 2; ++row) {
      for (int i = 0; i <= columns; ++i) vertices.emplace_back(x0 + i * cell, -row * cell);
    }
    const auto at = [&](int row, int i) { return row * (columns + 1) + i; };
    for (int row = 0; row < 2; ++row) {
      for (int i = 0; i < columns; ++i) {
        indices.insert(indices.end(), {at(row, i), at(row + 1, i), at(row, i + 1)});
        indices.insert(indices.end(), {at(row, i + 1), at(row + 1, i), at(row + 1, i + 1)});
      }
    }
    const MeshResult r = add_triangles(*ground, vertices.data(), static_cast<int>(vertices.size()),
                                       indices.data(), static_cast<int>(indices.size()));
    ASSERT_TRUE(r.ok()) << r.message;
    return;
  }
  for (int row = 0; row < 2; ++row) {
    for (int i = 0; i < columns; ++i) {
      const b2Vec2 bl(x0 + i * cell, -(row + 1) * cell);
      const b2Vec2 tr(x0 + (i + 1) * cell, -row * cell);
      if (kind == ShapeGround::TriangleTiles) {
        add_triangle(ground, b2Vec2(bl.x, tr.y), bl, tr, kIce);
        add_triangle(ground, tr, bl, b2Vec2(tr.x, bl.y), kIce);
      } else {
        b2PolygonShape tile;
        tile.SetAsBox(0.5f * cell, 0.5f * cell, 0.5f * (bl + tr), 0);
        b2FixtureDef def;
        def.shape = &tile;
        def.friction = 0;
        ground->CreateFixture(&def);
      }
    }
  }
}

struct ShapeGlide {
  float max_vertical = 0;  // largest |vy| after the first step, m/s
  float travel = 0;        // share of the free travel speed · time
};

ShapeGlide shape_glide(ShapeGround ground, ShapeBody body) {
  World world;
  add_shape_ground(world, ground, -2.0f, kShapePushSpeed * kShapeGlideSeconds + 4.0f);
  b2Body* glider = add_level_glider(world, body, true, kShapeSize);
  ShapeGlide g;
  const int steps = static_cast<int>(kShapeGlideSeconds * kStepsPerSecond);
  for (int step = 0; step < steps; ++step) {
    world.step();
    if (step > 0)
      g.max_vertical = std::max(g.max_vertical, std::abs(glider->GetLinearVelocity().y));
  }
  g.travel = glider->GetPosition().x / (kShapePushSpeed * kShapeGlideSeconds);
  return g;
}

struct ShapeCase {
  ShapeGround ground;
  ShapeBody body;
};

class EverydayShapes : public ::testing::TestWithParam<ShapeCase> {};

TEST_P(EverydayShapes, GlideWithoutGhostCollisionsWhereBox2DsOwnContactTrips) {
  const ShapeCase c = GetParam();
  ASSERT_TRUE(uninstall().ok());
  const ShapeGlide own = shape_glide(c.ground, c.body);
  ASSERT_TRUE(install(Backend::Dyop).ok());
  const ShapeGlide g = shape_glide(c.ground, c.body);
  const Stats s = stats();
  ASSERT_TRUE(uninstall().ok());
  std::printf("%s on %s: plug-in %.3f m/s, %.1f %% of the glide; Box2D's own %.3f m/s, %.1f %%\n",
              shape_name(c.body), name(c.ground), g.max_vertical, 100 * g.travel, own.max_vertical,
              100 * own.travel);
  EXPECT_LE(g.max_vertical, kShapeGlideVertical);
  EXPECT_GE(g.travel, kShapeGlideTravel);
  if (c.body != ShapeBody::TriangleBox || c.ground == ShapeGround::BoxTiles) {
    EXPECT_GT(s.exact_pairs, 0u);  // answered by the exact solver, not by Box2D's functions
  }
}

std::vector<ShapeCase> all_shape_cases() {
  std::vector<ShapeCase> out;
  for (ShapeGround g :
       {ShapeGround::TriangleGrid, ShapeGround::TriangleTiles, ShapeGround::BoxTiles}) {
    for (ShapeBody b :
         {ShapeBody::TriangleBox, ShapeBody::Box, ShapeBody::Hexagon, ShapeBody::Ball})
      out.push_back({g, b});
  }
  return out;
}

std::string shape_case_name(const ::testing::TestParamInfo<ShapeCase>& info) {
  static const char* grounds[] = {"TriangleGrid", "TriangleTiles", "BoxTiles"};
  static const char* bodies[] = {"TriangleBox", "Box", "Hexagon", "Ball"};
  return std::string(grounds[static_cast<int>(info.param.ground)]) + "_" +
         bodies[static_cast<int>(info.param.body)];
}

INSTANTIATE_TEST_SUITE_P(OnGroundsAndTileMaps, EverydayShapes,
                         ::testing::ValuesIn(all_shape_cases()), shape_case_name);

// `Config::triangles_only` keeps the plug-in to triangle pairs (0.1's behaviour): a `SetAsBox`
// box trips as under Box2D's own contact, bit for bit.
TEST(EverydayShapesTrianglesOnly, OtherPairsKeepBox2DsOwnAnswers) {
  ASSERT_TRUE(uninstall().ok());
  const ShapeGlide own = shape_glide(ShapeGround::TriangleGrid, ShapeBody::Box);
  const ShapeGlide own_ball = shape_glide(ShapeGround::BoxTiles, ShapeBody::Ball);
  Config c;
  c.triangles_only = true;
  ASSERT_TRUE(install(Backend::Dyop, c).ok());
  const ShapeGlide g = shape_glide(ShapeGround::TriangleGrid, ShapeBody::Box);
  const ShapeGlide ball = shape_glide(ShapeGround::BoxTiles, ShapeBody::Ball);
  const Stats s = stats();
  ASSERT_TRUE(uninstall().ok());
  EXPECT_EQ(g.max_vertical, own.max_vertical);
  EXPECT_EQ(g.travel, own.travel);
  EXPECT_EQ(ball.max_vertical, own_ball.max_vertical);
  EXPECT_EQ(ball.travel, own_ball.travel);
  EXPECT_EQ(s.exact_pairs, 0u);
  EXPECT_EQ(s.circle_pairs, 0u);  // Box2D's own circle contact, not the plug-in's
}

// `Backend::Box2D` answers every pair with Box2D's own functions: the reference, bit for bit.
TEST(EverydayShapesBox2DBackend, IsBox2DsOwnContactBitForBit) {
  for (ShapeBody b : {ShapeBody::Box, ShapeBody::Ball}) {
    ASSERT_TRUE(uninstall().ok());
    const ShapeGlide own = shape_glide(ShapeGround::BoxTiles, b);
    ASSERT_TRUE(install(Backend::Box2D).ok());
    const ShapeGlide g = shape_glide(ShapeGround::BoxTiles, b);
    const Stats s = stats();
    ASSERT_TRUE(uninstall().ok());
    EXPECT_EQ(g.max_vertical, own.max_vertical) << shape_name(b);
    EXPECT_EQ(g.travel, own.travel) << shape_name(b);
    EXPECT_EQ(s.exact_pairs, 0u);
  }
}

// The masks of a `SetAsBox` tile map's tiles, found as the contacts find them and fixed: the
// shared sides internal, the top corners closed.
TEST(EverydayShapesMasks, SetAsBoxTilesShareTheirSides) {
  World world;
  add_shape_ground(world, ShapeGround::BoxTiles, 0.0f, 2.0f);  // 4 tiles per row, 2 rows
  int checked = 0;
  for (b2Fixture* f = world.bodies().front()->GetFixtureList(); f; f = f->GetNext()) {
    const auto& box = *static_cast<const b2PolygonShape*>(f->GetShape());
    if (box.m_centroid.y < -0.3f || box.m_centroid.x < 0.3f || box.m_centroid.x > 1.7f) continue;
    // An inner tile of the top row: SetAsBox's edges 0 bottom, 1 right, 2 top, 3 left.
    const ShapeMasks m = polygon_internal_edges(*f);
    EXPECT_EQ(m.edges, 0b1011) << box.m_centroid.x;
    EXPECT_EQ(m.closed_vertices, 0b1111) << box.m_centroid.x;
    ++checked;
  }
  EXPECT_EQ(checked, 2);
  fix_internal_edges(*world.bodies().front());
  for (b2Fixture* f = world.bodies().front()->GetFixtureList(); f; f = f->GetNext()) {
    const std::optional<ShapeMasks> fixed = fixed_polygon_edges(*f);
    ASSERT_TRUE(fixed.has_value());
    EXPECT_EQ(*fixed, polygon_internal_edges(*f));
  }
}

}  // namespace
}  // namespace dyop::box2d::testing
