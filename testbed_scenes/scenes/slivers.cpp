// `slivers`: thin, tiny and large triangles together in a bin of triangle fixtures.
// `slivers-far`: the same scene, body for body, moved 10 km from the origin, where a float
// position has a resolution of about 1 mm.
#include <cmath>

#include "scenes/builders.hpp"

namespace dyop::scenes::detail {
namespace {

// A dynamic sliver: `length` long, `thickness` high, its apex anywhere along the top.
b2Body* add_sliver(World& world, workloads::Random& rng, const b2Vec2& position, float length,
                   float thickness) {
  const float apex = length * rng.uniformf(-0.3, 0.3);
  const b2Vec2 c((apex) / 3, thickness / 3);  // centroid, so the body origin is its centre
  b2Body* body = add_body(world, b2_dynamicBody, position, rng.uniformf(-0.5, 0.5));
  add_triangle(body, b2Vec2(-0.5f * length, 0.0f) - c, b2Vec2(0.5f * length, 0.0f) - c,
               b2Vec2(apex, thickness) - c);
  return body;
}

WorldBuild build(World& world, workloads::Random& rng, const b2Vec2& offset) {
  b2Body* bin = add_triangle_bin(world, 10.0f, 10.0f);
  bin->SetTransform(offset, 0.0f);
  // Bottom: six large triangles (2 to 3 m across) in 3.2 m cells.
  for (int i = 0; i < 6; ++i) {
    const b2Vec2 p(-8.0f + 3.2f * i, 2.5f);
    add_random_triangle(world, rng, offset + p, rng.uniform(1.0, 1.5));
  }
  // Above: 60 small bodies in 1.6 m cells, cycling sliver, tiny, sliver, tiny, medium.
  for (int k = 0; k < 60; ++k) {
    const b2Vec2 p(-8.8f + 1.6f * (k % 12), 6.0f + 1.6f * (k / 12));
    switch (k % 5) {
      case 0:
      case 2: {  // 0.6 to 1.4 m long, 1 to 3 cm thick: aspect 1/20 to 1/140
        // One draw per statement: the order of a call's arguments is unspecified.
        const float length = rng.uniformf(0.6, 1.4);
        const float thickness = rng.uniformf(0.01, 0.03);
        add_sliver(world, rng, offset + p, length, thickness);
        break;
      }
      case 1:
      case 3:  // 1.2 to 3 cm radius: edges of 1 to 5 cm
        add_random_triangle(world, rng, offset + p, rng.uniform(0.012, 0.03));
        break;
      default:
        add_random_triangle(world, rng, offset + p, rng.uniform(0.2, 0.5));
        break;
    }
  }
  return {};
}

}  // namespace

WorldBuild build_slivers(World& world, workloads::Random& rng) {
  return build(world, rng, b2Vec2(0.0f, 0.0f));
}

WorldBuild build_slivers_far(World& world, workloads::Random& rng) {
  // 10 km along the diagonal: both coordinates lose precision.
  const float d = static_cast<float>(10000.0 / std::sqrt(2.0));
  return build(world, rng, b2Vec2(d, d));
}

}  // namespace dyop::scenes::detail
