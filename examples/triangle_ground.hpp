// What the examples share for building with triangles: a triangle fixture through
// `make_triangle` (which names what is wrong where Box2D 2.4 would assert), and a flat ground of
// square cells split into two triangles each, fixture by fixture, as game code makes one.
#pragma once

#include <box2d/box2d.h>

#include <cstdio>
#include <stdexcept>

#include <dyop/box2d.hpp>

namespace example {

// A triangle fixture of `density` on `body` (body frame, any winding); throws with
// `make_triangle`'s message when the points cannot make a Box2D triangle.
inline b2Fixture* add_triangle(b2Body* body, b2Vec2 a, b2Vec2 b, b2Vec2 c, float density = 0) {
  const dyop::box2d::TriangleShape t = dyop::box2d::make_triangle(a, b, c);
  if (!t.ok()) throw std::invalid_argument(t.message);
  return body->CreateFixture(&t.shape, density);
}

// Cells of `cell` metres from x0 to x1, one cell deep, their tops at y = 0, on `body`.
inline void add_triangle_ground(b2Body* body, float x0, float x1, float cell) {
  for (float x = x0; x < x1 - 0.5f * cell; x += cell) {
    add_triangle(body, {x, -cell}, {x + cell, -cell}, {x + cell, 0});
    add_triangle(body, {x, -cell}, {x + cell, 0}, {x, 0});
  }
}

}  // namespace example
