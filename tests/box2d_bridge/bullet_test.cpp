// A fast small triangle fired at a thin static triangle wall must not pass through: Box2D's
// time of impact stops it at the wall, and the contact it then evaluates must hold it there.
#include <iostream>
#include <string>

#include "support/per_contact.hpp"
#include "support/worlds.hpp"

namespace dyop::box2d::testing {
namespace {

// 100 m/s is 1.7 m per step, 28 times the wall's thickest part; Box2D caps a step's translation
// at b2_maxTranslation (2 m), so this is about as fast as a Box2D body goes.
constexpr float kBulletSpeed = 100.0f;
constexpr float kWallThickness = 0.06f;  // at its middle; thinner towards its ends

struct Shot {
  float height;  // where it hits the wall (the wall is kWallThickness·(1 − |y|/2) thick there)
  bool bullet;
};

struct Flight {
  float reach = -5.0f;  // the largest x the projectile's vertices reach (m)
  bool finite = true;   // every body's state finite after every step (`finite_state`)
};

// The projectile's flight for 1 s after being fired from x = −5. (std::max keeps its first
// argument against a NaN: the reach alone cannot tell a world that went NaN.)
Flight fire(const Shot& shot) {
  World world(b2Vec2(0.0f, 0.0f));
  b2Body* wall = add_body(world, b2_staticBody, b2Vec2(0.0f, 0.0f));
  add_triangle(wall, b2Vec2(0.0f, -2.0f), b2Vec2(kWallThickness, 0.0f), b2Vec2(0.0f, 2.0f));
  b2Body* projectile = add_body(world, b2_dynamicBody, b2Vec2(-5.0f, shot.height));
  projectile->SetBullet(shot.bullet);
  const b2Fixture* f =
      add_triangle(projectile, b2Vec2(-0.05f, -0.04f), b2Vec2(0.05f, 0.0f), b2Vec2(-0.05f, 0.04f));
  projectile->SetLinearVelocity(b2Vec2(kBulletSpeed, 0.0f));
  const auto* shape = static_cast<const b2PolygonShape*>(f->GetShape());
  Flight flight;
  for (int i = 0; i < kStepsPerSecond; ++i) {
    world.step();
    flight.finite = flight.finite && finite_state(world);
    for (int k = 0; k < shape->m_count; ++k) {
      flight.reach = std::max(flight.reach, projectile->GetWorldPoint(shape->m_vertices[k]).x);
    }
  }
  return flight;
}

// Prints and records where a shot ended.
void record(const std::string& contact, const Shot& shot, float reach) {
  std::cout << contact << (shot.bullet ? " bullet" : " non-bullet") << " at y = " << shot.height
            << ": reached x = " << reach << " m\n";
  ::testing::Test::RecordProperty(std::string(shot.bullet ? "bullet" : "non_bullet") + "_y" +
                                      std::to_string(int(shot.height * 10)),
                                  std::to_string(reach));
}

using Bullet = PerContact;

TEST_P(Bullet, FastSmallTriangleDoesNotPassThroughThinStaticTriangleWall) {
  for (const Shot shot :
       {Shot{0.0f, false}, Shot{0.0f, true}, Shot{1.5f, false}, Shot{1.5f, true}}) {
    const float reach = fire(shot).reach;
    record(contact(), shot, reach);
    // The wall's face is x = 0; the skins stop the tip about 1.5 cm short of it.
    EXPECT_LT(reach, 0.0f) << (shot.bullet ? "bullet" : "non-bullet") << " at y = " << shot.height;
  }
}

INSTANTIATE_TEST_SUITE_P(ContactsButDyopFast, Bullet, ::testing::ValuesIn(kContactsButDyopFast),
                         contact_param_name);

// dyop-fast does not hold the wall: at the time of impact (5 mm apart) its pivot picks a slanted
// face of the wall, which is not a separating axis, so it reports no speculative point and the
// contact appears only once the tip is inside. Measured: at y = 0 (the wall 6 cm thick) the tip
// stops 5 cm deep; at y = 1.5 (2.25 cm thick) the projectile passes through, bullet or not.
// Asserted: what it achieves where the wall is thickest (the tip does not come out behind it),
// and a finite world everywhere.
using BulletUnderDyopFast = PerContact;

TEST_P(BulletUnderDyopFast, FastSmallTriangleStaysFiniteAndStopsInsideTheWallWhereItIsThickest) {
  for (const Shot shot :
       {Shot{0.0f, false}, Shot{0.0f, true}, Shot{1.5f, false}, Shot{1.5f, true}}) {
    const Flight flight = fire(shot);
    record(contact(), shot, flight.reach);
    EXPECT_TRUE(flight.finite) << (shot.bullet ? "bullet" : "non-bullet")
                               << " at y = " << shot.height;
    if (shot.height == 0.0f) {
      EXPECT_LT(flight.reach, kWallThickness)
          << (shot.bullet ? "bullet" : "non-bullet") << " at y = 0";
    }
  }
}

INSTANTIATE_TEST_SUITE_P(DyopFast, BulletUnderDyopFast, ::testing::ValuesIn(kDyopFastOnly),
                         contact_param_name);

}  // namespace
}  // namespace dyop::box2d::testing
