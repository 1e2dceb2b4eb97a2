// Installing, switching and uninstalling the plug-in in Box2D's process-wide contact registry, at
// any moment of a program: before the first step, mid-simulation, with two worlds alive, after a
// world was deleted without destroying its bodies. The sanitizer build (scripts/sanitize.sh) runs
// these too: a contact freed with the wrong function or size is reported there.
#include <gtest/gtest.h>

#include <cstdint>
#include <memory>

#include "dyop/box2d.hpp"
#include "support/worlds.hpp"

namespace dyop::box2d::testing {
namespace {

// Two triangles resting on each other: one touching triangle–triangle contact after a step.
void add_touching_pair(b2World& world) {
  b2BodyDef def;
  b2Body* base = world.CreateBody(&def);
  add_triangle(base, b2Vec2(-1.0f, -1.0f), b2Vec2(1.0f, 0.0f), b2Vec2(-1.0f, 0.0f));
  def.type = b2_dynamicBody;
  def.position.Set(0.0f, 0.01f);
  b2Body* top = world.CreateBody(&def);
  add_triangle(top, b2Vec2(-0.5f, 0.0f), b2Vec2(0.5f, 0.0f), b2Vec2(0.0f, 0.5f));
}

// A pile that keeps contacts coming and going: split boxes dropped on a triangle ground.
void add_pile(World& world) {
  add_triangle_ground(world, 6.0f);
  for (int i = 0; i < 12; ++i) {
    add_split_box(world, b2Vec2(-3.0f + 0.55f * (i % 6), 0.6f + 1.1f * (i / 6)), 0.5f);
  }
}

void step(World& world, int steps) {
  for (int i = 0; i < steps; ++i) world.step();
}

// The pile after 180 steps, with `change(step)` called before each step (installs, switches).
template <class Change>
std::uint64_t pile_after(Change change) {
  World world;
  add_pile(world);
  for (int i = 0; i < 180; ++i) {
    change(i);
    world.step();
  }
  return worlds::state_hash(world);
}

// Each test leaves the registry as it found it: Box2D's own contact.
class Install : public ::testing::Test {
 protected:
  void TearDown() override { EXPECT_TRUE(uninstall().ok()); }
};

TEST_F(Install, RoundTripRegistersTheBackendAndRestoresBox2DsOwnContact) {
  ASSERT_FALSE(installed().has_value());
  EXPECT_TRUE(uninstall().ok()) << "uninstalling when not installed does nothing";

  const InstallResult r = install(Backend::Dyop);
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_EQ(installed(), Backend::Dyop);
  EXPECT_TRUE(install(Backend::Dyop).ok()) << "installing the installed backend again";
  {
    World world;
    add_touching_pair(world.get());
    world.step();
  }
  EXPECT_EQ(stats().triangles(Backend::Dyop), 1u);
  EXPECT_EQ(stats().manifolds, 1u);

  ASSERT_TRUE(uninstall().ok());
  EXPECT_FALSE(installed().has_value());
  reset_stats();
  {
    World world;
    add_touching_pair(world.get());
    world.step();
    ASSERT_NE(world->GetContactList(), nullptr);
    EXPECT_TRUE(world->GetContactList()->IsTouching()) << "Box2D's own contact answers again";
  }
  const Stats s = stats();
  EXPECT_EQ(s.triangles(Backend::Dyop) + s.polygon_pairs + s.manifolds, 0u)
      << "the plug-in evaluated nothing";
}

TEST_F(Install, ByMethodMapsToTheBackendAndRefusesDyopPaper) {
  EXPECT_EQ(install(Method::DyopPaper).status, InstallStatus::UnsupportedMethod);
  EXPECT_FALSE(installed().has_value());
  const Method methods[] = {Method::Dyop, Method::DyopFast, Method::LinCanny, Method::Sat,
                            Method::Epa};
  const Backend backends[] = {Backend::Dyop, Backend::DyopFast, Backend::LinCanny, Backend::Sat,
                              Backend::Epa};
  for (int i = 0; i < 5; ++i) {
    ASSERT_TRUE(install(methods[i]).ok());
    EXPECT_EQ(installed(), backends[i]);
  }
}

TEST_F(Install, AWorldMadeAfterUninstallIsBitIdenticalToOneThatNeverSawThePlugIn) {
  const std::uint64_t never = pile_after([](int) {});
  ASSERT_TRUE(install(Backend::Dyop).ok());
  const std::uint64_t with_dyop = pile_after([](int) {});
  ASSERT_TRUE(uninstall().ok());
  EXPECT_EQ(pile_after([](int) {}), never);
  EXPECT_NE(with_dyop, never) << "the plug-in did answer while installed (float rounding differs)";
}

TEST_F(Install, InstallingMidSimulationKeepsBox2DsContactsAndGivesNewOnesToThePlugIn) {
  World world;
  add_pile(world);
  step(world, 60);  // Box2D's own contacts exist now
  ASSERT_TRUE(install(Backend::Dyop).ok()) << "never refused";
  add_split_box(world, b2Vec2(0.0f, 4.0f), 0.5f);  // lands on the pile: new contacts
  step(world, 120);
  EXPECT_GT(stats().triangles(Backend::Dyop), 0u) << "contacts made after the install are ours";
  for (const b2Body* b = world->GetBodyList(); b != nullptr; b = b->GetNext()) {
    EXPECT_TRUE(std::isfinite(b->GetPosition().x) && std::isfinite(b->GetPosition().y));
  }
  // Destroying the bodies destroys both kinds of contact through the registered function.
}

TEST_F(Install, InstallAndUninstallMidSimulationGiveTheWorldBox2DsOwnContactWouldGive) {
  // `Backend::Box2D` answers with b2CollidePolygons, bit for bit Box2D's own contact: a world whose
  // registration changes under live contacts ends where Box2D alone takes it, and every contact,
  // made under either registration, is freed by whichever is registered when it ends.
  const std::uint64_t never = pile_after([](int) {});
  const std::uint64_t toggled = pile_after([](int i) {
    if (i == 30 || i == 90) {
      ASSERT_TRUE(install(Backend::Box2D).ok());
    }
    if (i == 60 || i == 120) {
      ASSERT_TRUE(uninstall().ok());
    }
  });
  EXPECT_EQ(toggled, never);
}

TEST_F(Install, ExistingContactsFollowASwitchFromTheNextStep) {
  World world;
  add_pile(world);
  ASSERT_TRUE(install(Backend::Dyop).ok());
  step(world, 60);
  ASSERT_GT(stats().triangles(Backend::Dyop), 0u);
  ASSERT_TRUE(install(Backend::Epa).ok());  // resets the counters
  world.step();
  EXPECT_EQ(stats().triangles(Backend::Dyop), 0u);
  EXPECT_GT(stats().triangles(Backend::Epa), 0u) << "the pile's live contacts answer with EPA";

  // Switching back and forth between the two exact backends whose manifolds are equal bit for bit
  // (sat and dyop share their axes and clipping) leaves the world where dyop alone takes it; with
  // recycling off, as a switch makes every contact compute afresh.
  Config fresh;
  fresh.recycle_distance = 0;
  ASSERT_TRUE(uninstall().ok());
  ASSERT_TRUE(install(Backend::Dyop, fresh).ok());
  const std::uint64_t dyop_alone = pile_after([](int) {});
  const std::uint64_t switched = pile_after([&fresh](int i) {
    if (i == 50) {
      ASSERT_TRUE(install(Backend::Sat, fresh).ok());
    }
    if (i == 100) {
      ASSERT_TRUE(install(Backend::Dyop, fresh).ok());
    }
  });
  EXPECT_EQ(switched, dyop_alone);
}

TEST_F(Install, UninstallingLeavesThePlugInsLiveContactsAnsweringAsBox2D) {
  World world;
  add_pile(world);
  ASSERT_TRUE(install(Backend::Dyop).ok());
  step(world, 60);
  ASSERT_TRUE(uninstall().ok()) << "never refused, contacts or not";
  reset_stats();
  step(world, 60);
  EXPECT_EQ(stats().triangles(Backend::Dyop), 0u) << "no evaluation reaches the backend";
  EXPECT_EQ(stats().polygon_pairs, 0u);
}

TEST_F(Install, TwoWorldsAliveAcrossInstallSwitchAndUninstall) {
  auto first = std::make_unique<World>();
  add_pile(*first);
  step(*first, 30);  // Box2D's own contacts in the first world
  ASSERT_TRUE(install(Backend::Sat).ok());
  auto second = std::make_unique<World>();
  add_pile(*second);
  for (int i = 0; i < 60; ++i) {
    first->step();
    second->step();
  }
  ASSERT_TRUE(install(Backend::LinCanny).ok());
  step(*first, 30);
  ASSERT_TRUE(uninstall().ok());
  step(*second, 30);
  first.reset();  // each world frees a mix of Box2D's and the plug-in's contacts
  step(*second, 30);
  second.reset();
  EXPECT_FALSE(installed().has_value());
}

TEST_F(Install, AWorldDeletedWithoutDestroyingItsBodiesBlocksNothing) {
  ASSERT_TRUE(install(Backend::Dyop).ok());
  {
    // b2World's destructor frees its contacts wholesale, never calling a destroy function.
    b2World world(b2Vec2(0.0f, -10.0f));
    add_touching_pair(world);
    for (int i = 0; i < 10; ++i) world.Step(1.0f / 60, 8, 3);
    ASSERT_GT(stats().manifolds, 0u);
  }
  const InstallResult switched = install(Backend::Sat);
  EXPECT_TRUE(switched.ok()) << switched.message;
  EXPECT_EQ(installed(), Backend::Sat);
  const InstallResult removed = uninstall();
  EXPECT_TRUE(removed.ok()) << removed.message;
  EXPECT_FALSE(installed().has_value()) << "Box2D's own contact is really back";
  reset_stats();
  b2World world(b2Vec2(0.0f, -10.0f));
  add_touching_pair(world);
  world.Step(1.0f / 60, 8, 3);
  EXPECT_EQ(stats().triangles(Backend::Sat) + stats().manifolds, 0u);
}

TEST(InstallNames, BackendsHaveTheCommandLineNames) {
  const char* names[] = {"dyop", "dyop-fast", "lin-canny", "sat", "epa", "box2d"};
  for (int i = 0; i < backend_count; ++i) EXPECT_STREQ(name(all_backends[i]), names[i]);
}

}  // namespace
}  // namespace dyop::box2d::testing
