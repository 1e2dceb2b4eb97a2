// `stack`: three vertical stacks of 10 two-triangle boxes. `stack-concave`: L, U and star bodies
// (triangulated into fixtures) dropped into a bin of triangle fixtures.
#include "scenes/builders.hpp"

namespace dyop::scenes::detail {

WorldBuild build_stack(World& world, workloads::Random& rng) {
  constexpr int kStacks = 3;
  constexpr int kBoxes = 10;
  constexpr float kHalf = 0.5f;
  constexpr float kSpacing = 3.0f;  // m between stacks: they never meet
  // m, horizontal placement noise from the seed. Why so small: a 10-box stack of Box2D 2.4 is
  // that sensitive; 1 mm offsets already make Box2D's own stacks lean by 10 cm in 10 s.
  constexpr double kJitter = 0.0001;
  add_triangle_ground(world, 6.0f);
  const float pitch = 2 * kHalf + b2_polygonRadius;  // cores 1 cm apart: nothing starts overlapping
  WorldBuild build;
  for (int s = 0; s < kStacks; ++s) {
    b2Body* box = nullptr;
    for (int i = 0; i < kBoxes; ++i) {
      const float x = (s - 0.5f * (kStacks - 1)) * kSpacing + jitter(rng, kJitter);
      box = add_split_box(world, b2Vec2(x, kHalf + b2_polygonRadius + i * pitch), kHalf);
    }
    build.watched.push_back(box);
  }
  return build;
}

WorldBuild build_stack_concave(World& world, workloads::Random& rng) {
  // 24 bodies on a 4 × 6 grid of 3.8 m cells, each centred in its cell at a random angle: the
  // widest (the U) reaches 1.8 m from its centre, so no two start overlapping.
  constexpr int kColumns = 4;
  constexpr int kRows = 6;
  constexpr float kCell = 3.8f;
  add_triangle_bin(world, 8.0f, 12.0f);
  for (int r = 0; r < kRows; ++r) {
    for (int c = 0; c < kColumns; ++c) {
      const b2Vec2 centre((c - 0.5f * (kColumns - 1)) * kCell, 3.5f + r * kCell);
      const float angle = rng.uniformf(0, 6.283185307179586);
      const b2Rot q(angle);
      switch ((r * kColumns + c) % 3) {
        case 0:
          add_l_shape(world, centre - b2Mul(q, b2Vec2(1.0f, 1.0f)), angle);
          break;
        case 1:
          add_u_shape(world, centre - b2Mul(q, b2Vec2(1.5f, 1.0f)), angle);
          break;
        default:
          add_star(world, centre, angle);
          break;
      }
    }
  }
  return {};
}

}  // namespace dyop::scenes::detail
