// `pyramid`: 55 boxes of two triangle fixtures each on a triangle ground. `pyramid-rows`: a
// pyramid of single-triangle bodies, rows of alternating up and down triangles.
#include <cmath>

#include "scenes/builders.hpp"

namespace dyop::scenes::detail {
namespace {

constexpr int kBase = 10;      // 10 + 9 + ... + 1 = 55 boxes; 10² = 100 triangles in rows
constexpr float kHalf = 0.5f;  // boxes of 1 m
constexpr double kPlacementJitter = 0.001;  // m, horizontal placement noise from the seed

}  // namespace

WorldBuild build_pyramid(World& world, workloads::Random& rng) {
  add_triangle_ground(world, 10.0f);
  // Cores 1 cm apart (Box2D rests them 1.5 cm apart: the skins' sum less the slop), so nothing
  // starts overlapping.
  const float pitch = 2 * kHalf + b2_polygonRadius;
  b2Body* top = nullptr;
  for (int row = 0; row < kBase; ++row) {
    for (int i = 0; i < kBase - row; ++i) {
      const float x = (i - 0.5f * (kBase - row - 1)) * pitch + jitter(rng, kPlacementJitter);
      top = add_split_box(world, b2Vec2(x, kHalf + b2_polygonRadius + row * pitch), kHalf);
    }
  }
  WorldBuild build;
  build.watched.push_back(top);
  return build;
}

WorldBuild build_pyramid_rows(World& world, workloads::Random& rng) {
  // Equilateral triangles of side 1. Row r holds kBase − r upward triangles with a downward one
  // between each two; the next row's upward triangles stand on the downward ones' flat tops.
  constexpr float kSide = 1.0f;
  const float h = 0.5f * std::sqrt(3.0f) * kSide;
  // 6 cm between the bases of neighbours leaves 2.6 cm between their slanted faces, more than the
  // skins' 2 cm; rows start 3 cm apart. The downward triangles then sink into place.
  constexpr float kGap = 0.06f;
  constexpr float kRowGap = 0.03f;
  const float pitch = kSide + kGap;
  add_triangle_ground(world, 8.0f);
  const b2Vec2 up[3] = {b2Vec2(-0.5f * kSide, -h / 3), b2Vec2(0.5f * kSide, -h / 3),
                        b2Vec2(0.0f, 2 * h / 3)};
  const b2Vec2 down[3] = {b2Vec2(-0.5f * kSide, h / 3), b2Vec2(0.0f, -2 * h / 3),
                          b2Vec2(0.5f * kSide, h / 3)};
  b2Body* top = nullptr;
  for (int row = 0; row < kBase; ++row) {
    const int n = kBase - row;
    const float x0 = -0.5f * (kBase - 1) * pitch + 0.5f * row * pitch;
    const float y0 = b2_polygonRadius + row * (h + kRowGap);  // bottom of the row
    for (int i = 0; i < n; ++i) {
      top = add_body(world, b2_dynamicBody,
                     b2Vec2(x0 + i * pitch + jitter(rng, kPlacementJitter), y0 + h / 3));
      add_triangle(top, up[0], up[1], up[2]);
      if (i + 1 < n) {
        b2Body* d = add_body(
            world, b2_dynamicBody,
            b2Vec2(x0 + (i + 0.5f) * pitch + jitter(rng, kPlacementJitter), y0 + 2 * h / 3));
        add_triangle(d, down[0], down[1], down[2]);
      }
    }
  }
  WorldBuild build;
  build.watched.push_back(top);
  return build;
}

}  // namespace dyop::scenes::detail
