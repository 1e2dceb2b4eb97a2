// The sliders of the sliding scenes (`slide`, `tiles`): a frictionless box of two triangles, a
// frictionless L of six, a 16-sided rubber wheel, launched along +x on a ground whose top is
// y = `top`.
#include <cmath>

#include "scenes/builders.hpp"

namespace dyop::scenes::detail {
namespace {

constexpr float kLSquare = 0.25f;     // m: the L is three such squares, each split in two
constexpr float kWheelRadius = 0.4f;  // m, to its vertices
// Sides of the wheel: a polygon loses speed at each vertex it rolls over, 16 let it roll a few
// metres. At 1.8 m/s on 0.4 m, v²/r < g: it rolls without hopping.
constexpr int kWheelSides = 16;

// An L of three kLSquare squares (two along the ground, one on the left one), its corner at
// `corner`: six triangle fixtures.
b2Body* add_l(World& world, const b2Vec2& corner) {
  b2Body* body = add_body(world, b2_dynamicBody, corner);
  add_triangle_block(body, 0, 0, 2 * kLSquare, kLSquare, kLSquare, slider_ice);
  add_triangle_block(body, 0, kLSquare, kLSquare, 2 * kLSquare, kLSquare, slider_ice);
  return body;
}

// A regular polygon of kWheelSides triangles fanned from its centre, a side down on y = `top`.
b2Body* add_wheel(World& world, float x, float top) {
  constexpr double kPi = 3.14159265358979323846;
  const double half_angle = kPi / kWheelSides;
  b2Body* body =
      add_body(world, b2_dynamicBody, b2Vec2(x, top + float(kWheelRadius * std::cos(half_angle))));
  auto rim = [&](int i) {
    const double a = -kPi / 2 - half_angle + 2 * half_angle * i;
    return b2Vec2(float(kWheelRadius * std::cos(a)), float(kWheelRadius * std::sin(a)));
  };
  // rim(i + 1) modulo the sides: the last triangle shares the first one's edge bit for bit.
  for (int i = 0; i < kWheelSides; ++i) {
    add_triangle(body, b2Vec2(0, 0), rim(i), rim((i + 1) % kWheelSides), slider_rubber);
  }
  return body;
}

}  // namespace

Slider launch_slider(World& world, const std::string& body, const std::string& ground, float x,
                     float top, float speed, float lift) {
  top += lift;
  Slider s;
  s.speed = speed;
  s.figures.body = body;
  s.figures.ground = ground;
  s.figures.rolling = body == "wheel";
  if (body == "box") {
    s.body = add_split_box(world, b2Vec2(x, top + slider_box_half), slider_box_half, slider_ice);
  } else if (body == "L") {
    s.body = add_l(world, b2Vec2(x, top));
  } else {
    s.body = add_wheel(world, x, top);
    s.body->SetAngularVelocity(-speed / kWheelRadius);  // rolling along +x
  }
  s.body->SetLinearVelocity(b2Vec2(speed, 0));
  return s;
}

}  // namespace dyop::scenes::detail
