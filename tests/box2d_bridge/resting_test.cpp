// A triangle dropped on a ground of triangle fixtures, every contact triangle–triangle, under
// every backend and under Box2D's own contact.
#include <cstdint>
#include <iostream>
#include <vector>

#include "support/per_contact.hpp"
#include "support/worlds.hpp"

namespace dyop::box2d::testing {
namespace {

// Box2D's position solver stops correcting once the skins overlap by b2_linearSlop, and the
// velocity solver holds the body there (measured: 5.0002 mm under every contact). A tenth of the
// slop more is margin for rounding, far below the next failure mode (sinking by millimetres).
constexpr float kMaxSkinPenetration = 1.1f * b2_linearSlop;
// A body at rest with sleeping off must not move: a tenth of the slop over 10 s is drift.
constexpr float kMaxDrift = 0.1f * b2_linearSlop;
constexpr float kMaxTilt = 1e-3f;  // radians: the triangle lies flat on its base

// The ids of the body's touching contact points, contact by contact, in the world's order.
std::vector<std::uint32_t> contact_keys(b2Body* body) {
  std::vector<std::uint32_t> keys;
  for (b2ContactEdge* e = body->GetContactList(); e != nullptr; e = e->next) {
    if (!e->contact->IsTouching()) continue;
    const b2Manifold* m = e->contact->GetManifold();
    for (int i = 0; i < m->pointCount; ++i) keys.push_back(m->points[i].id.key);
  }
  return keys;
}

using Resting = PerContact;

TEST_P(Resting, TriangleOnTriangleGroundRestsWithinLinearSlopAndDoesNotDriftFor10s) {
  World world;
  add_triangle_ground(world, 5.0f);
  // The base spans the joint between two ground triangles (x = 0).
  b2Body* body = add_body(world, b2_dynamicBody, b2Vec2(0.3f, 1.5f));
  add_triangle(body, b2Vec2(-0.5f, 0.0f), b2Vec2(0.5f, 0.0f), b2Vec2(0.0f, 0.8f));

  for (int i = 0; i < 2 * kStepsPerSecond; ++i) world.step();  // fall and settle
  const b2Vec2 rest = body->GetPosition();
  const std::vector<std::uint32_t> resting_keys = contact_keys(body);
  float penetration = 0;
  float drift = 0;
  float tilt = 0;
  int key_changes = 0;
  for (int i = 0; i < 10 * kStepsPerSecond; ++i) {
    world.step();
    penetration = std::max(penetration, skin_penetration(body));
    drift = std::max(drift, (body->GetPosition() - rest).Length());
    tilt = std::max(tilt, std::abs(body->GetAngle()));
    key_changes += contact_keys(body) != resting_keys;
  }
  // The base's height above the ground top: the skins' sum less the overlap Box2D allows.
  const float height = body->GetWorldPoint(b2Vec2(0.0f, 0.0f)).y;
  std::cout << contact() << ": skin penetration " << penetration << " m, drift " << drift
            << " m, base height " << height << " m, tilt " << tilt << " rad\n";
  RecordProperty("skin_penetration", std::to_string(penetration));
  RecordProperty("drift", std::to_string(drift));
  EXPECT_LE(penetration, kMaxSkinPenetration);
  EXPECT_LE(drift, kMaxDrift);
  EXPECT_LE(tilt, kMaxTilt);
  EXPECT_GT(height, 0.0f) << "the triangles themselves overlap";
  EXPECT_GT(skin_penetration(body), 0.0f) << "not in contact";
  // Warm starting matches points by id.key: at rest the same features touch every step.
  EXPECT_FALSE(resting_keys.empty());
  EXPECT_EQ(key_changes, 0) << "steps whose contact keys differ from the resting ones";
}

INSTANTIATE_TEST_SUITE_P(EveryContact, Resting, ::testing::ValuesIn(kAllContacts),
                         contact_param_name);

}  // namespace
}  // namespace dyop::box2d::testing
