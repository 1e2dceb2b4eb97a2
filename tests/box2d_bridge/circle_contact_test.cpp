// Circles and polygons through the plug-in behave as a Box2D user expects: the polygon is fixture
// A of a polygon–circle contact and the manifold has Box2D's type, `PreSolve` one-way platforms
// work as under Box2D's own contact, and install and uninstall at any moment leave every contact
// freed as what it is (run under ASan in CI) and `Backend::Box2D` bit-identical to Box2D's own.
#include <gtest/gtest.h>

#include <box2d/box2d.h>

#include <cmath>
#include <functional>

#include "dyop/box2d.hpp"
#include "support/worlds.hpp"

namespace dyop::box2d::testing {
namespace {

// A SetAsBox ground, then balls and crates dropped on it in a heap.
void add_heap(World& world) {
  b2Body* ground = add_body(world, b2_staticBody, b2Vec2(0, 0));
  for (int i = 0; i < 16; ++i) {
    b2PolygonShape tile;
    tile.SetAsBox(0.5f, 0.5f, b2Vec2(-8.0f + static_cast<float>(i), -0.5f), 0);
    ground->CreateFixture(&tile, 0);
  }
  for (int i = 0; i < 24; ++i) {
    b2Body* body = add_body(world, b2_dynamicBody,
                            b2Vec2(-3.0f + 0.8f * static_cast<float>(i % 8), 1.0f + 0.8f * (i / 8)),
                            0.5f * static_cast<float>(i));
    if (i % 2 == 0) {
      b2CircleShape ball;
      ball.m_radius = 0.3f;
      body->CreateFixture(&ball, 1.0f);
    } else {
      b2PolygonShape crate;
      crate.SetAsBox(0.3f, 0.25f);
      body->CreateFixture(&crate, 1.0f);
    }
  }
}

// The heap's final state after 150 steps, `at_step(i)` called before step i.
std::uint64_t heap_after(const std::function<void(int)>& at_step) {
  World world;
  add_heap(world);
  for (int i = 0; i < 150; ++i) {
    at_step(i);
    world.step();
  }
  return worlds::state_hash(world);
}

class CircleContact : public ::testing::Test {
 protected:
  void SetUp() override { ASSERT_TRUE(uninstall().ok()); }
  void TearDown() override { EXPECT_TRUE(uninstall().ok()); }
};

TEST_F(CircleContact, InstallAndUninstallMidSimulationGiveTheWorldBox2DsOwnContactWouldGive) {
  const std::uint64_t never = heap_after([](int) {});
  const std::uint64_t toggled = heap_after([](int i) {
    if (i == 30 || i == 90) {
      ASSERT_TRUE(install(Backend::Box2D).ok());
    }
    if (i == 60 || i == 120) {
      ASSERT_TRUE(uninstall().ok());
    }
  });
  EXPECT_EQ(toggled, never);
}

TEST_F(CircleContact, SwitchingBetweenTheExactSolverAndBox2DUnderLiveContactsFreesEveryContact) {
  // Contacts made under Box2D's own registration, the plug-in's, and a `triangles_only` one (where
  // circles keep Box2D's own contact) live side by side; the world's destruction frees each as
  // what it is (ASan checks the sizes).
  Config triangles_only;
  triangles_only.triangles_only = true;
  const std::uint64_t h = heap_after([&](int i) {
    if (i == 20) {
      ASSERT_TRUE(install(Backend::Dyop).ok());
    }
    if (i == 50) {
      ASSERT_TRUE(install(Backend::Dyop, triangles_only).ok());
    }
    if (i == 80) {
      ASSERT_TRUE(uninstall().ok());
    }
    if (i == 110) {
      ASSERT_TRUE(install(Backend::Sat).ok());
    }
  });
  EXPECT_NE(h, 0u);
}

// Checks every polygon–circle contact's order and manifold type in PreSolve.
class OrderChecker : public b2ContactListener {
 public:
  void PreSolve(b2Contact* contact, const b2Manifold*) override {
    const b2Shape::Type a = contact->GetFixtureA()->GetType();
    const b2Shape::Type b = contact->GetFixtureB()->GetType();
    if (a == b2Shape::e_circle && b == b2Shape::e_polygon) ++circle_first;
    if (a != b2Shape::e_polygon || b != b2Shape::e_circle) return;
    ++pairs;
    if (contact->GetManifold()->type != b2Manifold::e_faceA) ++wrong_type;
  }
  int pairs = 0;
  int circle_first = 0;
  int wrong_type = 0;
};

TEST_F(CircleContact, ThePolygonIsFixtureAAndTheManifoldIsFaceAAsUnderBox2D) {
  for (const bool plugin : {false, true}) {
    if (plugin) {
      ASSERT_TRUE(install(Backend::Dyop).ok());
    }
    OrderChecker checker;
    World world;
    world->SetContactListener(&checker);
    add_heap(world);
    for (int i = 0; i < 120; ++i) world.step();
    world->SetContactListener(nullptr);
    EXPECT_GT(checker.pairs, 0) << plugin;
    EXPECT_EQ(checker.circle_first, 0) << plugin;
    EXPECT_EQ(checker.wrong_type, 0) << plugin;
  }
  EXPECT_GT(stats().circle_pairs, 0u);
  EXPECT_GT(stats().exact_pairs, 0u);
}

// Box2D's one-sided platform (its testbed's): a contact with a body still below the platform's
// top is disabled in PreSolve, so what jumps from below passes through and lands on top.
class OneSided : public b2ContactListener {
 public:
  explicit OneSided(const b2Fixture* platform, float top) : platform_(platform), top_(top) {}
  void PreSolve(b2Contact* contact, const b2Manifold*) override {
    const b2Fixture* a = contact->GetFixtureA();
    const b2Fixture* b = contact->GetFixtureB();
    if (a != platform_ && b != platform_) return;
    const b2Body* other = (a == platform_ ? b : a)->GetBody();
    b2AABB box;
    (a == platform_ ? b : a)->GetShape()->ComputeAABB(&box, other->GetTransform(), 0);
    if (box.lowerBound.y < top_ - 3 * b2_linearSlop) contact->SetEnabled(false);
  }

 private:
  const b2Fixture* platform_;
  float top_;
};

// Where a ball or a crate thrown up through a platform at y = 3 ends (its lowest point).
float lands_at(bool ball) {
  World world;
  b2Body* ground = add_body(world, b2_staticBody, b2Vec2(0, 0));
  b2PolygonShape shape;
  shape.SetAsBox(5, 0.25f, b2Vec2(0, 2.75f), 0);
  const b2Fixture* platform = ground->CreateFixture(&shape, 0);
  OneSided listener(platform, 3.0f);
  world->SetContactListener(&listener);
  b2Body* body = add_body(world, b2_dynamicBody, b2Vec2(0, 1.0f));
  b2CircleShape circle;
  circle.m_radius = 0.3f;
  b2PolygonShape crate;
  crate.SetAsBox(0.3f, 0.3f);
  body->CreateFixture(ball ? static_cast<const b2Shape*>(&circle) : &crate, 1.0f);
  body->SetLinearVelocity(b2Vec2(0, 9.0f));
  for (int i = 0; i < 180; ++i) world.step();
  world->SetContactListener(nullptr);
  return body->GetPosition().y - 0.3f;
}

TEST_F(CircleContact, OneSidedPlatformsLetBodiesThroughFromBelowAndHoldThemOnTop) {
  for (const bool ball : {true, false}) {
    const float own = lands_at(ball);
    ASSERT_TRUE(install(Backend::Dyop).ok());
    const float plugin = lands_at(ball);
    ASSERT_TRUE(uninstall().ok());
    EXPECT_NEAR(own, 3.0f, 0.03f) << (ball ? "ball" : "crate") << " under Box2D's own contact";
    EXPECT_NEAR(plugin, 3.0f, 0.03f) << (ball ? "ball" : "crate") << " under the plug-in";
  }
}

}  // namespace
}  // namespace dyop::box2d::testing
