#pragma once
// Internal to the scenes library: the builder of each Box2D scene (one file per family) and the
// seeded shapes they share. The catalogue (catalog.cpp) maps names to builders.

#include <string_view>

#include "scenes/world_scene.hpp"
#include "workloads/random.hpp"

namespace dyop::scenes::detail {

WorldBuild build_pyramid(World& world, workloads::Random& rng);
WorldBuild build_pyramid_rows(World& world, workloads::Random& rng);
WorldBuild build_stack(World& world, workloads::Random& rng);
WorldBuild build_stack_concave(World& world, workloads::Random& rng);
WorldBuild build_rain(World& world, workloads::Random& rng);
/// `rain` with `falling` triangles (the catalogue's has `rain_triangles`).
WorldBuild build_rain_of(World& world, workloads::Random& rng, int falling);
/// `rain` with `tall_rain_triangles`: a grid 39 columns wide and 39 rows tall.
WorldBuild build_rain_tall(World& world, workloads::Random& rng);
WorldBuild build_tumbler(World& world, workloads::Random& rng);
WorldBuild build_slivers(World& world, workloads::Random& rng);
WorldBuild build_slivers_far(World& world, workloads::Random& rng);
WorldBuild build_mixed(World& world, workloads::Random& rng);
WorldBuild build_slide(World& world, workloads::Random& rng);

/// The builder of the catalogue's Box2D scene `name`, or nullptr (unknown, or `paper`, which has
/// no Box2D world). Seed its `workloads::Random` with the scene's seed, as `make_scene` does.
const WorldBuilder* find_builder(std::string_view name);

/// A dynamic body at `position`, turned at random, holding one irregular triangle whose vertices
/// lie 0.75 to 1 × `radius` from the body origin, at angles at least 0.5 rad apart (so no sliver).
b2Body* add_random_triangle(World& world, workloads::Random& rng, const b2Vec2& position,
                            double radius);

/// Up to ±`amount` metres, for placement jitter.
inline float jitter(workloads::Random& rng, double amount) {
  return rng.uniformf(-amount, amount);
}

}  // namespace dyop::scenes::detail
