#pragma once
// The everyday bodies of a game as frictionless gliders — a box of two triangle fixtures, a
// `SetAsBox` box, a hexagon and a ball — where they start, and the bounds of a glide without ghost
// collisions: for the tests of grounds made of chains, edges, tile maps, outlines and terrains.

#include <gtest/gtest.h>

#include <box2d/box2d.h>

#include <cmath>
#include <string>

#include "support/worlds.hpp"

namespace dyop::box2d::testing {

inline constexpr float kLevelPushSpeed = 4.0f;  // m/s, frictionless
inline constexpr float kLevelGlideSeconds = 4.0f;
// The bounds of a glide: the largest speed normal to the ground once settled (m/s), and the share
// of the frictionless travel a body makes.
inline constexpr float kLevelGlideVertical = 0.01f;
inline constexpr float kLevelGlideTravel = 0.99f;

enum class LevelBody { TriangleBox, Box, Hexagon, Ball };

inline const char* name(LevelBody b) {
  switch (b) {
    case LevelBody::TriangleBox:
      return "box of two triangles";
    case LevelBody::Box:
      return "SetAsBox box";
    case LevelBody::Hexagon:
      return "hexagon";
    case LevelBody::Ball:
      return "ball";
  }
  return "";
}

// A glider's dimensions (metres): the boxes' width and height, the hexagon's circumradius (a face
// at the bottom), the ball's radius.
struct GliderSize {
  float width = 0.8f;
  float height = 0.6f;
  float hexagon = 0.35f;
  float ball = 0.3f;
};

// A frictionless body of `size` resting on y = 0 at x = 0 (hanging from it when not `up`), pushed
// along +x at `kLevelPushSpeed`: its body origin is the middle of its flat bottom (the point a ball
// touches the ground at).
inline b2Body* add_level_glider(World& world, LevelBody kind, bool up = true,
                                const GliderSize& size = {}) {
  const float side = up ? 1.0f : -1.0f;
  const float w = 0.5f * size.width, h = size.height, r = size.hexagon;
  b2Body* body = add_body(world, b2_dynamicBody, b2Vec2(0, 0));
  b2FixtureDef def;
  def.friction = 0;
  def.density = 1;
  b2PolygonShape polygon;
  b2CircleShape ball;
  switch (kind) {
    case LevelBody::TriangleBox:
      add_triangle(body, b2Vec2(-w, 0), b2Vec2(w, 0), b2Vec2(w, side * h), kIce);
      add_triangle(body, b2Vec2(-w, 0), b2Vec2(w, side * h), b2Vec2(-w, side * h), kIce);
      break;
    case LevelBody::Box:
      polygon.SetAsBox(w, 0.5f * h, b2Vec2(0, side * 0.5f * h), 0);
      def.shape = &polygon;
      break;
    case LevelBody::Hexagon: {
      b2Vec2 points[6];
      for (int i = 0; i < 6; ++i) {
        const float a = 3.14159265f / 3 * i;
        points[i] = b2Vec2(r * std::cos(a), side * (r * std::sin(a) + r * 0.8660254f));
      }
      polygon.Set(points, 6);
      def.shape = &polygon;
      break;
    }
    case LevelBody::Ball:
      ball.m_radius = size.ball;
      ball.m_p = b2Vec2(0, side * size.ball);
      def.shape = &ball;
      break;
  }
  if (def.shape) body->CreateFixture(&def);
  body->SetLinearVelocity(b2Vec2(kLevelPushSpeed, 0));
  return body;
}

// Where a glider starts (metres): its offset along the ground from a vertex, and the height of its
// lowest point above the ground's line: inside the two skins (0.02 m), where Box2D's position
// solver lifts it out over its first steps. Box2D's own contact trips on a chain from some of them
// and not from others (its smoothing admits the slight tilt the lift leaves).
inline constexpr float kLaunchOffsets[][2] = {{0.0f, 0.0f},   {0.07f, 0.0f},   {0.13f, 0.0f},
                                              {0.0f, 0.005f}, {0.13f, 0.005f}, {0.3f, 0.005f}};
// Steps after which a launched body has settled on the ground (0.25 s): its vertical speed counts
// from then on.
inline constexpr int kSettleSteps = 15;

inline std::string level_body_name(const ::testing::TestParamInfo<LevelBody>& info) {
  static const char* bodies[] = {"TriangleBox", "Box", "Hexagon", "Ball"};
  return bodies[static_cast<int>(info.param)];
}

}  // namespace dyop::box2d::testing
