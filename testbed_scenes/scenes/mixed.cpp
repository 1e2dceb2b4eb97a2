// `mixed`: triangles with boxes and circles on a ground of two-sided edges. Triangle pairs go to
// the plug-in's backend; boxes, circles and the edges' pairs to the exact solver
// (`Config::edges_and_chains`); circle–circle pairs keep Box2D's own contacts.
#include "scenes/builders.hpp"

namespace dyop::scenes::detail {
namespace {

void add_edge(b2Body* body, const b2Vec2& a, const b2Vec2& b) {
  b2EdgeShape edge;
  edge.SetTwoSided(a, b);
  body->CreateFixture(&edge, 0.0f);
}

}  // namespace

WorldBuild build_mixed(World& world, workloads::Random& rng) {
  b2Body* ground = add_body(world, b2_staticBody, b2Vec2(0.0f, 0.0f));
  add_edge(ground, b2Vec2(-10.0f, 0.0f), b2Vec2(10.0f, 0.0f));
  add_edge(ground, b2Vec2(-10.0f, 0.0f), b2Vec2(-10.0f, 12.0f));
  add_edge(ground, b2Vec2(10.0f, 0.0f), b2Vec2(10.0f, 12.0f));
  // 80 bodies on a 10 × 8 grid of 1.8 m cells, cycling triangle, box, triangle, circle; each
  // reaches at most 0.7 m from its centre, so none starts overlapping.
  for (int k = 0; k < 80; ++k) {
    const b2Vec2 p(-8.1f + 1.8f * (k % 10), 1.5f + 1.8f * (k / 10));
    switch (k % 4) {
      case 0:
      case 2:
        add_random_triangle(world, rng, p, rng.uniform(0.25, 0.7));
        break;
      case 1: {
        // One draw per statement: the order of a call's arguments is unspecified.
        const float hx = rng.uniformf(0.2, 0.45);
        const float hy = rng.uniformf(0.2, 0.45);
        b2PolygonShape box;
        box.SetAsBox(hx, hy);
        add_solid(add_body(world, b2_dynamicBody, p, rng.uniformf(0, 6.283185307179586)), box);
        break;
      }
      default: {
        b2CircleShape circle;
        circle.m_radius = rng.uniformf(0.2, 0.6);
        add_solid(add_body(world, b2_dynamicBody, p), circle);
        break;
      }
    }
  }
  return {};
}

}  // namespace dyop::scenes::detail
