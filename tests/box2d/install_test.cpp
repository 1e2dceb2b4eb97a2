// Installing, switching and uninstalling the plug-in in Box2D's process-wide contact registry.
#include <cstring>

#include "scene.hpp"

namespace dyop::box2d::testing {
namespace {

// Two triangles resting on each other: one touching triangle–triangle contact after a step.
void add_touching_pair(World& world) {
  b2Body* base = add_body(world, b2_staticBody, b2Vec2(0.0f, 0.0f));
  add_triangle(base, b2Vec2(-1.0f, -1.0f), b2Vec2(1.0f, 0.0f), b2Vec2(-1.0f, 0.0f));
  b2Body* top = add_body(world, b2_dynamicBody, b2Vec2(0.0f, 0.01f));
  add_triangle(top, b2Vec2(-0.5f, 0.0f), b2Vec2(0.5f, 0.0f), b2Vec2(0.0f, 0.5f));
}

TEST(Install, RoundTripRegistersTheBackendAndRestoresBox2DsOwnContact) {
  ASSERT_FALSE(installed().has_value());
  EXPECT_TRUE(uninstall().ok()) << "uninstalling when not installed does nothing";

  const InstallResult r = install(Backend::Dyop);
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_EQ(installed(), Backend::Dyop);
  EXPECT_TRUE(install(Backend::Dyop).ok()) << "installing the installed backend again";
  {
    World world;
    add_touching_pair(world);
    world.step();
    EXPECT_EQ(live_contacts(), 1);
  }
  EXPECT_EQ(live_contacts(), 0);
  EXPECT_EQ(stats().triangles(Backend::Dyop), 1u);
  EXPECT_EQ(stats().manifolds, 1u);

  ASSERT_TRUE(uninstall().ok());
  EXPECT_FALSE(installed().has_value());
  reset_stats();
  {
    World world;
    add_touching_pair(world);
    world.step();
    ASSERT_NE(world->GetContactList(), nullptr);
    EXPECT_TRUE(world->GetContactList()->IsTouching()) << "Box2D's own contact answers again";
    EXPECT_EQ(live_contacts(), 0) << "and the plug-in made none";
  }
  const Stats s = stats();
  EXPECT_EQ(s.triangles(Backend::Dyop) + s.polygon_pairs + s.manifolds, 0u);
}

TEST(Install, ByMethodMapsToTheBackendAndRefusesDyopPaper) {
  EXPECT_EQ(install(Method::DyopPaper).status, InstallStatus::UnsupportedMethod);
  EXPECT_FALSE(installed().has_value());
  const Method methods[] = {Method::Dyop, Method::DyopFast, Method::LinCanny, Method::Sat,
                            Method::Epa};
  const Backend backends[] = {Backend::Dyop, Backend::DyopFast, Backend::LinCanny, Backend::Sat,
                              Backend::Epa};
  for (int i = 0; i < 5; ++i) {
    ASSERT_TRUE(install(methods[i]).ok());
    EXPECT_EQ(installed(), backends[i]) << "switching with no contact alive is allowed";
  }
  EXPECT_TRUE(uninstall().ok());
}

TEST(Install, SwitchingOrUninstallingWhileContactsExistIsRefused) {
  ASSERT_TRUE(install(Backend::Sat).ok());
  {
    World world;
    add_touching_pair(world);
    world.step();
    ASSERT_EQ(live_contacts(), 1);

    const InstallResult switched = install(Backend::Dyop);
    EXPECT_EQ(switched.status, InstallStatus::ContactsExist);
    EXPECT_NE(std::strstr(switched.message, "contacts"), nullptr) << switched.message;
    const InstallResult removed = uninstall();
    EXPECT_EQ(removed.status, InstallStatus::ContactsExist);
    EXPECT_EQ(installed(), Backend::Sat) << "a refusal changes nothing";
    EXPECT_TRUE(install(Backend::Sat).ok()) << "re-installing the same backend is not a switch";

    world.step();  // the world goes on with the contact it had
    EXPECT_GT(stats().triangles(Backend::Sat), 1u);
  }
  EXPECT_EQ(live_contacts(), 0);
  EXPECT_TRUE(install(Backend::Dyop).ok()) << "allowed once the contacts are gone";
  EXPECT_TRUE(uninstall().ok());
}

TEST(Install, BackendsHaveTheCommandLineNames) {
  const char* names[] = {"dyop", "dyop-fast", "lin-canny", "sat", "epa", "box2d"};
  for (int i = 0; i < backend_count; ++i) EXPECT_STREQ(name(all_backends[i]), names[i]);
}

}  // namespace
}  // namespace dyop::box2d::testing
