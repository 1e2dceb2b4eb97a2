// Skipping never changes the answer: a world stepped with every skip on gives the same bodies,
// to the bit, as with every skip off (exact backends), and each skip is actually taken.
#include <gtest/gtest.h>

#include <box2d/box2d.h>

#include <cstdint>
#include <iostream>
#include <memory>
#include <set>
#include <sstream>
#include <vector>

#include "dyop/box2d.hpp"
#include "worlds/world.hpp"

namespace dyop::box2d {
namespace {

constexpr float kStep = 1.0f / 60.0f;

struct Outcome {
  std::uint64_t hash = 0;  // `worlds::state_hash` of the falling bodies
  Stats stats;
};

void add_triangle(b2Body* body, b2Vec2 p0, b2Vec2 p1, b2Vec2 p2, float density) {
  const TriangleShape t = make_triangle(p0, p1, p2);
  ASSERT_TRUE(t.ok()) << t.message;
  b2FixtureDef fd;
  fd.shape = &t.shape;
  fd.density = density;
  fd.friction = 0.6f;
  body->CreateFixture(&fd);
}

// A static bin of triangle fixtures, triangles of mixed sizes dropped into it from a grid (many
// pairs meet in the broad phase while apart), and boxes of two triangles that come to rest.
Outcome run(Backend backend, const Config& config, int steps) {
  EXPECT_TRUE(install(backend, config).ok());
  Outcome out;
  {
    auto world = std::make_unique<b2World>(b2Vec2(0.0f, -10.0f));
    b2BodyDef ground_def;
    b2Body* ground = world->CreateBody(&ground_def);
    for (float x = -6; x < 6; x += 1) {
      add_triangle(ground, {x, -1}, {x + 1, -1}, {x + 1, 0}, 0);
      add_triangle(ground, {x, -1}, {x + 1, 0}, {x, 0}, 0);
    }
    for (float y = 0; y < 8; y += 1) {
      add_triangle(ground, {-7, y}, {-6, y}, {-6, y + 1}, 0);
      add_triangle(ground, {6, y}, {7, y + 1}, {6, y + 1}, 0);
    }
    std::vector<b2Body*> bodies;
    int k = 0;
    for (int row = 0; row < 6; ++row) {
      for (int col = 0; col < 10; ++col, ++k) {
        b2BodyDef def;
        def.type = b2_dynamicBody;
        def.position.Set(-5.0f + 1.1f * col, 1.5f + 1.2f * row);
        def.angle = 0.37f * k;
        b2Body* body = world->CreateBody(&def);
        const float s = 0.25f + 0.05f * static_cast<float>(k % 5);
        add_triangle(body, {-s, -s}, {s, -0.5f * s}, {0.2f * s, s}, 1);
        bodies.push_back(body);
      }
    }
    for (int i = 0; i < steps; ++i) world->Step(kStep, 8, 3);
    out.hash = worlds::state_hash(bodies);
    out.stats = stats();
    // Destroying the bodies destroys their contacts, so the plug-in can be switched afterwards.
    for (b2Body* b = world->GetBodyList(); b != nullptr;) {
      b2Body* next = b->GetNext();
      world->DestroyBody(b);
      b = next;
    }
  }
  EXPECT_TRUE(uninstall().ok());
  return out;
}

class Skips : public ::testing::TestWithParam<Backend> {};

TEST_P(Skips, EverySkipOnGivesTheBitIdenticalWorldOfEverySkipOff) {
  const Outcome off = run(GetParam(), Config::no_skips(), 360);
  const Outcome on = run(GetParam(), Config::all(), 360);
  EXPECT_EQ(on.hash, off.hash);
  EXPECT_EQ(on.stats.triangles(GetParam()), off.stats.triangles(GetParam()));
  EXPECT_EQ(on.stats.manifolds, off.stats.manifolds);
  EXPECT_GT(on.stats.skips(Skip::Bounds), 0u);
  if (GetParam() != Backend::Box2D) {  // Box2D's own code reports no face to warm-start
    EXPECT_GT(on.stats.skips(Skip::WarmAxis), 0u);
  }
  for (int s = 0; s < skip_count; ++s) EXPECT_EQ(off.stats.skipped[s], 0u);
  std::ostringstream figures;
  figures << "evaluations " << on.stats.triangles(GetParam()) << ", skipped: bounds "
          << on.stats.skips(Skip::Bounds) << ", warm-axis " << on.stats.skips(Skip::WarmAxis);
  RecordProperty("skips", figures.str());
  std::cout << name(GetParam()) << ": " << figures.str() << '\n';
}

TEST_P(Skips, EachSkipAloneGivesTheBitIdenticalWorld) {
  const Outcome off = run(GetParam(), Config::no_skips(), 240);
  for (int which = 0; which < 3; ++which) {
    Config one = Config::no_skips();
    bool* flags[] = {&one.bounds_early_out, &one.warm_axis, &one.lin_canny_cache};
    *flags[which] = true;
    EXPECT_EQ(run(GetParam(), one, 240).hash, off.hash) << "skip " << which;
  }
}

// The exact backends, and Box2D's own code through the plug-in (which uses the same face rule).
INSTANTIATE_TEST_SUITE_P(ExactBackends, Skips,
                         ::testing::Values(Backend::Dyop, Backend::Sat, Backend::Box2D),
                         [](const auto& info) { return std::string(name(info.param)); });

// Boxes, hexagons and balls poured onto a chain (no triangle pair): every family's evaluations
// split into kept, skipped (per reason) and answered afresh, and every contact the plug-in made is
// counted, as Box2D's contact list sees them.
TEST(StatsOfEveryFamily, EvaluationsSplitIntoKeptSkippedAndAnsweredAndContactsAreCounted) {
  ASSERT_TRUE(install(Backend::Dyop).ok());
  std::uint64_t made = 0;
  {
    worlds::World world;
    b2Body* ground = worlds::add_body(world, b2_staticBody, b2Vec2(0, 0));
    const b2Vec2 v[] = {{10, 0}, {-10, 0}};
    b2ChainShape chain;
    chain.CreateChain(v, 2, b2Vec2(12, 0), b2Vec2(-12, 0));
    ground->CreateFixture(&chain, 0);
    for (int i = 0; i < 60; ++i) {
      b2Body* body = worlds::add_body(world, b2_dynamicBody,
                                      b2Vec2(-5.0f + 0.5f * static_cast<float>(i % 20),
                                             1.0f + 0.6f * static_cast<float>(i / 20)));
      b2PolygonShape box;
      box.SetAsBox(0.25f, 0.2f);
      b2CircleShape ball;
      ball.m_radius = 0.25f;
      body->CreateFixture(i % 2 == 0 ? static_cast<const b2Shape*>(&box) : &ball, 1.0f);
    }
    // The plug-in's contacts that appear in the world's list from one step to the next (a
    // contact destroyed and another made at its address within one step is seen once).
    std::set<const b2Contact*> before;
    for (int step = 0; step < 120; ++step) {
      world.step();
      std::set<const b2Contact*> now;
      for (const b2Contact* c = world->GetContactList(); c; c = c->GetNext()) {
        if (c->GetFixtureA()->GetType() == b2Shape::e_circle &&
            c->GetFixtureB()->GetType() == b2Shape::e_circle) {
          continue;  // Box2D's own
        }
        now.insert(c);
        made += before.count(c) == 0 ? 1 : 0;
      }
      before = std::move(now);
    }
  }
  const Stats s = stats();
  EXPECT_EQ(s.triangles(Backend::Dyop), 0u);
  EXPECT_GT(s.polygon_pairs, 0u);
  EXPECT_GT(s.circle_pairs, 0u);
  EXPECT_GT(s.edge_pairs, 0u);
  EXPECT_GT(s.skips(Skip::Bounds), 0u);
  EXPECT_GT(s.recycled, 0u);
  EXPECT_EQ(s.evaluations(), s.polygon_pairs + s.circle_pairs + s.edge_pairs);
  EXPECT_EQ(s.answered() + s.recycled + s.skips(Skip::Bounds) + s.skips(Skip::WarmAxis),
            s.evaluations());
  EXPECT_GT(s.answered(), 0u);
  EXPECT_GT(made, 0u);
  EXPECT_GE(s.contacts, made);
  ASSERT_TRUE(uninstall().ok());
}

}  // namespace
}  // namespace dyop::box2d
