// `tumbler`: a kinematic square drum of triangle-fixture walls turning at 0.3 rad/s, holding 300
// triangles: contacts are made and broken all the time.
#include <cmath>

#include "scenes/builders.hpp"

namespace dyop::scenes::detail {

WorldBuild build_tumbler(World& world, workloads::Random& rng) {
  constexpr float kInner = 6.0f;  // half the inside width
  constexpr float kWall = 0.5f;
  constexpr float kSpin = 0.3f;  // rad/s: a turn every 21 s
  const b2Vec2 centre(0.0f, 10.0f);
  b2Body* drum = add_body(world, b2_kinematicBody, centre);
  const float o = kInner + kWall;
  add_triangle_block(drum, -o, -o, o, -kInner);            // bottom
  add_triangle_block(drum, -o, kInner, o, o);              // top
  add_triangle_block(drum, -o, -kInner, -kInner, kInner);  // left
  add_triangle_block(drum, kInner, -kInner, o, kInner);    // right
  drum->SetAngularVelocity(kSpin);

  // 300 triangles on a 20 × 15 grid of 0.55 m cells inside (radius at most 0.26 m: no overlap).
  constexpr int kColumns = 20;
  constexpr int kRows = 15;
  constexpr float kCell = 0.55f;
  for (int r = 0; r < kRows; ++r) {
    for (int c = 0; c < kColumns; ++c) {
      const b2Vec2 p((c - 0.5f * (kColumns - 1)) * kCell, (r - 0.5f * (kRows - 1)) * kCell - 1.0f);
      const double radius = 0.1 * std::pow(2.6, rng.unit());  // 0.1 to 0.26 m
      add_random_triangle(world, rng, centre + p, radius);
    }
  }
  return {};
}

}  // namespace dyop::scenes::detail
