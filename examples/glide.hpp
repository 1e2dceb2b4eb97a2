// What the examples share: the bodies a game pushes along its levels (a crate, a ball, a box made
// of two triangle fixtures), and a watch that tells a glide from a ghost collision. A body
// glides when, pushed at speed over flat ground without friction, it never gains more than
// 0.05 m/s of vertical speed and travels at least 98 % of the way (the project's tests' bounds).
#pragma once

#include <box2d/box2d.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include <dyop/box2d.hpp>

namespace example {

enum class Shape { Crate, Ball, TriangleBox };

inline const char* name(Shape s) {
  return s == Shape::Crate ? "crate (SetAsBox)" : s == Shape::Ball ? "ball" : "box of 2 triangles";
}

// A frictionless crate of unit density: a `SetAsBox` of half side `half` centred at `center`,
// launched at `velocity`.
inline b2Body* add_crate(b2World& world, b2Vec2 center, float half, b2Vec2 velocity) {
  b2BodyDef def;
  def.type = b2_dynamicBody;
  def.position = center;
  b2Body* body = world.CreateBody(&def);
  b2PolygonShape box;
  box.SetAsBox(half, half);
  b2FixtureDef fixture;
  fixture.shape = &box;
  fixture.density = 1;
  fixture.friction = 0;
  body->CreateFixture(&fixture);
  body->SetLinearVelocity(velocity);
  return body;
}

// A frictionless body of `shape`, 0.6 m across, the bottom of its core at `bottom` (resting in
// the ground's skin, as bodies rest), pushed along x at `speed` m/s. Pushed bodies pass through
// each other (one negative collision group).
inline b2Body* add_pushed(b2World& world, Shape shape, b2Vec2 bottom, float speed) {
  constexpr float half = 0.3f;
  b2BodyDef def;
  def.type = b2_dynamicBody;
  def.position = bottom + b2Vec2(0, half);
  b2Body* body = world.CreateBody(&def);
  b2FixtureDef fixture;
  fixture.density = 1;
  fixture.friction = 0;
  fixture.filter.groupIndex = -1;
  b2PolygonShape crate;
  crate.SetAsBox(half, half);
  b2CircleShape ball;
  ball.m_radius = half;
  const b2Vec2 c[4] = {{-half, -half}, {half, -half}, {half, half}, {-half, half}};
  const dyop::box2d::TriangleShape lower = dyop::box2d::make_triangle(c[0], c[1], c[2]);
  const dyop::box2d::TriangleShape upper = dyop::box2d::make_triangle(c[0], c[2], c[3]);
  if (shape == Shape::TriangleBox) {
    fixture.shape = &lower.shape;
    body->CreateFixture(&fixture);
    fixture.shape = &upper.shape;
  } else {
    fixture.shape = shape == Shape::Crate ? static_cast<const b2Shape*>(&crate) : &ball;
  }
  body->CreateFixture(&fixture);
  body->SetLinearVelocity(b2Vec2(speed, 0));
  return body;
}

// One pushed body under watch.
struct Pushed {
  Shape shape;
  b2Body* body;
  float speed;            // m/s, as launched
  float start_x = 0;      // where it was launched
  float vertical = 0;     // largest vertical speed seen (m/s)
  float travelled = 0;    // metres along x
  float free_travel = 0;  // speed × time: how far a glide goes
  bool glided() const { return vertical <= 0.05f && travelled >= 0.98f * free_travel; }
};

// Box2D's own profile of the steps, summed (milliseconds).
struct Timing {
  float collide = 0;  // the narrow phase (`b2Profile::collide`)
  float step = 0;     // the whole step
};

// Steps `world` for `seconds` at 60 Hz (Box2D's testbed iterations) and watches `bodies`.
inline Timing step_and_watch(b2World& world, std::vector<Pushed>& bodies, float seconds) {
  Timing timing;
  for (Pushed& p : bodies) p.start_x = p.body->GetPosition().x;
  const int steps = static_cast<int>(std::lround(seconds * 60));
  for (int i = 0; i < steps; ++i) {
    world.Step(1.0f / 60, 8, 3);
    timing.collide += world.GetProfile().collide;
    timing.step += world.GetProfile().step;
    for (Pushed& p : bodies) {
      p.vertical = std::fmax(p.vertical, std::fabs(p.body->GetLinearVelocity().y));
    }
  }
  for (Pushed& p : bodies) {
    p.travelled = p.body->GetPosition().x - p.start_x;
    p.free_travel = p.speed * seconds;
  }
  return timing;
}

// Prints one line per body under `title`; true when every body glided.
inline bool report(const char* title, const std::vector<Pushed>& bodies) {
  bool all = true;
  std::printf("%s\n", title);
  for (const Pushed& p : bodies) {
    std::printf("  %-20s largest vertical speed %.3f m/s, travelled %5.2f m of %5.2f: %s\n",
                name(p.shape), p.vertical, p.travelled, p.free_travel,
                p.glided() ? "glides" : "trips");
    all = all && p.glided();
  }
  return all;
}

// The three shapes, pushed from `bottom` at `speed`.
inline std::vector<Pushed> push_all(b2World& world, b2Vec2 bottom, float speed) {
  std::vector<Pushed> out;
  for (Shape s : {Shape::Crate, Shape::Ball, Shape::TriangleBox}) {
    out.push_back({s, add_pushed(world, s, bottom, speed), speed});
  }
  return out;
}

}  // namespace example
