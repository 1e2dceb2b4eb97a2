// Manifold recycling (`Config::recycle_distance`) in worlds built by hand: a resting pair keeps its
// manifolds, fast bodies are stopped, a change of masks or install recomputes, bodies made and
// destroyed far away change nothing, and the measurement floor keeps everything. (In the scenes:
// structures stand, kept manifolds stay within the bound of a fresh answer, off is bit-identical:
// tests/testbed/recycling_scenes_test.cpp.)
#include <gtest/gtest.h>

#include <optional>
#include <utility>
#include <vector>

#include "dyop/box2d_internal_edges.hpp"
#include "dyop/box2d_measurement.hpp"
#include "dyop/box2d.hpp"
#include "support/worlds.hpp"

namespace dyop::box2d::testing {
namespace {

Config recycling(float distance) {
  Config c = Config::all();
  c.recycle_distance = distance;
  return c;
}

// 100 m/s at a 6 cm wall (see bullet_test.cpp): every step moves the body metres, far beyond any
// distance, so no evaluation of its contact with the wall is kept.
TEST(Recycling, FastBodyIsNeverKeptThroughAThinWall) {
  ASSERT_TRUE(install(Backend::Dyop, recycling(0.05f)).ok());
  for (const bool bullet : {false, true}) {
    World world(b2Vec2(0.0f, 0.0f));
    b2Body* wall = add_body(world, b2_staticBody, b2Vec2(0.0f, 0.0f));
    add_triangle(wall, b2Vec2(0.0f, -2.0f), b2Vec2(0.06f, 0.0f), b2Vec2(0.0f, 2.0f));
    b2Body* shot = add_body(world, b2_dynamicBody, b2Vec2(-5.0f, 0.0f));
    shot->SetBullet(bullet);
    const b2Fixture* f =
        add_triangle(shot, b2Vec2(-0.05f, -0.04f), b2Vec2(0.05f, 0.0f), b2Vec2(-0.05f, 0.04f));
    shot->SetLinearVelocity(b2Vec2(100.0f, 0.0f));
    const auto* shape = static_cast<const b2PolygonShape*>(f->GetShape());
    float reach = -5.0f;
    for (int i = 0; i < kStepsPerSecond; ++i) {
      world.step();
      for (int k = 0; k < 3; ++k) {
        reach = std::max(reach, shot->GetWorldPoint(shape->m_vertices[k]).x);
      }
    }
    EXPECT_LT(reach, 0.0f) << (bullet ? "bullet" : "non-bullet");
  }
  uninstall();
}

// A box resting awake on a one-triangle ground (static unless told): once settled, every
// evaluation is kept.
struct RestingBox {
  World world;
  b2Body* ground;
  b2Body* box;
  explicit RestingBox(b2BodyType ground_type = b2_staticBody) {
    ground = add_body(world, ground_type, b2Vec2(0.0f, 0.0f));
    add_triangle(ground, b2Vec2(-4.0f, 0.0f), b2Vec2(4.0f, 0.0f), b2Vec2(-4.0f, -1.0f));
    box = add_split_box(world, b2Vec2(0.0f, 0.5f + b2_polygonRadius), 0.5f);
    box->SetSleepingAllowed(false);
    for (int i = 0; i < 2 * kStepsPerSecond; ++i) world.step();
  }
  // A triangle added to the ground 3.5 m from the box, covering the ground triangle's left edge
  // from below: that edge becomes internal, a change of masks far from the box.
  void add_far_neighbour() {
    add_triangle(ground, b2Vec2(-4.0f, 0.0f), b2Vec2(-4.0f, -1.0f), b2Vec2(-6.0f, -1.0f));
  }
  // The box moved by `dx` along the ground (metres).
  void move_box(float dx) {
    box->SetTransform(box->GetPosition() + b2Vec2(dx, 0.0f), box->GetAngle());
  }
  // Evaluations kept in one step.
  std::uint64_t kept_in_one_step() {
    const std::uint64_t before = stats().recycled;
    world.step();
    return stats().recycled - before;
  }
};

TEST(Recycling, RestingContactsAreKeptAndAnotherInstallRecomputes) {
  ASSERT_TRUE(install(Backend::Dyop, recycling(0.01f)).ok());
  RestingBox r;
  EXPECT_EQ(r.kept_in_one_step(), 2u) << "both of the box's triangles rest on the ground";
  Config other = recycling(0.01f);
  other.warm_axis = false;
  ASSERT_TRUE(install(Backend::Dyop, other).ok());
  EXPECT_EQ(r.kept_in_one_step(), 0u) << "the first step under another install";
  EXPECT_EQ(r.kept_in_one_step(), 2u);
  uninstall();
}

TEST(Recycling, AContactWhoseMasksMayChangeRecomputes) {
  ASSERT_TRUE(install(Backend::Dyop, recycling(0.01f)).ok());
  RestingBox r;
  ASSERT_EQ(r.kept_in_one_step(), 2u);
  // A triangle added under the box, covering the ground's long edge from below: the ground
  // triangle's masks change (that edge becomes internal), so the box's contacts with the ground
  // recompute. It lies within the broad phase's reach of the box: their new contact tells.
  add_triangle(r.ground, b2Vec2(4.0f, 0.0f), b2Vec2(-4.0f, -1.0f), b2Vec2(4.0f, -1.0f));
  EXPECT_EQ(r.kept_in_one_step(), 0u);
  EXPECT_EQ(r.kept_in_one_step(), 4u) << "the box's 2 triangles on the ground's 2";
  uninstall();
}

// A world that makes and destroys bodies far from a resting pair (a spawner, a streamed level):
// the world's fixture count moves at every step, and the pair keeps its manifolds throughout.
// Before: every contact recomputed at every step (the spawning pyramid's narrow phase went from
// 0.44 to 3.4 times Box2D's own).
TEST(Recycling, BodiesMadeAndDestroyedFarAwayLeaveKeptManifoldsKept) {
  ASSERT_TRUE(install(Backend::Dyop, recycling(0.01f)).ok());
  RestingBox r;
  ASSERT_EQ(r.kept_in_one_step(), 2u);
  b2Body* far = nullptr;
  for (int i = 0; i < 10; ++i) {
    if (far) {
      r.world->DestroyBody(far);
      far = nullptr;
    } else {
      far = add_body(r.world, b2_dynamicBody, b2Vec2(100.0f, 100.0f));
      add_triangle(far, b2Vec2(0.0f, 0.0f), b2Vec2(1.0f, 0.0f), b2Vec2(0.0f, 1.0f));
    }
    EXPECT_EQ(r.kept_in_one_step(), 2u) << "step " << i;
  }
  uninstall();
}

// The contacts of `world` that report masks (`contact_internal_edges`), each checked to hold those
// of its two fixtures found afresh.
int contacts_holding_masks_found_afresh(World& world) {
  int checked = 0;
  for (b2Contact* c = world->GetContactList(); c; c = c->GetNext()) {
    const std::optional<InternalEdges> held = contact_internal_edges(*c);
    if (!held) continue;
    EXPECT_EQ(*held, InternalEdges::pair(triangle_internal_edges(*c->GetFixtureA()),
                                         triangle_internal_edges(*c->GetFixtureB())));
    ++checked;
  }
  return checked;
}

// A triangle added to the ground far from the box, sharing the end of the ground's top edge (so
// that the ground triangle's masks change there, 3.5 m from the box): the kept manifolds stay,
// and once the box has moved as far as such a change could matter (0.05 m; here 0.15 m, as a
// body sliding toward it would), its contacts answer with the masks as the world now is.
TEST(Recycling, AFarChangeOfMasksIsSeenOnceThePairMovedTowardIt) {
  ASSERT_TRUE(install(Backend::Dyop, recycling(0.01f)).ok());
  RestingBox r;
  ASSERT_EQ(r.kept_in_one_step(), 2u);
  const b2Fixture* ground = r.ground->GetFixtureList();
  const InternalEdges before = triangle_internal_edges(*ground);
  r.add_far_neighbour();
  ASSERT_FALSE(triangle_internal_edges(*ground) == before) << "the ground triangle's masks moved";
  EXPECT_EQ(r.kept_in_one_step(), 2u) << "nothing near the box changed";
  r.move_box(-0.15f);
  EXPECT_EQ(r.kept_in_one_step(), 0u) << "moved beyond the distance";
  EXPECT_EQ(contacts_holding_masks_found_afresh(r.world), 2)
      << "both of the box's contacts with the ground hold current masks";
  uninstall();
}

// With a recycling distance of 5 cm, a kept manifold may move 10 cm around the pose at a far
// change, beyond what the change's distance allows (0.05 m): the box's contacts recompute (and
// find their masks again) at the first step after it, then keep again.
TEST(Recycling, WithALargeDistanceAFarChangeRecomputesAtOnce) {
  ASSERT_TRUE(install(Backend::Dyop, recycling(0.05f)).ok());
  RestingBox r;
  ASSERT_EQ(r.kept_in_one_step(), 2u);
  r.add_far_neighbour();
  EXPECT_EQ(r.kept_in_one_step(), 0u);
  EXPECT_EQ(r.kept_in_one_step(), 2u);
  uninstall();
}

// The same far change, with the world's fixture count brought back to what it was by another far
// change a step later (a far body destroyed): the pair saw the count move once, and follows its
// motion from then on, so it still finds its masks again once it moved toward the change.
TEST(Recycling, AFarChangeIsSeenAfterAnotherBringsTheFixtureCountBack) {
  ASSERT_TRUE(install(Backend::Dyop, recycling(0.01f)).ok());
  RestingBox r;
  b2Body* far = add_body(r.world, b2_staticBody, b2Vec2(100.0f, 100.0f));
  add_triangle(far, b2Vec2(0.0f, 0.0f), b2Vec2(1.0f, 0.0f), b2Vec2(0.0f, 1.0f));
  // The box's masks found afresh under the count with `far`.
  r.move_box(0.15f);
  for (int i = 0; i < 10; ++i) r.world.step();
  const int fixtures = r.world->GetProxyCount();
  r.add_far_neighbour();
  EXPECT_EQ(r.kept_in_one_step(), 2u) << "nothing near the box changed";
  r.world->DestroyBody(far);
  ASSERT_EQ(r.world->GetProxyCount(), fixtures);
  EXPECT_EQ(r.kept_in_one_step(), 2u);
  r.move_box(-0.15f);
  EXPECT_EQ(r.kept_in_one_step(), 0u) << "moved beyond the distance";
  EXPECT_EQ(contacts_holding_masks_found_afresh(r.world), 2)
      << "both of the box's contacts with the ground hold current masks";
  uninstall();
}

// A pair with a static body keeps within a fifth of the distance (a body sinking deeper into
// static ground meets Box2D's time-of-impact pass): the box moved 4 mm between steps recomputes
// on a static ground (kept within 2 mm) and is kept on a kinematic one at rest (within 10 mm).
TEST(Recycling, APairWithAStaticBodyKeepsWithinAFifthOfTheDistance) {
  ASSERT_TRUE(install(Backend::Dyop, recycling(0.01f)).ok());
  for (const b2BodyType ground : {b2_staticBody, b2_kinematicBody}) {
    RestingBox r(ground);
    ASSERT_EQ(r.kept_in_one_step(), 2u);
    r.move_box(0.004f);
    EXPECT_EQ(r.kept_in_one_step(), ground == b2_staticBody ? 0u : 2u)
        << (ground == b2_staticBody ? "static" : "kinematic") << " ground";
  }
  uninstall();
}

TEST(Recycling, TheFloorKeepsEveryAnswerAfterTheFirst) {
  ASSERT_TRUE(install(Backend::Dyop).ok());
  RestingBox r;
  ASSERT_TRUE(measurement::install_never_recompute(Backend::Dyop).ok());
  EXPECT_EQ(r.kept_in_one_step(), 0u) << "the first answer under the floor is computed";
  for (int i = 0; i < 10; ++i) {
    const std::uint64_t pairs = stats().triangles(Backend::Dyop);
    const std::uint64_t kept = r.kept_in_one_step();
    EXPECT_EQ(kept, stats().triangles(Backend::Dyop) - pairs);
  }
  EXPECT_EQ(install(Backend::Dyop).message, std::string("installed")) << "install ends the floor";
  uninstall();
}

}  // namespace
}  // namespace dyop::box2d::testing
