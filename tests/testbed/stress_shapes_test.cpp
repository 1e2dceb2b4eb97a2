// Hostile points, as the testbed's stress categories make them, in Box2D worlds: `make_triangle`
// refuses what Box2D would assert on and Box2D takes the rest (the stress worlds of every contact:
// tests/box2d_bridge/stress_world_test.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "box2d_bridge/support/worlds.hpp"
#include "dyop/box2d.hpp"
#include "workloads/input_classes.hpp"
#include "workloads/random.hpp"

namespace dyop::box2d::testing {
namespace {

// Hostile points, as the stress categories make them (slivers, nearly collinear, touching,
// contained...), scaled from 1e-4 to 1e4: `make_triangle` refuses them with a message, or Box2D
// takes them without asserting (fixture creation computes the centroid and the mass, where Box2D
// 2.4 asserts) and steps them on a ground without a NaN.
TEST(StressShapes, MakeTriangleRefusesWhatBox2DWouldAssertOnAndBox2DTakesTheRest) {
  using workloads::InputClass;
  using workloads::Precision;
  int accepted = 0;
  int refused = 0;
  workloads::Random rng(3);
  for (InputClass c : workloads::stress_classes) {
    for (const workloads::RawPair& p : workloads::make_pairs(c, 100, 21, Precision::Float)) {
      const double s = rng.log_uniform(-4, 4);
      b2Vec2 v[3];
      for (int i = 0; i < 3; ++i) {
        v[i].Set(float(s * (p.a[i].x() - p.a[0].x())), float(s * (p.a[i].y() - p.a[0].y())));
      }
      const TriangleShape t = make_triangle(v[0], v[1], v[2]);
      if (!t.ok()) {
        ++refused;
        EXPECT_NE(t.error, ShapeError::None);
        EXPECT_GT(std::string(t.message).size(), 10u);
        continue;
      }
      ++accepted;
      World world;
      add_triangle_ground(world, 2.0f);
      b2Body* body = add_body(world, b2_dynamicBody, b2Vec2(0.0f, 1.0f + 2.0f * float(s)));
      b2FixtureDef def;
      def.shape = &t.shape;
      def.density = 1.0f;
      body->CreateFixture(&def);
      EXPECT_GT(body->GetMass(), 0.0f);
      EXPECT_TRUE(std::isfinite(body->GetInertia()));
      for (int i = 0; i < 5; ++i) world.step();
      EXPECT_TRUE(finite_state(world)) << workloads::name(c) << " scaled by " << s;
    }
  }
  EXPECT_GT(accepted, 0);
  EXPECT_GT(refused, 0);
  ::testing::Test::RecordProperty("accepted", accepted);
  ::testing::Test::RecordProperty("refused", refused);
}

}  // namespace
}  // namespace dyop::box2d::testing
