#pragma once
// Shared by the bridge tests: real b2Worlds built from triangle fixtures, and the per-backend
// installation every physics test runs under.

#include <box2d/box2d.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "dyop/box2d.hpp"

namespace dyop::box2d::testing {

// Box2D's testbed settings: 60 Hz, 8 velocity and 3 position iterations.
constexpr float kTimeStep = 1.0f / 60.0f;
constexpr int kVelocityIterations = 8;
constexpr int kPositionIterations = 3;
constexpr int kStepsPerSecond = 60;

// A world that destroys its bodies before itself: b2World's destructor frees contacts without
// destroying them, which would leave the plug-in's contacts counted and block `uninstall`.
// Sleeping is off: a sleeping body cannot drift or jitter, and the tests measure both.
class World {
 public:
  explicit World(const b2Vec2& gravity = b2Vec2(0.0f, -10.0f)) : world_(gravity) {
    world_.SetAllowSleeping(false);
  }
  World(const World&) = delete;
  World& operator=(const World&) = delete;
  ~World() {
    while (b2Body* body = world_.GetBodyList()) world_.DestroyBody(body);
  }

  b2World* operator->() { return &world_; }
  b2World& get() { return world_; }

  void step() { world_.Step(kTimeStep, kVelocityIterations, kPositionIterations); }

 private:
  b2World world_;
};

// A triangle fixture from body-frame points, validated by the plug-in.
inline b2Fixture* add_triangle(b2Body* body, const b2Vec2& p0, const b2Vec2& p1, const b2Vec2& p2,
                               float density = 1.0f, float friction = 0.6f) {
  const TriangleShape t = make_triangle(p0, p1, p2);
  EXPECT_TRUE(t.ok()) << t.message;
  b2FixtureDef def;
  def.shape = &t.shape;
  def.density = density;
  def.friction = friction;
  return body->CreateFixture(&def);
}

inline b2Body* add_body(World& world, b2BodyType type, const b2Vec2& position, float angle = 0) {
  b2BodyDef def;
  def.type = type;
  def.position = position;
  def.angle = angle;
  return world->CreateBody(&def);
}

// A static ground whose top is y = 0 over [-half_width, half_width], made of unit squares split
// along a diagonal into two triangle fixtures each: every contact with it is triangle–triangle.
inline b2Body* add_triangle_ground(World& world, float half_width) {
  b2Body* ground = add_body(world, b2_staticBody, b2Vec2(0.0f, 0.0f));
  for (float x = -half_width; x < half_width; x += 1.0f) {
    add_triangle(ground, b2Vec2(x, -1.0f), b2Vec2(x + 1.0f, -1.0f), b2Vec2(x + 1.0f, 0.0f));
    add_triangle(ground, b2Vec2(x, -1.0f), b2Vec2(x + 1.0f, 0.0f), b2Vec2(x, 0.0f));
  }
  return ground;
}

// A dynamic square of side 2·half made of two triangle fixtures split along its diagonal.
inline b2Body* add_split_box(World& world, const b2Vec2& center, float half) {
  b2Body* body = add_body(world, b2_dynamicBody, center);
  add_triangle(body, b2Vec2(-half, -half), b2Vec2(half, -half), b2Vec2(half, half));
  add_triangle(body, b2Vec2(-half, -half), b2Vec2(half, half), b2Vec2(-half, half));
  return body;
}

// Deepest overlap of the skins over the body's touching contacts (metres, 0 when none overlap):
// minus the least world-manifold separation, which Box2D measures between the skins. Box2D's
// position solver lets skins overlap by about b2_linearSlop at rest, by design.
inline float skin_penetration(b2Body* body) {
  float deepest = 0;
  for (b2ContactEdge* e = body->GetContactList(); e != nullptr; e = e->next) {
    const b2Contact* c = e->contact;
    if (!c->IsTouching()) continue;
    b2WorldManifold wm;
    c->GetWorldManifold(&wm);
    for (int i = 0; i < c->GetManifold()->pointCount; ++i) deepest = std::max(deepest, -wm.separations[i]);
  }
  return deepest;
}

// Every backend, plus nothing: Box2D's own b2PolygonContact (the plug-in not installed).
using Contact = std::optional<Backend>;

inline std::string contact_name(const Contact& c) {
  if (!c) return "box2d_own";
  std::string n = name(*c);
  std::replace(n.begin(), n.end(), '-', '_');
  return "via_plugin_" + n;
}

inline const Contact kAllContacts[] = {std::nullopt,     Backend::Dyop, Backend::DyopFast,
                                      Backend::LinCanny, Backend::Sat,  Backend::Epa,
                                      Backend::Box2D};

// A test run with one contact: installs the backend before the world exists, checks afterwards
// that every triangle pair was answered by it (no fallback to Box2D), and uninstalls.
class PerContact : public ::testing::TestWithParam<Contact> {
 protected:
  void SetUp() override {
    if (GetParam()) {
      const InstallResult r = install(*GetParam());
      ASSERT_TRUE(r.ok()) << r.message;
    }
  }
  void TearDown() override {
    if (GetParam()) {
      const Stats s = stats();
      EXPECT_EQ(s.fallbacks, 0u) << "pairs answered by Box2D instead of " << name(*GetParam());
      const InstallResult r = uninstall();
      EXPECT_TRUE(r.ok()) << r.message;
    }
  }
  std::string contact() const { return contact_name(GetParam()); }
};

inline std::string contact_param_name(const ::testing::TestParamInfo<Contact>& info) {
  return contact_name(info.param);
}

}  // namespace dyop::box2d::testing
