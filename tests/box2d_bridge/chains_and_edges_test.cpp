// Grounds made the way Box2D tells users to make them — a one-sided `b2ChainShape` (open, or a
// loop around a solid block) and two-sided `b2EdgeShape`s laid end to end — with the plug-in
// installed by its defaults: every body of a game glides over them (no ghost collision at the
// vertices), on either side of a two-sided strip, and a body behind a one-sided chain passes
// through it as under Box2D's own contact.
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

constexpr float kLevelGlideSeconds = 4.0f;
constexpr float kVertexSpacing = 0.25f;  // m between the ground's vertices

enum class LevelGround { Chain, Loop, TwoSidedEdges, EdgeBodies };

const char* name(LevelGround g) {
  switch (g) {
    case LevelGround::Chain:
      return "one-sided chain (CreateChain)";
    case LevelGround::Loop:
      return "chain loop (CreateLoop)";
    case LevelGround::TwoSidedEdges:
      return "two-sided edges end to end";
    case LevelGround::EdgeBodies:
      return "two-sided edges end to end, a static body each";
  }
  return "";
}

// A static ground whose surface is y = 0 over [x0, x0 + length], a vertex every
// `kVertexSpacing`, facing up (`up`) or down (its underside, for bodies under gravity reversed).
// Chains run so that their front (the right of the direction of travel) faces the body; the
// two-sided edges run left to right, so that a body above lies on their back.
void add_level_ground(World& world, LevelGround kind, float x0, float length, bool up = true) {
  b2Body* ground = add_body(world, b2_staticBody, b2Vec2(0, 0));
  const int n = static_cast<int>(std::lround(length / kVertexSpacing));
  std::vector<b2Vec2> top;
  for (int i = 0; i <= n; ++i) top.emplace_back(x0 + i * kVertexSpacing, 0.0f);
  if (up) std::reverse(top.begin(), top.end());  // right to left: the front up
  b2FixtureDef def;
  def.friction = 0;
  switch (kind) {
    case LevelGround::Chain: {
      b2ChainShape chain;
      const b2Vec2 step = top[1] - top[0];
      chain.CreateChain(top.data(), static_cast<int>(top.size()), top.front() - step,
                        top.back() + step);
      def.shape = &chain;
      ground->CreateFixture(&def);
      return;
    }
    case LevelGround::Loop: {
      // The surface, then around a block 1 m deep back to it: counter-clockwise seen from the
      // body's side.
      std::vector<b2Vec2> loop = top;
      const float depth = up ? -1.0f : 1.0f;
      loop.emplace_back(top.back().x, depth);
      loop.emplace_back(top.front().x, depth);
      b2ChainShape chain;
      chain.CreateLoop(loop.data(), static_cast<int>(loop.size()));
      def.shape = &chain;
      ground->CreateFixture(&def);
      return;
    }
    case LevelGround::TwoSidedEdges:
    case LevelGround::EdgeBodies:
      std::sort(top.begin(), top.end(), [](const b2Vec2& p, const b2Vec2& q) { return p.x < q.x; });
      for (std::size_t i = 0; i + 1 < top.size(); ++i) {
        // A body of its own at the edge's start, the edge in its frame.
        b2Body* owner =
            kind == LevelGround::EdgeBodies ? add_body(world, b2_staticBody, top[i]) : ground;
        b2EdgeShape edge;
        edge.SetTwoSided(top[i] - owner->GetPosition(), top[i + 1] - owner->GetPosition());
        def.shape = &edge;
        owner->CreateFixture(&def);
      }
      return;
  }
}

struct LevelGlide {
  float max_vertical = 0;  // largest |vy| once settled, m/s, over every launch
  float travel = 1;        // least share of the free travel speed · time, over every launch
};

// Where a glider starts (metres): its offset along the ground from a vertex, and the height of its
// lowest point above the ground's line: inside the two skins (0.02 m), where Box2D's position
// solver lifts it out over its first steps. Box2D's own contact trips on a chain from some of them
// and not from others (its smoothing admits the slight tilt the lift leaves).
constexpr float kLaunchOffsets[][2] = {{0.0f, 0.0f},   {0.07f, 0.0f},   {0.13f, 0.0f},
                                       {0.0f, 0.005f}, {0.13f, 0.005f}, {0.3f, 0.005f}};
// Steps after which a launched body has settled on the ground (0.25 s): its vertical speed counts
// from then on.
constexpr int kSettleSteps = 15;

// The glide of `body` on `ground` from every launch point.
LevelGlide level_glide(LevelGround ground, LevelBody body, bool up = true) {
  LevelGlide g;
  for (const auto& [x0, height] : kLaunchOffsets) {
    World world(b2Vec2(0, up ? -10.0f : 10.0f));
    add_level_ground(world, ground, -2.0f, kLevelPushSpeed * kLevelGlideSeconds + 4.0f, up);
    b2Body* glider = add_level_glider(world, body, up);
    glider->SetTransform(b2Vec2(x0, up ? height : -height), 0);
    const int steps = static_cast<int>(kLevelGlideSeconds * kStepsPerSecond);
    for (int step = 0; step < steps; ++step) {
      world.step();
      if (step >= kSettleSteps) {
        g.max_vertical = std::max(g.max_vertical, std::abs(glider->GetLinearVelocity().y));
      }
    }
    g.travel =
        std::min(g.travel, (glider->GetPosition().x - x0) / (kLevelPushSpeed * kLevelGlideSeconds));
  }
  return g;
}

struct LevelCase {
  LevelGround ground;
  LevelBody body;
};

class ChainsAndEdges : public ::testing::TestWithParam<LevelCase> {};

TEST_P(ChainsAndEdges, EveryBodyGlidesWithThePlugInInstalledByItsDefaults) {
  const LevelCase c = GetParam();
  ASSERT_TRUE(uninstall().ok());
  const LevelGlide own = level_glide(c.ground, c.body);
  ASSERT_TRUE(install(Backend::Dyop).ok());
  const LevelGlide g = level_glide(c.ground, c.body);
  const Stats s = stats();
  ASSERT_TRUE(uninstall().ok());
  std::printf("%s on %s: plug-in %.4f m/s, %.2f %% of the glide; Box2D's own %.4f m/s, %.2f %%\n",
              name(c.body), name(c.ground), g.max_vertical, 100 * g.travel, own.max_vertical,
              100 * own.travel);
  EXPECT_LE(g.max_vertical, kLevelGlideVertical);
  EXPECT_GE(g.travel, kLevelGlideTravel);
  EXPECT_GT(s.edge_pairs, 0u);
  EXPECT_GT(s.exact_pairs, 0u);
}

// Gravity reversed, the body hanging under the strip: a two-sided edge's contact keeps the side
// its body began on, so the underside is as smooth as the top.
class TwoSidedStripUnderside : public ::testing::TestWithParam<LevelBody> {};

TEST_P(TwoSidedStripUnderside, GlidesAsItsTop) {
  const LevelBody body = GetParam();
  ASSERT_TRUE(install(Backend::Dyop).ok());
  const LevelGlide g = level_glide(LevelGround::TwoSidedEdges, body, false);
  ASSERT_TRUE(uninstall().ok());
  std::printf("%s under %s: %.4f m/s, %.2f %% of the glide\n", name(body),
              name(LevelGround::TwoSidedEdges), g.max_vertical, 100 * g.travel);
  EXPECT_LE(g.max_vertical, kLevelGlideVertical);
  EXPECT_GE(g.travel, kLevelGlideTravel);
}

std::string level_body_name(const ::testing::TestParamInfo<LevelBody>& info) {
  static const char* bodies[] = {"TriangleBox", "Box", "Hexagon", "Ball"};
  return bodies[static_cast<int>(info.param)];
}

INSTANTIATE_TEST_SUITE_P(EveryBody, TwoSidedStripUnderside,
                         ::testing::Values(LevelBody::TriangleBox, LevelBody::Box,
                                           LevelBody::Hexagon, LevelBody::Ball),
                         level_body_name);

std::vector<LevelCase> all_level_cases() {
  std::vector<LevelCase> out;
  for (LevelGround g : {LevelGround::Chain, LevelGround::Loop, LevelGround::TwoSidedEdges,
                        LevelGround::EdgeBodies}) {
    for (LevelBody b :
         {LevelBody::TriangleBox, LevelBody::Box, LevelBody::Hexagon, LevelBody::Ball})
      out.push_back({g, b});
  }
  return out;
}

std::string level_case_name(const ::testing::TestParamInfo<LevelCase>& info) {
  static const char* grounds[] = {"Chain", "Loop", "TwoSidedEdges", "EdgeBodies"};
  static const char* bodies[] = {"TriangleBox", "Box", "Hexagon", "Ball"};
  return std::string(grounds[static_cast<int>(info.param.ground)]) + "_" +
         bodies[static_cast<int>(info.param.body)];
}

INSTANTIATE_TEST_SUITE_P(GroundsAndBodies, ChainsAndEdges, ::testing::ValuesIn(all_level_cases()),
                         level_case_name);

// A body thrown up through a one-sided chain from below passes it (its centroid behind the chain:
// no contact), under the plug-in as under Box2D's own contact; a body above it lands on it.
TEST(OneSidedChains, ABodyBehindPassesThroughAndABodyInFrontLands) {
  for (const bool plugged : {false, true}) {
    if (plugged) {
      ASSERT_TRUE(install(Backend::Dyop).ok());
    } else {
      ASSERT_TRUE(uninstall().ok());
    }
    for (LevelBody kind : {LevelBody::TriangleBox, LevelBody::Box, LevelBody::Ball}) {
      World world;
      add_level_ground(world, LevelGround::Chain, -4.0f, 8.0f);
      b2Body* below = add_level_glider(world, kind);
      below->SetTransform(b2Vec2(0, -1.0f), 0);
      below->SetLinearVelocity(b2Vec2(0, 8.0f));
      b2Body* above = add_level_glider(world, kind);
      above->SetTransform(b2Vec2(2.0f, 0.5f), 0);
      above->SetLinearVelocity(b2Vec2(0, 0));
      float highest = -10;
      for (int i = 0; i < 2 * kStepsPerSecond; ++i) {
        world.step();
        highest = std::max(highest, below->GetPosition().y);
      }
      EXPECT_GT(highest, 1.0f) << name(kind) << (plugged ? ", plug-in" : ", Box2D's own");
      EXPECT_NEAR(above->GetPosition().y, 0.0f, 0.02f)
          << name(kind) << (plugged ? ", plug-in" : ", Box2D's own") << ": landed at "
          << above->GetPosition().y;
    }
  }
  EXPECT_TRUE(uninstall().ok());
}

// `Config::edges_and_chains` off, `Config::triangles_only` and `Backend::Box2D` leave edges and
// chains to Box2D: bit for bit its own answers.
TEST(ChainsAndEdgesLeftToBox2D, ConfigAndBackendKeepBox2DsOwnAnswersBitForBit) {
  ASSERT_TRUE(uninstall().ok());
  const LevelGlide own = level_glide(LevelGround::Chain, LevelBody::Box);
  const LevelGlide own_edges = level_glide(LevelGround::TwoSidedEdges, LevelBody::Ball);
  Config off;
  off.edges_and_chains = false;
  Config triangles;
  triangles.triangles_only = true;
  for (const auto& [backend, config] :
       {std::pair{Backend::Dyop, off}, std::pair{Backend::Dyop, triangles},
        std::pair{Backend::Box2D, Config::all()}}) {
    ASSERT_TRUE(install(backend, config).ok());
    const LevelGlide g = level_glide(LevelGround::Chain, LevelBody::Box);
    const LevelGlide e = level_glide(LevelGround::TwoSidedEdges, LevelBody::Ball);
    const Stats s = stats();
    ASSERT_TRUE(uninstall().ok());
    EXPECT_EQ(g.max_vertical, own.max_vertical) << name(backend);
    EXPECT_EQ(g.travel, own.travel) << name(backend);
    EXPECT_EQ(e.max_vertical, own_edges.max_vertical) << name(backend);
    EXPECT_EQ(e.travel, own_edges.travel) << name(backend);
    EXPECT_EQ(s.exact_pairs, 0u) << name(backend);
  }
}

// The masks of a strip of two-sided edges, and of a V: a middle edge has its other side internal
// and both ends closed (the strip goes on flat); an end edge only its inner end; a lone edge
// none; the V's joint is closed seen from above (a valley), open from below (a peak).
TEST(TwoSidedEdgeData, MasksAreTheBodysSideAndTheEndsTheOutlineClosesThere) {
  World world;
  b2Body* ground = add_body(world, b2_staticBody, b2Vec2(0, 0));
  const auto edge = [&](b2Vec2 p, b2Vec2 q) {
    b2EdgeShape e;
    e.SetTwoSided(p, q);
    return ground->CreateFixture(&e, 0);
  };
  std::vector<b2Fixture*> strip;
  for (int i = 0; i < 4; ++i) strip.push_back(edge(b2Vec2(i, 0), b2Vec2(i + 1, 0)));
  const b2Fixture* lone = edge(b2Vec2(10, 0), b2Vec2(11, 0));
  const b2Fixture* down = edge(b2Vec2(20, 1), b2Vec2(21, 0));  // its front faces down-left
  const b2Fixture* up = edge(b2Vec2(21, 0), b2Vec2(22, 1));
  const ShapeMasks front_middle{0b10, 0b11};
  const ShapeMasks back_middle{0b01, 0b11};
  EXPECT_EQ(edge_internal_edges(*strip[1]), front_middle);
  EXPECT_EQ(edge_internal_edges(*strip[1], 0, true), back_middle);
  EXPECT_EQ(edge_internal_edges(*strip[0]), (ShapeMasks{0b10, 0b10}));
  EXPECT_EQ(edge_internal_edges(*strip[3], 0, true), (ShapeMasks{0b01, 0b01}));
  EXPECT_EQ(edge_internal_edges(*lone), ShapeMasks{});
  EXPECT_EQ(edge_internal_edges(*lone, 0, true), ShapeMasks{});
  EXPECT_EQ(edge_internal_edges(*down, 0, true), (ShapeMasks{0b01, 0b10}));  // above: a valley
  EXPECT_EQ(edge_internal_edges(*down), (ShapeMasks{0b10, 0b00}));           // below: a peak
  EXPECT_EQ(edge_internal_edges(*up, 0, true), (ShapeMasks{0b01, 0b01}));
  EXPECT_EQ(edge_internal_edges(*up), (ShapeMasks{0b10, 0b00}));
}

// fix_internal_edges fixes every two-sided edge's ends as they are found, within a body and
// across static bodies alike; a fixture never fixed has none.
TEST(TwoSidedEdgeData, FixedEdgeDataIsWhatIsFoundAcrossStaticBodiesToo) {
  for (const LevelGround kind : {LevelGround::TwoSidedEdges, LevelGround::EdgeBodies}) {
    World world;
    add_level_ground(world, kind, -2.0f, 3.0f);
    std::vector<const b2Fixture*> edges;
    std::vector<ShapeMasks> found;
    for (b2Body* b = world->GetBodyList(); b; b = b->GetNext()) {
      for (const b2Fixture* f = b->GetFixtureList(); f; f = f->GetNext()) {
        EXPECT_FALSE(fixed_edge_internal_edges(*f).has_value());
        edges.push_back(f);
        found.push_back(edge_internal_edges(*f, 0, true));
      }
    }
    ASSERT_EQ(edges.size(), 12u) << name(kind);
    fix_internal_edges(world.get());
    int middle = 0;
    for (std::size_t i = 0; i < edges.size(); ++i) {
      const std::optional<ShapeMasks> fixed = fixed_edge_internal_edges(*edges[i], true);
      ASSERT_TRUE(fixed.has_value()) << name(kind);
      EXPECT_EQ(*fixed, found[i]) << name(kind) << ", edge " << i;
      middle += found[i] == ShapeMasks{0b01, 0b11};
    }
    EXPECT_EQ(middle, 10) << name(kind);
  }
}

// A two-sided edge continuing a triangulated ground's top flat: closed from above at the ground's
// vertex, where the outline goes on along the ground's top; from below, the ground's face going
// down bounds a quarter-turn of free space there: closed too.
TEST(TwoSidedEdgeData, AnEdgeEndingOnATriangulatedGroundsVertexTakesItsOutline) {
  World world;
  b2Body* ground = add_body(world, b2_staticBody, b2Vec2(0, 0));
  const b2Vec2 v[] = {{0, 0}, {1, 0}, {1, -1}, {0, -1}};
  const int indices[] = {0, 3, 1, 1, 3, 2};
  ASSERT_TRUE(add_triangles(*ground, v, 4, indices, 6).ok());
  b2Body* bridge = add_body(world, b2_staticBody, b2Vec2(1, 0));
  b2EdgeShape e;
  e.SetTwoSided(b2Vec2(0, 0), b2Vec2(1, 0));  // from the ground's corner (1, 0) to (2, 0)
  const b2Fixture* strip = bridge->CreateFixture(&e, 0);
  EXPECT_EQ(edge_internal_edges(*strip, 0, true), (ShapeMasks{0b01, 0b01}));
  EXPECT_EQ(edge_internal_edges(*strip), (ShapeMasks{0b10, 0b01}));
}

// A triangulated tile ground whose top is y = 0 over [0, `length`], 0.5 m deep in 0.25 m cells
// (`add_triangles`: its edge data fixed).
b2Body* add_tile_ground(World& world, float length) {
  b2Body* ground = add_body(world, b2_staticBody, b2Vec2(0, 0));
  constexpr float cell = 0.25f;
  const int columns = static_cast<int>(std::lround(length / cell));
  std::vector<b2Vec2> vertices;
  std::vector<int> indices;
  for (int row = 0; row <= 2; ++row) {
    for (int i = 0; i <= columns; ++i) vertices.emplace_back(i * cell, -row * cell);
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
  EXPECT_TRUE(r.ok()) << r.message;
  return ground;
}

// Two-sided edges from `from` to `to` (a vertex every 0.25 m), on a static body of their own.
void add_edge_strip(World& world, const b2Vec2& from, const b2Vec2& to) {
  b2Body* strip = add_body(world, b2_staticBody, b2Vec2(0, 0));
  const int n = static_cast<int>(std::lround((to - from).Length() / kVertexSpacing));
  for (int i = 0; i < n; ++i) {
    b2EdgeShape e;
    e.SetTwoSided(from + (float(i) / n) * (to - from), from + (float(i + 1) / n) * (to - from));
    strip->CreateFixture(&e, 0);
  }
}

// A strip of two-sided edges going on flat from a tile map's corner: the tile's side below the
// strip is hidden from bodies above it (the tile's junction), so every body glides across the
// corner both ways, with the edge data fixed after the strip is added.
TEST(EdgeOntoTiles, AStripGoingOnFlatFromATileMapsCornerGlidesBothWays) {
  ASSERT_TRUE(install(Backend::Dyop).ok());
  for (const float direction : {1.0f, -1.0f}) {
    for (LevelBody kind :
         {LevelBody::TriangleBox, LevelBody::Box, LevelBody::Hexagon, LevelBody::Ball}) {
      float worst = 0;
      float least_travel = 1;
      for (const auto& [x0, height] : kLaunchOffsets) {
        World world;
        add_tile_ground(world, 8.0f);
        add_edge_strip(world, b2Vec2(8, 0), b2Vec2(16, 0));
        fix_internal_edges(world.get());
        b2Body* glider = add_level_glider(world, kind);
        const float start = (direction > 0 ? 5.0f : 11.0f) + x0;
        glider->SetTransform(b2Vec2(start, height), 0);
        glider->SetLinearVelocity(b2Vec2(direction * kLevelPushSpeed, 0));
        const int steps = kStepsPerSecond;  // 4 m: across the corner
        for (int step = 0; step < steps; ++step) {
          world.step();
          if (step >= kSettleSteps) {
            worst = std::max(worst, std::abs(glider->GetLinearVelocity().y));
          }
        }
        least_travel =
            std::min(least_travel, direction * (glider->GetPosition().x - start) / kLevelPushSpeed);
      }
      EXPECT_LE(worst, kLevelGlideVertical) << name(kind) << ", direction " << direction;
      EXPECT_GE(least_travel, kLevelGlideTravel) << name(kind) << ", direction " << direction;
    }
  }
  ASSERT_TRUE(uninstall().ok());
}

// A ramp of two-sided edges up onto a tile map (rising 1 in 8 to its corner): a body sliding up
// it keeps, over the tiles, the horizontal speed it had at the top (frictionless), from every
// launch point: no ghost collision with the tile's side under the ramp's end, which would stop it.
// The crest is convex: passing over it, a body resting in the skins is deflected up by the corner
// (a ball loses up to 5 % of its horizontal speed there, as under Box2D's own contact).
TEST(EdgeOntoTiles, ARampOntoATileMapIsClimbedWithoutAGhostCollision) {
  constexpr float kRise = 0.5f;
  constexpr float kRun = 4.0f;
  const float slope = std::atan2(kRise, kRun);
  const auto climb = [&](LevelBody kind, float offset) {
    World world;
    add_tile_ground(world, 8.0f);
    add_edge_strip(world, b2Vec2(-kRun, -kRise), b2Vec2(0, 0));
    fix_internal_edges(world.get());
    b2Body* glider = add_level_glider(world, kind);
    // On the ramp's foot, turned with it, sliding up it at 5 m/s.
    const float along = 0.5f + offset;
    const b2Vec2 foot(-kRun + along * std::cos(slope), -kRise + along * std::sin(slope));
    glider->SetTransform(foot, slope);
    glider->SetLinearVelocity(5.0f * b2Vec2(std::cos(slope), std::sin(slope)));
    // The speed at the top, from the energy at the start (frictionless, no rotation).
    const float top_speed = std::sqrt(25.0f - 2 * 10.0f * (0 - foot.y));
    float least_vx = 100;
    for (int step = 0; step < 2 * kStepsPerSecond; ++step) {
      world.step();
      if (glider->GetPosition().x > 1.0f)
        least_vx = std::min(least_vx, glider->GetLinearVelocity().x);
    }
    return least_vx / (top_speed * std::cos(slope));
  };
  ASSERT_TRUE(install(Backend::Dyop).ok());
  for (LevelBody kind :
       {LevelBody::TriangleBox, LevelBody::Box, LevelBody::Hexagon, LevelBody::Ball}) {
    for (const auto& launch : kLaunchOffsets) {
      const float kept = climb(kind, launch[0]);
      EXPECT_GE(kept, 0.9f) << name(kind) << " from " << launch[0];
    }
  }
  ASSERT_TRUE(uninstall().ok());
}

// A ball driven up a chain's slope over its convex top, as Box2D 2.4.1's testbed drives its
// character (its horizontal speed set every step): past the top it leaves the slope as under
// Box2D's own contact. The flat edge after the top owns no contact while the ball's centre is in
// the slope's face region (Box2D's own rule for a one-sided edge and a circle); its vertex used to
// kick the ball up along a direction outside the outline's normals there.
TEST(OneSidedChains, ABallOverAConvexTopLeavesTheSlopeAsUnderBox2DsOwnContact) {
  const auto climb = [](bool plugged) {
    if (plugged) {
      EXPECT_TRUE(install(Backend::Dyop).ok());
    } else {
      EXPECT_TRUE(uninstall().ok());
    }
    World world;
    b2Body* ground = add_body(world, b2_staticBody, b2Vec2(0, 0));
    // Right to left, the front up: a flat run, a slope up 1 in 2, a flat top.
    const b2Vec2 v[] = {{6, 0}, {2, 0}, {-2, 2}, {-6, 2}};
    b2ChainShape chain;
    chain.CreateChain(v, 4, b2Vec2(8, 0), b2Vec2(-8, 2));
    ground->CreateFixture(&chain, 0);
    b2Body* ball = add_level_glider(world, LevelBody::Ball);
    ball->SetTransform(b2Vec2(4, 0.0f), 0);
    float vy_past_top = 0;
    for (int step = 0; step < 3 * kStepsPerSecond; ++step) {
      ball->SetLinearVelocity(b2Vec2(-5.0f, ball->GetLinearVelocity().y));
      world.step();
      if (ball->GetPosition().x < -2.3f && vy_past_top == 0)
        vy_past_top = ball->GetLinearVelocity().y;
    }
    EXPECT_TRUE(uninstall().ok());
    return vy_past_top;
  };
  const float own = climb(false);
  const float plugged = climb(true);
  std::printf("ball past a convex top: vertical speed %.4f m/s (Box2D's own %.4f)\n", plugged, own);
  EXPECT_NEAR(plugged, own, 0.05f);
}

// A step down to the right made of two-sided edges on one static body, left to right: a top at
// y = 0.5 over [−4, 0], the riser at x = 0 down to the floor at y = 0 over [0, 4].
void add_edge_step(World& world) {
  b2Body* ground = add_body(world, b2_staticBody, b2Vec2(0, 0));
  const b2Vec2 v[] = {{-4, 0.5f}, {-2, 0.5f}, {0, 0.5f}, {0, 0}, {2, 0}, {4, 0}};
  for (int i = 0; i + 1 < 6; ++i) {
    b2EdgeShape e;
    e.SetTwoSided(v[i], v[i + 1]);
    ground->CreateFixture(&e, 0);
  }
}

constexpr LevelBody kEveryLevelBody[] = {LevelBody::TriangleBox, LevelBody::Box, LevelBody::Hexagon,
                                         LevelBody::Ball};

// A frictionless `kind` on `world`'s step (`add_edge_step`) at `at`, moving at `velocity`.
b2Body* add_step_body(World& world, LevelBody kind, const b2Vec2& at, const b2Vec2& velocity) {
  add_edge_step(world);
  b2Body* body = add_level_glider(world, kind);
  body->SetTransform(at, 0);
  body->SetLinearVelocity(velocity);
  return body;
}

// True when `body` touches an edge fixture running from `p` to `q`.
bool touches_edge(b2Body* body, const b2Vec2& p, const b2Vec2& q) {
  for (b2ContactEdge* c = body->GetContactList(); c; c = c->next) {
    const b2Fixture* f = c->contact->GetFixtureA();
    if (f->GetType() != b2Shape::e_edge || !c->contact->IsTouching()) continue;
    const auto& e = *static_cast<const b2EdgeShape*>(f->GetShape());
    if (e.m_vertex1 == p && e.m_vertex2 == q) return true;
  }
  return false;
}

// A frictionless body at rest on a step's top, hanging over its corner (its centroid over the
// top): the riser's back, which faces the inside of the corner below the top, faces away from the
// body (its centroid lies beyond the top, the corner's other edge) and gives it no contact. It used
// to push the body back over the top at the depth of its overhang. (The body settles in the skins
// on a support off its centre: the exact normal tilts with it by a thousandth, a millimetre's drift
// in two seconds.)
TEST(TwoSidedEdgeCorners, ABodyOverhangingAStepRestsWithoutAPushFromTheRiserBehindIt) {
  ASSERT_TRUE(install(Backend::Dyop).ok());
  for (const LevelBody kind : kEveryLevelBody) {
    World world;
    const b2Vec2 start(-0.15f, 0.5f + 0.005f);
    b2Body* body = add_step_body(world, kind, start, b2Vec2(0, 0));
    float drift = 0;
    int riser_contacts = 0;
    for (int step = 0; step < 2 * kStepsPerSecond; ++step) {
      world.step();
      drift = std::max(drift, std::abs(body->GetPosition().x - start.x));
      riser_contacts += touches_edge(body, b2Vec2(0, 0.5f), b2Vec2(0, 0));
    }
    EXPECT_EQ(riser_contacts, 0) << name(kind);
    EXPECT_LT(drift, 0.005f) << name(kind);
  }
  ASSERT_TRUE(uninstall().ok());
}

// A frictionless body sliding off a step's top at 2 m/s: its contact with the riser began on the
// riser's back (the body over the top), and the body goes around the riser's top end; from there
// the riser's front faces it, so it falls down beside the riser to the floor, never pushed back
// toward the riser nor through it.
TEST(TwoSidedEdgeCorners, ABodyGoingAroundAnEndIsFacedByTheOtherSide) {
  ASSERT_TRUE(install(Backend::Dyop).ok());
  for (const LevelBody kind : kEveryLevelBody) {
    World world;
    b2Body* body = add_step_body(world, kind, b2Vec2(-1.5f, 0.5f + 0.005f), b2Vec2(2.0f, 0));
    float least_vx = 2.0f;
    for (int step = 0; step < 2 * kStepsPerSecond; ++step) {
      world.step();
      least_vx = std::min(least_vx, body->GetLinearVelocity().x);
    }
    // Frictionless: nothing but the corner's vertex and the floor slows it; no face pushes it back.
    EXPECT_GT(least_vx, 1.0f) << name(kind);
    EXPECT_GT(body->GetPosition().x, 2.0f) << name(kind);
    EXPECT_GT(body->GetPosition().y, -0.05f) << name(kind);
  }
  ASSERT_TRUE(uninstall().ok());
}

// The single-pair entry point with the edge's ends set in the pair's memory answers as a world's
// contact: a box over the top of a step, touching the riser's top end within the skins, gets no
// contact from the riser; without the ends (an edge alone, as Box2D's) it gets the riser's face.
TEST(TwoSidedEdgeCorners, TheSinglePairEntryPointFollowsTheEndsSetInItsMemory) {
  World world;
  add_edge_step(world);
  const b2Fixture* riser = nullptr;
  for (const b2Fixture* f = world->GetBodyList()->GetFixtureList(); f; f = f->GetNext()) {
    const auto& e = *static_cast<const b2EdgeShape*>(f->GetShape());
    if (e.m_vertex1.x == 0 && e.m_vertex2.x == 0) riser = f;
  }
  ASSERT_NE(riser, nullptr);
  const auto& edge = *static_cast<const b2EdgeShape*>(riser->GetShape());
  b2PolygonShape box;
  box.SetAsBox(0.4f, 0.3f);
  b2Transform at_edge;
  at_edge.SetIdentity();
  b2Transform over_top;
  over_top.Set(b2Vec2(-0.15f, 0.5f + 0.3f + 0.005f), 0);
  const EdgeEnds ends = edge_ends(*riser);
  EXPECT_EQ(ends.neighbours(), 0b11);
  ContactMemory memory;
  b2Manifold m;
  collide_edge_and_polygon(&m, Backend::Dyop, edge, at_edge, box, over_top, &memory);
  EXPECT_GT(m.pointCount, 0) << "an edge alone: the box touches its end within the skins";
  memory.edge_ends = ends;
  collide_edge_and_polygon(&m, Backend::Dyop, edge, at_edge, box, over_top, &memory);
  EXPECT_EQ(m.pointCount, 0) << "the riser faces away from a box over the top";
}

}  // namespace
}  // namespace dyop::box2d::testing
