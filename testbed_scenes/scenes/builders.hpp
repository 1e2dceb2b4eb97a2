#pragma once
// Internal to the scenes library: the builder of each Box2D scene (one file per family) and the
// seeded shapes they share. The catalogue (catalog.cpp) maps names to builders.

#include <string>
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
WorldBuild build_tiles(World& world, workloads::Random& rng);
WorldBuild build_tile_map(World& world, workloads::Random& rng);
WorldBuild build_tile_map_unfixed(World& world, workloads::Random& rng);
WorldBuild build_crowd(World& world, workloads::Random& rng);

/// The builder of the catalogue's Box2D scene `name`, or nullptr (unknown, or `paper`, which has
/// no Box2D world). Seed its `workloads::Random` with the scene's seed, as `make_scene` does.
const WorldBuilder* find_builder(std::string_view name);

/// A dynamic body at `position`, turned at random, holding one irregular triangle whose vertices
/// lie 0.75 to 1 × `radius` from the body origin, at angles at least 0.5 rad apart (so no sliver).
b2Body* add_random_triangle(World& world, workloads::Random& rng, const b2Vec2& position,
                            double radius);

/// A fixture of `shape` on `body`, of the scenes' default material (`Material`).
inline void add_solid(b2Body* body, const b2Shape& shape) {
  const Material material;
  b2FixtureDef def;
  def.shape = &shape;
  def.density = material.density;
  def.friction = material.friction;
  body->CreateFixture(&def);
}

/// Up to ±`amount` metres, for placement jitter.
inline float jitter(workloads::Random& rng, double amount) { return rng.uniformf(-amount, amount); }

/// The sliding scenes' materials: frictionless for the gliding bodies and their grounds, friction
/// 0.6 (as every other scene) for the wheel, its ground and resting bodies.
inline const Material slider_ice{1.0f, 0.0f};
inline const Material slider_rubber{};
/// m: half the side of the sliding scenes' box (the 0.5 m box).
inline constexpr float slider_box_half = 0.25f;

/// A slider of the sliding scenes (`slide`, `tiles`) launched at `speed` along +x from x, on a
/// ground whose top is y = `top`, its core `lift` above it (0: cores touching; Box2D's skins then
/// overlap by 2 cm and the position solver parts them without any velocity; 2·b2_polygonRadius:
/// skins touching, nothing to part): `body` "box" (a
/// frictionless 0.5 m box of two triangles), "L" (a frictionless L of three 0.25 m squares, six
/// triangles) or "wheel" (a 16-sided rubber polygon of radius 0.4 m, rolling); `ground` names the
/// lane in its figures.
Slider launch_slider(World& world, const std::string& body, const std::string& ground, float x,
                     float top, float speed, float lift = 0);

}  // namespace dyop::scenes::detail
