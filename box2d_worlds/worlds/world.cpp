#include "worlds/world.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "dyop/box2d.hpp"
#include "worlds/fnv1a.hpp"

namespace dyop::worlds {

World::World(const b2Vec2& gravity) : world_(gravity) { world_.SetAllowSleeping(false); }

World::~World() {
  while (b2Body* body = world_.GetBodyList()) world_.DestroyBody(body);
}

void World::step() { world_.Step(time_step, velocity_iterations, position_iterations); }

std::uint64_t state_hash(const std::vector<b2Body*>& bodies) {
  Fnv1a hash;
  for (const b2Body* b : bodies) {
    hash.add(b->GetPosition().x);
    hash.add(b->GetPosition().y);
    hash.add(b->GetAngle());
    hash.add(b->GetLinearVelocity().x);
    hash.add(b->GetLinearVelocity().y);
    hash.add(b->GetAngularVelocity());
  }
  return hash.value();
}

b2Body* World::create_body(const b2BodyDef& def) {
  b2Body* body = world_.CreateBody(&def);
  bodies_.push_back(body);
  return body;
}

b2Body* add_body(World& world, b2BodyType type, const b2Vec2& position, float angle) {
  b2BodyDef def;
  def.type = type;
  def.position = position;
  def.angle = angle;
  return world.create_body(def);
}

b2Fixture* add_triangle(b2Body* body, const b2Vec2& p0, const b2Vec2& p1, const b2Vec2& p2,
                        const Material& material) {
  const box2d::TriangleShape t = box2d::make_triangle(p0, p1, p2);
  if (!t.ok()) {
    throw std::invalid_argument("triangle (" + std::to_string(p0.x) + ", " + std::to_string(p0.y) +
                                "), (" + std::to_string(p1.x) + ", " + std::to_string(p1.y) +
                                "), (" + std::to_string(p2.x) + ", " + std::to_string(p2.y) +
                                "): " + t.message);
  }
  b2FixtureDef def;
  def.shape = &t.shape;
  def.density = material.density;
  def.friction = material.friction;
  return body->CreateFixture(&def);
}

void add_triangle_block(b2Body* body, float x0, float y0, float x1, float y1, float cell,
                        const Material& material) {
  const int nx = std::max(1, static_cast<int>(std::ceil((x1 - x0) / cell - 1e-4f)));
  const int ny = std::max(1, static_cast<int>(std::ceil((y1 - y0) / cell - 1e-4f)));
  const float wx = (x1 - x0) / nx;
  const float wy = (y1 - y0) / ny;
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      const float ax = x0 + i * wx;
      const float ay = y0 + j * wy;
      add_triangle(body, b2Vec2(ax, ay), b2Vec2(ax + wx, ay), b2Vec2(ax + wx, ay + wy), material);
      add_triangle(body, b2Vec2(ax, ay), b2Vec2(ax + wx, ay + wy), b2Vec2(ax, ay + wy), material);
    }
  }
}

b2Body* add_triangle_ground(World& world, float half_width) {
  b2Body* ground = add_body(world, b2_staticBody, b2Vec2(0.0f, 0.0f));
  add_triangle_block(ground, -half_width, -1.0f, half_width, 0.0f);
  return ground;
}

b2Body* add_triangle_bin(World& world, float half_width, float height) {
  b2Body* bin = add_triangle_ground(world, half_width + 1.0f);
  add_triangle_block(bin, -half_width - 1.0f, 0.0f, -half_width, height);
  add_triangle_block(bin, half_width, 0.0f, half_width + 1.0f, height);
  return bin;
}

b2Body* add_split_box(World& world, const b2Vec2& center, float half, const Material& material) {
  b2Body* body = add_body(world, b2_dynamicBody, center);
  add_triangle(body, b2Vec2(-half, -half), b2Vec2(half, -half), b2Vec2(half, half), material);
  add_triangle(body, b2Vec2(-half, -half), b2Vec2(half, half), b2Vec2(-half, half), material);
  return body;
}

b2Body* add_l_shape(World& world, const b2Vec2& position, float angle) {
  b2Body* body = add_body(world, b2_dynamicBody, position, angle);
  add_triangle(body, b2Vec2(0, 0), b2Vec2(2, 0), b2Vec2(2, 1));
  add_triangle(body, b2Vec2(0, 0), b2Vec2(2, 1), b2Vec2(1, 1));
  add_triangle(body, b2Vec2(0, 0), b2Vec2(1, 1), b2Vec2(0, 2));
  add_triangle(body, b2Vec2(1, 1), b2Vec2(1, 2), b2Vec2(0, 2));
  return body;
}

b2Body* add_u_shape(World& world, const b2Vec2& position, float angle) {
  b2Body* body = add_body(world, b2_dynamicBody, position, angle);
  add_triangle(body, b2Vec2(0, 0), b2Vec2(3, 0), b2Vec2(3, 1));
  add_triangle(body, b2Vec2(0, 0), b2Vec2(3, 1), b2Vec2(0, 1));
  add_triangle(body, b2Vec2(0, 1), b2Vec2(1, 1), b2Vec2(1, 2));
  add_triangle(body, b2Vec2(0, 1), b2Vec2(1, 2), b2Vec2(0, 2));
  add_triangle(body, b2Vec2(2, 1), b2Vec2(3, 1), b2Vec2(3, 2));
  add_triangle(body, b2Vec2(2, 1), b2Vec2(3, 2), b2Vec2(2, 2));
  return body;
}

b2Body* add_star(World& world, const b2Vec2& position, float angle, float outer, float inner) {
  constexpr int kPoints = 5;
  constexpr float kPi = 3.14159265358979f;
  b2Body* body = add_body(world, b2_dynamicBody, position, angle);
  b2Vec2 rim[2 * kPoints];
  for (int i = 0; i < 2 * kPoints; ++i) {
    const float a = kPi / 2 + i * kPi / kPoints;  // first tip straight up
    const float r = i % 2 == 0 ? outer : inner;
    rim[i].Set(r * std::cos(a), r * std::sin(a));
  }
  for (int i = 0; i < 2 * kPoints; ++i) {
    add_triangle(body, b2Vec2(0, 0), rim[i], rim[(i + 1) % (2 * kPoints)]);
  }
  return body;
}

bool is_triangle(const b2Fixture* fixture) {
  return fixture->GetType() == b2Shape::e_polygon &&
         static_cast<const b2PolygonShape*>(fixture->GetShape())->m_count == 3;
}

}  // namespace dyop::worlds
