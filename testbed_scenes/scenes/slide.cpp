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
constexpr double kSlideJitter = 0.001;  // m, launch position noise from the seed

const char* ground_name(const Lane& lane) {
  switch (lane.cells) {
    case Cells::OnePiece:
      return "one-piece";
    case Cells::Diagonal:
      return lane.cell == 1 ? "diagonal-1m" : "diagonal-0.25m";
    default:
      return "fan-0.25m";
  }
}

// A static ground whose top is y = `top` over [kStart, kStart + kLength], two cells deep.
void add_ground(World& world, const Lane& lane, float top, const Material& material) {
  b2Body* ground = add_body(world, b2_staticBody, b2Vec2(0, top));
  const float x1 = kStart + kLength;
  switch (lane.cells) {
    case Cells::OnePiece:
      add_triangle_block(ground, kStart, -1, x1, 0, kLength, material);
      return;
    case Cells::Diagonal:
      add_triangle_block(ground, kStart, -2 * lane.cell, x1, 0, lane.cell, material);
      return;
    case Cells::Fan:
      break;
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

}  // namespace

WorldBuild build_slide(World& world, workloads::Random& rng) {
  WorldBuild build;
  for (std::size_t i = 0; i < std::size(kLanes); ++i) {
    const Lane& lane = kLanes[i];
    const float top = -kLaneGap * static_cast<float>(i);
    const bool ice = lane.body != nullptr && std::string(lane.body) != "wheel";
    add_ground(world, lane, top, ice ? slider_ice : slider_rubber);
    const float x = jitter(rng, kSlideJitter);
    if (lane.body == nullptr) {  // at rest, its middle on the junction of two cells at x = 0
      build.watched.push_back(
          add_split_box(world, b2Vec2(x, top + slider_box_half), slider_box_half, slider_rubber));
      continue;
    }
    build.sliders.push_back(launch_slider(world, lane.body, ground_name(lane), x, top, lane.speed));
  }
  return build;
}

}  // namespace dyop::scenes::detail
