// Stacks and pyramids of two-triangle boxes stand on tiled grounds as on one piece, with the
// internal-edge rule (the exact backends): grounds of 0.5 m tiles in one static body, in one static
// body per tile and in 8 × 8 chunks per body. Edges shared across static bodies are internal, so
// the boxes' corners over tile junctions are pushed up, as over the junctions of one body.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include "dyop/box2d.hpp"
#include "support/worlds.hpp"

namespace dyop::box2d::testing {
namespace {

constexpr float kTile = 0.5f;
constexpr int kColumns = 32;  // 16 m of ground from x = -8
// m: a structure stands when its top body moves no more than this over the run (one that falls
// moves by metres; a stack of eight 1 m boxes sways by 3 cm on one piece), and no more than this
// beyond its motion on one piece.
constexpr float kStands = 0.05f;
constexpr float kAsOnOnePiece = 0.005f;

enum class Ground { OnePiece, Tiles, Chunks };

const char* name(Ground g) {
  return g == Ground::OnePiece ? "one body" : g == Ground::Tiles ? "a body per tile" : "8x8 chunks";
}

// A ground whose top is y = 0, 8 tiles deep, each tile split along its diagonal.
void add_ground(World& world, Ground g) {
  b2Body* one = g == Ground::OnePiece ? add_body(world, b2_staticBody, b2Vec2(0, 0)) : nullptr;
  b2Body* chunk = nullptr;
  for (int i = 0; i < kColumns; ++i) {
    for (int row = 0; row < 8; ++row) {
      const b2Vec2 bl(-8.0f + i * kTile, -(row + 1) * kTile);
      b2Body* body = one;
      if (g == Ground::Tiles) body = add_body(world, b2_staticBody, bl);
      if (g == Ground::Chunks) {
        if (i % 8 == 0 && row == 0) chunk = add_body(world, b2_staticBody, bl);
        body = chunk;
      }
      const b2Transform& xf = body->GetTransform();
      const b2Vec2 br(bl.x + kTile, bl.y), tr(bl.x + kTile, bl.y + kTile), tl(bl.x, bl.y + kTile);
      add_triangle(body, b2MulT(xf, tl), b2MulT(xf, bl), b2MulT(xf, tr));
      add_triangle(body, b2MulT(xf, tr), b2MulT(xf, bl), b2MulT(xf, br));
    }
  }
}

// The largest displacement of the top body over 10 s: a pyramid of `base` rows (base > 1) or a
// stack of `-base` boxes, placed a quarter tile off the junctions.
float top_motion(Ground g, int base) {
  World world;
  add_ground(world, g);
  const float pitch = 2 * kBoxHalf + b2_polygonRadius;
  const int rows = base > 0 ? base : -base;
  b2Body* top = nullptr;
  for (int row = 0; row < rows; ++row) {
    const int count = base > 0 ? base - row : 1;
    for (int i = 0; i < count; ++i) {
      const float x = 0.125f + (i - 0.5f * (count - 1)) * pitch;
      top = add_split_box(world, b2Vec2(x, kBoxHalf + b2_polygonRadius + row * pitch), kBoxHalf);
    }
  }
  for (int i = 0; i < 60; ++i) world.step();  // settle, as the scenes do
  const b2Vec2 start = top->GetPosition();
  float moved = 0;
  for (int i = 0; i < 10 * kStepsPerSecond; ++i) {
    world.step();
    moved = std::max(moved, (top->GetPosition() - start).Length());
  }
  return moved;
}

class ExactBackendOnTiledGround : public ::testing::TestWithParam<Backend> {};

TEST_P(ExactBackendOnTiledGround, StacksAndPyramidsStandOnTiledGroundsAsOnOnePiece) {
  ASSERT_TRUE(install(GetParam()).ok());
  for (const int base : {6, -8}) {
    const float one_piece = top_motion(Ground::OnePiece, base);
    for (const Ground g : {Ground::Tiles, Ground::Chunks}) {
      SCOPED_TRACE(std::string(base > 0 ? "pyramid" : "stack") + " on " + name(g));
      const float tiled = top_motion(g, base);
      std::printf("%s %s on %s: top moved %.5f m (one piece %.5f m)\n", name(GetParam()),
                  base > 0 ? "pyramid" : "stack", name(g), tiled, one_piece);
      EXPECT_LE(tiled, kStands);
      EXPECT_LE(tiled, one_piece + kAsOnOnePiece);
    }
  }
  EXPECT_EQ(stats().fallbacks, 0u);
  ASSERT_TRUE(uninstall().ok());
}

INSTANTIATE_TEST_SUITE_P(TiledGrounds, ExactBackendOnTiledGround,
                         ::testing::Values(Backend::Dyop, Backend::Sat),
                         [](const ::testing::TestParamInfo<Backend>& i) {
                           return std::string(name(i.param));
                         });

}  // namespace
}  // namespace dyop::box2d::testing
