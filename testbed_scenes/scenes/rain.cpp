// `rain`: triangles of mixed sizes falling into a bin of triangle fixtures, settling; 500 in the
// catalogue's scene, any number for the scaling runs of `dyop bench`.
#include <algorithm>
#include <cmath>

#include "scenes/builders.hpp"

namespace dyop::scenes::detail {

WorldBuild build_rain_of(World& world, workloads::Random& rng, int falling) {
  // A grid of 1 m cells from 2 m up, about as many columns as rows but at least 22 (500: 22
  // columns, 23 rows); each triangle (radius at most 0.48 m) stays in its cell, so none starts
  // overlapping. The bin is as wide as the grid and its walls grow with it (12 m for 22 columns).
  constexpr float kCell = 1.0f;
  const int columns = std::max(22, static_cast<int>(std::lround(std::sqrt(falling))));
  const float half_width = 0.5f * columns * kCell;
  add_triangle_bin(world, half_width, 12.0f * columns / 22.0f);
  for (int i = 0; i < falling; ++i) {
    const int r = i / columns, c = i % columns;
    const b2Vec2 centre((c - 0.5f * (columns - 1)) * kCell, 2.0f + r * kCell);
    // Log-uniform radius from 0.1 to 0.48 m: edges from about 0.1 m to 0.9 m.
    const double radius = 0.1 * std::pow(4.8, rng.unit());
    add_random_triangle(world, rng, centre, radius);
  }
  return {};
}

WorldBuild build_rain(World& world, workloads::Random& rng) {
  return build_rain_of(world, rng, rain_triangles);
}

WorldBuild build_rain_tall(World& world, workloads::Random& rng) {
  return build_rain_of(world, rng, tall_rain_triangles);
}

}  // namespace dyop::scenes::detail
