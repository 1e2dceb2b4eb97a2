// `slide`: bodies launched along flat grounds of triangle fixtures, one lane each: frictionless
// boxes and L bodies that should glide level, polygon wheels that roll, and a box at rest across a
// junction of two cells. Triangulated grounds have internal edges, on which Box2D's own contact
// trips (ghost collisions); one-piece grounds show what a glide is.
#include <cmath>
#include <iterator>
#include <string>

#include "scenes/builders.hpp"

namespace dyop::scenes::detail {
namespace {

enum class Cells { OnePiece, Diagonal, Fan };

struct Lane {
  const char* body;  // "box", "L", "wheel", or nullptr: the resting box
  Cells cells;
  float cell;   // m, side of the square cells (one-piece: unused)
  float speed;  // m/s along +x
};

// One slider per lane: the box on the one-piece ground (what a glide is), on 1 m and 0.25 m
// diagonal cells and on 0.25 m fans; the L on the 0.25 m grounds; the wheel on the one-piece
// ground (how far a polygon rolls) and on 0.25 m diagonal cells; last the resting box.
constexpr Lane kLanes[] = {
    {"box", Cells::OnePiece, 0, 6},      {"box", Cells::Diagonal, 1, 6},
    {"box", Cells::Diagonal, 0.25f, 6},  {"box", Cells::Fan, 0.25f, 6},
    {"L", Cells::Diagonal, 0.25f, 6},    {"L", Cells::Fan, 0.25f, 6},
    {"wheel", Cells::OnePiece, 0, 1.8f}, {"wheel", Cells::Diagonal, 0.25f, 1.8f},
    {nullptr, Cells::Diagonal, 1, 0},
};

// m between the tops of two lanes: a 1 m-cell ground is 2 m deep, and a slider that hops stays
// well below the lane above.
constexpr float kLaneGap = 4.0f;
// Every lane's ground runs from kStart to kStart + kLength: 6 s at 6 m/s (the full run) from x = 0.
constexpr float kStart = -2.0f;
constexpr float kLength = 40.0f;
constexpr float kBoxHalf = 0.25f;    // m: the 0.5 m box
constexpr float kLSquare = 0.25f;    // m: the L is three such squares, each split in two
constexpr float kWheelRadius = 0.4f;  // m, to its vertices
// Sides of the wheel: a polygon loses speed at each vertex it rolls over, 16 let it roll a few
// metres. At 1.8 m/s on 0.4 m, v²/r < g: it rolls without hopping.
constexpr int kWheelSides = 16;
constexpr double kJitter = 0.001;  // m, launch position noise from the seed
const Material kIce{1.0f, 0.0f};
const Material kRubber{};  // friction 0.6, as every other scene

const char* ground_name(const Lane& lane) {
  switch (lane.cells) {
    case Cells::OnePiece: return "one-piece";
    case Cells::Diagonal: return lane.cell == 1 ? "diagonal-1m" : "diagonal-0.25m";
    default: return "fan-0.25m";
  }
}

// A static ground whose top is y = `top` over [kStart, kStart + kLength], two cells deep.
void add_ground(World& world, const Lane& lane, float top, const Material& material) {
  b2Body* ground = add_body(world, b2_staticBody, b2Vec2(0, top));
  const float x1 = kStart + kLength;
  switch (lane.cells) {
    case Cells::OnePiece: add_triangle_block(ground, kStart, -1, x1, 0, kLength, material); return;
    case Cells::Diagonal:
      add_triangle_block(ground, kStart, -2 * lane.cell, x1, 0, lane.cell, material);
      return;
    case Cells::Fan: break;
  }
  const int columns = static_cast<int>(std::lround(kLength / lane.cell));
  for (int row = 0; row < 2; ++row) {
    for (int i = 0; i < columns; ++i) {
      const b2Vec2 bl(kStart + i * lane.cell, -(row + 1) * lane.cell);
      const b2Vec2 tr(bl.x + lane.cell, bl.y + lane.cell);
      const b2Vec2 br(tr.x, bl.y), tl(bl.x, tr.y), c = 0.5f * (bl + tr);
      add_triangle(ground, tl, bl, c, material);
      add_triangle(ground, bl, br, c, material);
      add_triangle(ground, br, tr, c, material);
      add_triangle(ground, tr, tl, c, material);
    }
  }
}

// An L of three kLSquare squares (two along the ground, one on the left one), its corner at
// `corner`: six triangle fixtures.
b2Body* add_l(World& world, const b2Vec2& corner) {
  b2Body* body = add_body(world, b2_dynamicBody, corner);
  add_triangle_block(body, 0, 0, 2 * kLSquare, kLSquare, kLSquare, kIce);
  add_triangle_block(body, 0, kLSquare, kLSquare, 2 * kLSquare, kLSquare, kIce);
  return body;
}

// A regular polygon of kWheelSides triangles fanned from its centre, a side down on y = `top`.
b2Body* add_wheel(World& world, float x, float top) {
  constexpr double kPi = 3.14159265358979323846;
  const double half_angle = kPi / kWheelSides;
  b2Body* body = add_body(world, b2_dynamicBody,
                          b2Vec2(x, top + float(kWheelRadius * std::cos(half_angle))));
  auto rim = [&](int i) {
    const double a = -kPi / 2 - half_angle + 2 * half_angle * i;
    return b2Vec2(float(kWheelRadius * std::cos(a)), float(kWheelRadius * std::sin(a)));
  };
  // rim(i + 1) modulo the sides: the last triangle shares the first one's edge bit for bit.
  for (int i = 0; i < kWheelSides; ++i) {
    add_triangle(body, b2Vec2(0, 0), rim(i), rim((i + 1) % kWheelSides), kRubber);
  }
  return body;
}

}  // namespace

WorldBuild build_slide(World& world, workloads::Random& rng) {
  WorldBuild build;
  for (std::size_t i = 0; i < std::size(kLanes); ++i) {
    const Lane& lane = kLanes[i];
    const float top = -kLaneGap * static_cast<float>(i);
    const bool ice = lane.body != nullptr && std::string(lane.body) != "wheel";
    add_ground(world, lane, top, ice ? kIce : kRubber);
    // Cores touching: Box2D's skins overlap by 2 cm and the position solver parts them without
    // any velocity, so a glide starts level.
    const float x = jitter(rng, kJitter);
    if (lane.body == nullptr) {  // at rest, its middle on the junction of two cells at x = 0
      build.watched.push_back(add_split_box(world, b2Vec2(x, top + kBoxHalf), kBoxHalf, kRubber));
      continue;
    }
    Slider s;
    s.speed = lane.speed;
    s.figures.body = lane.body;
    s.figures.ground = ground_name(lane);
    s.figures.rolling = !ice;
    if (s.figures.body == "box") {
      s.body = add_split_box(world, b2Vec2(x, top + kBoxHalf), kBoxHalf, kIce);
    } else if (s.figures.body == "L") {
      s.body = add_l(world, b2Vec2(x, top));
    } else {
      s.body = add_wheel(world, x, top);
      s.body->SetAngularVelocity(-lane.speed / kWheelRadius);  // rolling along +x
    }
    s.body->SetLinearVelocity(b2Vec2(lane.speed, 0));
    build.sliders.push_back(std::move(s));
  }
  return build;
}

}  // namespace dyop::scenes::detail
