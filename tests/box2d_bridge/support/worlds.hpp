#pragma once
// The bridge tests' worlds: real b2Worlds built from triangle fixtures (box2d_worlds/), named in
// the tests' namespace, and what the tests check of a world's bodies: their state finite, how
// deep a body's skin sinks into what it touches.

#include <box2d/box2d.h>

#include <algorithm>
#include <cmath>

#include "worlds/world.hpp"

namespace dyop::box2d::testing {

using worlds::add_body;
using worlds::add_split_box;
using worlds::add_triangle;
using worlds::add_triangle_ground;
using worlds::World;
constexpr int kStepsPerSecond = worlds::steps_per_second;

// A frictionless material of unit density: bodies glide on it.
inline const worlds::Material kIce{1.0f, 0.0f};
// Half the side of the 1 m boxes the stacking tests build (metres).
constexpr float kBoxHalf = 0.5f;

// A `SetAsBox` fixture of half sizes `hx`, `hy` about `center` (body frame) on `body`; a sensor
// when `sensor`.
inline b2Fixture* add_box(b2Body* body, float hx, float hy, const worlds::Material& material,
                          const b2Vec2& center = b2Vec2(0, 0), bool sensor = false) {
  b2PolygonShape box;
  box.SetAsBox(hx, hy, center, 0);
  b2FixtureDef def;
  def.shape = &box;
  def.density = material.density;
  def.friction = material.friction;
  def.isSensor = sensor;
  return body->CreateFixture(&def);
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
    for (int i = 0; i < c->GetManifold()->pointCount; ++i)
      deepest = std::max(deepest, -wm.separations[i]);
  }
  return deepest;
}

// True when every body's position, angle and velocities are finite.
inline bool finite_state(World& world) {
  for (b2Body* b = world->GetBodyList(); b != nullptr; b = b->GetNext()) {
    const b2Vec2 p = b->GetPosition();
    const b2Vec2 v = b->GetLinearVelocity();
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(b->GetAngle()) ||
        !std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(b->GetAngularVelocity())) {
      return false;
    }
  }
  return true;
}

}  // namespace dyop::box2d::testing
