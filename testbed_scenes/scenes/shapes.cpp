#include <cmath>

#include "scenes/builders.hpp"

namespace dyop::scenes::detail {

b2Body* add_random_triangle(World& world, workloads::Random& rng, const b2Vec2& position,
                            double radius) {
  constexpr double kTwoPi = 6.283185307179586;
  constexpr double kMinGap = 0.5;  // rad between vertices: the thinnest angle stays above ~14°
  // Three gaps of at least kMinGap summing to a full turn.
  double w[3];
  for (double& x : w) x = rng.unit();
  const double sum = w[0] + w[1] + w[2];
  const double spare = kTwoPi - 3 * kMinGap;
  double angle = rng.uniform(0, kTwoPi);
  b2Vec2 v[3];
  for (int i = 0; i < 3; ++i) {
    const double r = radius * rng.uniform(0.75, 1.0);
    v[i].Set(static_cast<float>(r * std::cos(angle)), static_cast<float>(r * std::sin(angle)));
    angle += kMinGap + spare * w[i] / sum;
  }
  b2Body* body = add_body(world, b2_dynamicBody, position, rng.uniformf(0, kTwoPi));
  add_triangle(body, v[0], v[1], v[2]);
  return body;
}

}  // namespace dyop::scenes::detail
