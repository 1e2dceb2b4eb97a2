// The grounds section's levels: a tile grid's cells traced into chain loops that enclose exactly
// its solid cells, and the same level built as chains, as edges and by the builders, side by side.
#include <box2d/box2d.h>
#include <gtest/gtest.h>

#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "experiments/ground_comparison.hpp"
#include "experiments/ground_measures.hpp"

namespace dyop::experiments {
namespace {

using Cells = std::vector<std::uint8_t>;

struct Grid {
  std::string name;
  int columns, rows;
  Cells cells;
};

// Hostile grids: a single cell, a checkerboard (cells meeting only by their corners), full and
// empty maps, a ring around a hole, and a random map.
std::vector<Grid> hostile_grids() {
  std::vector<Grid> grids;
  grids.push_back({"single cell", 1, 1, {1}});
  Cells checker(7 * 5);
  for (int r = 0; r < 5; ++r) {
    for (int c = 0; c < 7; ++c) checker[static_cast<std::size_t>(r * 7 + c)] = (r + c) % 2 == 0;
  }
  grids.push_back({"checkerboard", 7, 5, checker});
  grids.push_back({"full", 9, 4, Cells(36, 1)});
  grids.push_back({"empty", 6, 6, Cells(36, 0)});
  Cells ring(5 * 5, 1);
  ring[12] = 0;
  grids.push_back({"ring around a hole", 5, 5, ring});
  std::mt19937 rng(7);
  Cells random(40 * 20);
  for (auto& cell : random) cell = rng() % 10 < 4;
  grids.push_back({"random", 40, 20, random});
  return grids;
}

TEST(TileLoops, EncloseExactlyTheSolidCellsWithTheSolidOnTheLeft) {
  const float cell = 0.5f;
  const b2Vec2 origin(-3, 2);
  for (const Grid& g : hostile_grids()) {
    SCOPED_TRACE(g.name);
    const auto loops = tile_loops(g.cells, g.columns, g.rows, cell, origin);
    double area = 0;
    std::size_t solid = 0;
    for (const std::uint8_t c : g.cells) solid += c != 0;
    for (const auto& loop : loops) {
      ASSERT_GE(loop.size(), 4u) << "a loop of cells has at least four corners";
      area += signed_area(loop);
      for (std::size_t i = 0; i < loop.size(); ++i) {
        const b2Vec2 a = loop[i];
        const b2Vec2 b = loop[(i + 1) % loop.size()];
        const b2Vec2 c = loop[(i + 2) % loop.size()];
        EXPECT_GT(b2Distance(a, b), b2_linearSlop) << "consecutive corners apart, as a chain needs";
        EXPECT_TRUE(a.x == b.x || a.y == b.y) << "edges along the grid";
        EXPECT_NE(b2Cross(b - a, c - b), 0.0f) << "straight runs merged";
      }
      // Box2D takes it as a loop.
      b2ChainShape chain;
      chain.CreateLoop(loop.data(), static_cast<int>(loop.size()));
      EXPECT_EQ(chain.GetChildCount(), static_cast<int>(loop.size()));
    }
    // Counter-clockwise around solid, clockwise around holes: the areas add up to the solid's.
    EXPECT_NEAR(area, static_cast<double>(solid) * cell * cell, 1e-6);
    if (g.name == "checkerboard") {
      EXPECT_EQ(loops.size(), solid) << "cells meeting by a corner stay apart";
    }
    if (g.name == "ring around a hole") {
      ASSERT_EQ(loops.size(), 2u);
      EXPECT_LT(std::min(signed_area(loops[0]), signed_area(loops[1])), 0) << "the hole's loop";
    }
    if (g.name == "empty") {
      EXPECT_TRUE(loops.empty());
    }
  }
}

TEST(TileLoops, RefuseCellsThatAreNotColumnsTimesRowsLong) {
  EXPECT_THROW(tile_loops(Cells(5, 1), 2, 3, 1, b2Vec2(0, 0)), std::invalid_argument);
  EXPECT_THROW(tile_loops(Cells(), 0, 0, 1, b2Vec2(0, 0)), std::invalid_argument);
}

// The tile grid (256 × 64 cells) every way, a short crowd: under the plug-in every everyday
// body glides on the chain, on the two-sided edges and on the builders' ground; the builders'
// ground pushes boxes started under its top back out, where the chain, one-sided, lets them
// through (under either contact). Every way has the same boundary.
TEST(Grounds, UnderThePlugInEveryGroundGlidesAndTheBuildersPushOutWhatTheChainLetsThrough) {
  const GroundTiming timing{20, 5, 1};
  const auto runs = compare_ground(GroundLevel::TileGrid, timing, box2d::Config{});
  ASSERT_EQ(runs.size(), ground_ways.size());
  for (std::size_t w = 0; w < runs.size(); ++w) {
    EXPECT_EQ(runs[w].way.build, ground_ways[w].build);
    EXPECT_EQ(runs[w].way.plugin, ground_ways[w].plugin);
    EXPECT_DOUBLE_EQ(runs[w].boundary, runs[0].boundary);
    EXPECT_GT(runs[w].fixtures, 0);
    ASSERT_EQ(runs[w].glides.size(), 4u);
    if (!runs[w].way.plugin) continue;
    for (const GroundGlide& g : runs[w].glides) {
      EXPECT_LE(g.max_vertical_speed, 0.01) << name(runs[w].way) << ": " << g.body;
      EXPECT_GE(g.travel, 0.99) << name(runs[w].way) << ": " << g.body;
    }
  }
  const GroundRun& chain = runs[0];
  const GroundRun& builders = runs[4];
  ASSERT_EQ(builders.way.build, GroundBuild::Builder);
  ASSERT_EQ(chain.placements.size(), builders.placements.size());
  for (std::size_t k = 0; k < builders.placements.size(); ++k) {
    const GroundPlacement& p = builders.placements[k];
    EXPECT_EQ(p.on_top, p.boxes) << p.trial;
    if (p.trial.find("0.4 m inside") != std::string::npos) {
      EXPECT_EQ(chain.placements[k].on_top, 0) << "a one-sided chain lets them through";
      EXPECT_EQ(runs[1].placements[k].on_top, 0) << "under the plug-in too";
    }
  }
}

// The flat level recorded both ways for the viewer: each ground's fixtures on its own side (the
// chain as one segment per edge, the builders' triangles), the moving bodies shared; every contact
// names fixtures of its own runner's world; the boxes started 0.4 m inside end under the chain
// and on top of the builders' ground.
TEST(Grounds, TheRecordingDrawsEachGroundOnItsSideAndSharesTheMovingBodies) {
  const LockstepRecording r = record_ground(GroundLevel::Flat, {std::nullopt, box2d::Backend::Dyop},
                                            120, {box2d::Config::all(), box2d::Config::all()});
  EXPECT_EQ(r.scene, "grounds-flat");
  ASSERT_EQ(r.bodies.size(), 2u + 4u + 10u);  // two grounds, the gliders, the boxes
  int own[2] = {0, 0};
  int shared = 0;
  for (const ViewFixture& f : r.fixtures) {
    if (f.side < 0) {
      ++shared;
      EXPECT_GE(f.body, 2);
      continue;
    }
    ++own[f.side];
    EXPECT_EQ(f.body, f.side);
    EXPECT_EQ(f.kind,
              f.side == 0 ? scenes::DrawShape::Kind::Segment : scenes::DrawShape::Kind::Polygon);
  }
  EXPECT_GT(own[0], 100);  // a vertex every 0.25 m along 140 m of boundary
  EXPECT_GT(own[1], 100);
  EXPECT_EQ(shared, 3 + 2 + 10);  // box, hexagon, ball; the box of two triangles; the boxes
  for (int k = 0; k < 2; ++k) {
    ASSERT_EQ(r.frames[k].size(), 120u);
    for (const ViewFrame& frame : r.frames[k]) {
      ASSERT_EQ(frame.poses.size(), r.bodies.size());
      for (const ViewContact& c : frame.contacts) {
        for (const int f : {c.fixture_a, c.fixture_b}) {
          const int side = r.fixtures[static_cast<std::size_t>(f)].side;
          EXPECT_TRUE(side < 0 || side == k) << "runner " << k << ", fixture " << f;
        }
      }
    }
    for (std::size_t b = r.bodies.size() - 10; b < r.bodies.size(); ++b) {
      const float y = r.frames[k].back().poses[b].y;
      if (k == 0) {
        EXPECT_LT(y, 0) << "the chain holds a box started inside it";
      } else {
        EXPECT_GT(y, 0) << "the builders' ground leaves a box inside it";
      }
    }
  }
}

}  // namespace
}  // namespace dyop::experiments
