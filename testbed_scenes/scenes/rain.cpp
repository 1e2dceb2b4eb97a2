// `rain`: 500 triangles of mixed sizes falling into a bin of triangle fixtures, settling.
#include <cmath>

#include "scenes/builders.hpp"

namespace dyop::scenes::detail {

WorldBuild build_rain(World& world, Rng& rng) {
  // A 22-column grid of 1 m cells from 2 m up: each triangle (radius at most 0.48 m) stays in
  // its cell, so none starts overlapping; the top row is 24 m up and lands within about 2.5 s.
  constexpr int kTriangles = 500;
  constexpr int kColumns = 22;
  constexpr float kCell = 1.0f;
  add_triangle_bin(world, 11.0f, 12.0f);
  for (int i = 0; i < kTriangles; ++i) {
    const int r = i / kColumns, c = i % kColumns;
    const b2Vec2 centre((c - 0.5f * (kColumns - 1)) * kCell, 2.0f + r * kCell);
    // Log-uniform radius from 0.1 to 0.48 m: edges from about 0.1 m to 0.9 m.
    const double radius = 0.1 * std::pow(4.8, rng.unit());
    add_random_triangle(world, rng, centre, radius);
  }
  return {};
}

}  // namespace dyop::scenes::detail
