#include "experiments/everyday_bodies.hpp"

#include <box2d/box2d.h>

#include <cmath>

namespace dyop::experiments {

EverydayShapes::EverydayShapes() {
  box.SetAsBox(0.25f, 0.3f);
  b2Vec2 v[6];
  for (int i = 0; i < 6; ++i) {
    const float a = static_cast<float>(i) * b2_pi / 3;
    v[i] = {0.3f * std::cos(a), 0.3f * std::sin(a)};
  }
  hexagon.Set(v, 6);
  ball.m_radius = 0.3f;
}

std::vector<std::pair<const char*, const b2Shape*>> EverydayShapes::all() const {
  return {{"`SetAsBox` box", &box},
          {"hexagon", &hexagon},
          {"ball", &ball},
          {"box of 2 triangles", nullptr}};
}

b2Body* add_everyday_body(worlds::World& world, const b2Shape* shape, const b2Vec2& at,
                          float friction) {
  if (!shape) return worlds::add_split_box(world, at, 0.3f, worlds::Material{1, friction});
  b2Body* body = worlds::add_body(world, b2_dynamicBody, at);
  b2FixtureDef fixture;
  fixture.shape = shape;
  fixture.density = 1;
  fixture.friction = friction;
  body->CreateFixture(&fixture);
  return body;
}

float resting_height(const b2Shape* shape) {
  if (!shape) return 0.3f;
  b2AABB box;
  shape->ComputeAABB(&box, b2Transform(b2Vec2(0, 0), b2Rot(0)), 0);
  return -box.lowerBound.y;
}

}  // namespace dyop::experiments
