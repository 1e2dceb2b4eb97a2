// `crowd`: the bodies games are made of — `SetAsBox` boxes, hexagons, circles and triangles —
// poured into a bin of triangle fixtures: every pair family the plug-in answers, on a
// triangulated ground.
#include <cmath>

#include "scenes/builders.hpp"

namespace dyop::scenes::detail {
namespace {

constexpr int kBodies = 600;
constexpr int kColumns = 30;
constexpr float kCell = 1.0f;  // m: each body (at most 0.45 m from its centre) stays in its cell

}  // namespace

WorldBuild build_crowd(World& world, workloads::Random& rng) {
  const float half_width = 0.5f * kColumns * kCell;
  add_triangle_bin(world, half_width, 12.0f);
  for (int i = 0; i < kBodies; ++i) {
    const b2Vec2 p((i % kColumns - 0.5f * (kColumns - 1)) * kCell,
                   2.0f + static_cast<float>(i / kColumns) * kCell);
    // One draw per statement: the order of a call's arguments is unspecified.
    const float size = rng.uniformf(0.2, 0.4);
    const float angle = rng.uniformf(0, 6.283185307179586);
    switch (i % 4) {
      case 0: {
        const float aspect = rng.uniformf(0.5, 1.0);
        b2PolygonShape box;
        box.SetAsBox(size, aspect * size);
        add_solid(add_body(world, b2_dynamicBody, p, angle), box);
        break;
      }
      case 1: {
        b2Vec2 v[6];
        for (int k = 0; k < 6; ++k) {
          v[k].Set(size * std::cos(1.0471976f * k), size * std::sin(1.0471976f * k));
        }
        b2PolygonShape hexagon;
        hexagon.Set(v, 6);
        add_solid(add_body(world, b2_dynamicBody, p, angle), hexagon);
        break;
      }
      case 2: {
        b2CircleShape circle;
        circle.m_radius = size;
        add_solid(add_body(world, b2_dynamicBody, p, angle), circle);
        break;
      }
      default:
        add_random_triangle(world, rng, p, size + 0.05);
        break;
    }
  }
  return {};
}

}  // namespace dyop::scenes::detail
