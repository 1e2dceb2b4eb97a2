#pragma once
// Seeded draws for the bridge's randomized worlds and pairs: the bits of std::mt19937_64, which
// the standard fixes bit for bit, made into numbers with × and + only (the standard's
// distributions are not fixed), so that a seed gives the same draws with any standard library.

#include <cstdint>
#include <random>

namespace dyop::box2d::testing {

class Draws {
 public:
  explicit Draws(std::uint64_t seed) : bits_(seed) {}

  // Uniform in [0, 1), 53 random bits.
  double unit() { return static_cast<double>(bits_() >> 11) * 0x1.0p-53; }

  // Uniform in [lo, hi) as a float (what Box2D takes).
  float uniformf(double lo, double hi) { return static_cast<float>(lo + (hi - lo) * unit()); }

 private:
  std::mt19937_64 bits_;
};

}  // namespace dyop::box2d::testing
