// `TileGround`: a tile map's solid cells merged into rectangles that cover exactly the solid
// cells, every fixture valid for Box2D with its edge data fixed as the rule finds it, refusals
// that create nothing, a dig that rebuilds one chunk, and bodies gliding over the merged ground.
#include <gtest/gtest.h>

#include <box2d/box2d.h>

#include <cmath>
#include <vector>

#include "dyop/box2d.hpp"
#include "dyop/box2d_grid.hpp"
#include "dyop/box2d_internal_edges.hpp"
#include "support/worlds.hpp"

namespace dyop::box2d::testing {
namespace {

// How many fixtures cover the centre of cell (column, row) of `ground`.
int covering(const TileGround& ground, int column, int row) {
  const GridLayout& g = ground.layout();
  const b2Vec2 centre(g.origin.x + g.cell * (static_cast<float>(column) + 0.5f),
                      g.origin.y + g.cell * (static_cast<float>(row) + 0.5f));
  int n = 0;
  for (const b2Fixture* f : ground.fixtures())
    n += f->TestPoint(f->GetBody()->GetWorldPoint(centre));
  return n;
}

// Every solid cell covered once, every empty cell not at all; every fixture a rectangle with
// fixed edge data equal to what the rule finds.
void expect_exact_cover(const TileGround& ground) {
  const GridLayout& g = ground.layout();
  for (int r = 0; r < g.rows; ++r) {
    for (int c = 0; c < g.columns; ++c) {
      EXPECT_EQ(covering(ground, c, r), ground.solid(c, r) ? 1 : 0) << c << ", " << r;
    }
  }
  for (const b2Fixture* f : ground.fixtures()) {
    ASSERT_EQ(f->GetType(), b2Shape::e_polygon);
    EXPECT_EQ(static_cast<const b2PolygonShape*>(f->GetShape())->m_count, 4);
    const std::optional<ShapeMasks> fixed = fixed_polygon_edges(*f);
    ASSERT_TRUE(fixed.has_value());
    EXPECT_EQ(*fixed, polygon_internal_edges(*f));
  }
}

std::vector<std::uint8_t> pattern(int columns, int rows, bool (*solid)(int, int)) {
  std::vector<std::uint8_t> cells(static_cast<std::size_t>(columns * rows));
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < columns; ++c)
      cells[static_cast<std::size_t>(r * columns + c)] = solid(c, r);
  }
  return cells;
}

TEST(TileGround, FullEmptySingleAndCheckerboardMapsAreCoveredExactly) {
  struct Map {
    int columns, rows;
    bool (*solid)(int, int);
  };
  const Map maps[] = {
      {20, 6, [](int, int) { return true; }},
      {20, 6, [](int, int) { return false; }},
      {1, 1, [](int, int) { return true; }},
      {9, 7, [](int c, int r) { return (c + r) % 2 == 0; }},                      // corners only
      {40, 10, [](int c, int r) { return r < 3 || (r < 6 && c % 7 < 3); }},       // steps
      {33, 17, [](int c, int r) { return (c * 7 + r * 3) % 5 != 0 || r == 0; }},  // holes
  };
  for (const Map& m : maps) {
    World world;
    b2Body* body = add_body(world, b2_staticBody, b2Vec2(3.0f, -2.0f), 0.3f);
    TileGround ground(*body, {m.columns, m.rows, 0.5f, b2Vec2(-1, 0), 8});
    ASSERT_EQ(ground.set_cells(pattern(m.columns, m.rows, m.solid)), GridError::None);
    expect_exact_cover(ground);
    int solid = 0;
    for (int r = 0; r < m.rows; ++r) {
      for (int c = 0; c < m.columns; ++c) solid += ground.solid(c, r);
    }
    // Merged: never more rectangles than solid cells, far fewer on a full map.
    EXPECT_LE(static_cast<int>(ground.fixtures().size()), solid);
    if (solid == m.columns * m.rows && solid > 1) {
      EXPECT_LE(ground.fixtures().size(), 9u);  // at most one per 8 × 8 chunk
    }
  }
}

TEST(TileGround, RefusedCallsCreateNothingAndSayWhy) {
  World world;
  b2Body* body = add_body(world, b2_staticBody, b2Vec2(0, 0));
  const std::vector<std::uint8_t> four(4, 1);
  EXPECT_EQ(TileGround(*body, {2, 2, 0.0f}).set_cells(four), GridError::CellSize);
  EXPECT_EQ(TileGround(*body, {2, 2, NAN}).set_cells(four), GridError::CellSize);
  EXPECT_EQ(TileGround(*body, {0, 2, 1.0f}).set_cells(four), GridError::Size);
  EXPECT_EQ(TileGround(*body, {2, 2, 1.0f, b2Vec2(0, 0), 0}).set_cells(four), GridError::Size);
  EXPECT_EQ(TileGround(*body, {3, 2, 1.0f}).set_cells(four), GridError::Size);
  EXPECT_EQ(TileGround(*body, {2, 2, 1e9f}).set_cells(four), GridError::TooLarge);
  TileGround ground(*body, {2, 2, 1.0f});
  EXPECT_EQ(ground.set_cell(0, 0, false), GridError::Size);  // no cells yet
  ASSERT_EQ(ground.set_cells(four), GridError::None);
  EXPECT_EQ(ground.set_cell(2, 0, false), GridError::OutOfRange);
  EXPECT_EQ(ground.set_cell(0, -1, false), GridError::OutOfRange);
  EXPECT_EQ(body->GetFixtureList()->GetNext(), nullptr);  // the one merged rectangle, no more
  EXPECT_STRNE(describe(GridError::TooLarge), describe(GridError::None));
}

TEST(TileGround, DiggingAndBuildingRebuildOneChunkAndKeepTheCoverExact) {
  World world;
  b2Body* body = add_body(world, b2_staticBody, b2Vec2(0, 0));
  TileGround ground(*body, {24, 8, 0.5f, b2Vec2(0, 0), 8});
  ASSERT_EQ(ground.set_cells(std::vector<std::uint8_t>(24 * 8, 1)), GridError::None);
  const std::vector<b2Fixture*> before = ground.fixtures();
  ASSERT_EQ(before.size(), 3u);
  ASSERT_EQ(ground.set_cell(11, 7, false), GridError::None);  // a dig in the middle chunk
  expect_exact_cover(ground);
  const std::vector<b2Fixture*> after = ground.fixtures();
  EXPECT_EQ(after.front(), before.front());  // the other chunks keep their fixtures
  EXPECT_EQ(after.back(), before.back());
  // The neighbour chunks' rectangles next to the dug cell: their shared edges with the middle
  // chunk stay internal where the middle chunk is still solid.
  ASSERT_EQ(ground.set_cell(11, 7, true), GridError::None);
  expect_exact_cover(ground);
  EXPECT_EQ(ground.fixtures().size(), 3u);
  // A whole chunk dug out: its neighbours' edges along it become outline.
  for (int r = 0; r < 8; ++r) {
    for (int c = 8; c < 16; ++c) ASSERT_EQ(ground.set_cell(c, r, false), GridError::None);
  }
  expect_exact_cover(ground);
}

// A box and a ball pushed at 4 m/s over a merged map whose top has steps down and T-junctions
// between rectangles of different heights: they glide where the map is flat.
TEST(TileGround, BodiesGlideOverTheMergedMap) {
  ASSERT_TRUE(install(Backend::Dyop).ok());
  for (const bool ball : {false, true}) {
    World world;
    b2Body* body = add_body(world, b2_staticBody, b2Vec2(0, 0));
    // 80 × 6 cells of 0.25 m, the top at y = 0; holes below the top row make rectangles of
    // several heights meet along it.
    TileGround ground(*body, {80, 6, 0.25f, b2Vec2(-2.0f, -1.5f), 8});
    ASSERT_EQ(ground.set_cells(
                  pattern(80, 6, [](int c, int r) { return r == 5 || (c * 3 + r) % 4 != 0; })),
              GridError::None);
    b2Body* glider = add_body(world, b2_dynamicBody, b2Vec2(0, 0.3f));
    b2FixtureDef def;
    def.friction = 0;
    def.density = 1;
    b2PolygonShape box;
    box.SetAsBox(0.25f, 0.3f);
    b2CircleShape circle;
    circle.m_radius = 0.3f;
    def.shape = ball ? static_cast<const b2Shape*>(&circle) : &box;
    glider->CreateFixture(&def);
    glider->SetLinearVelocity(b2Vec2(4.0f, 0));
    float max_vertical = 0;
    for (int i = 0; i < 180; ++i) {
      world.step();
      if (i > 0) max_vertical = std::max(max_vertical, std::abs(glider->GetLinearVelocity().y));
    }
    EXPECT_LE(max_vertical, 0.05f) << (ball ? "ball" : "box");
    EXPECT_GE(glider->GetPosition().x, 0.98f * 4.0f * 3.0f) << (ball ? "ball" : "box");
  }
  ASSERT_TRUE(uninstall().ok());
}

}  // namespace
}  // namespace dyop::box2d::testing
