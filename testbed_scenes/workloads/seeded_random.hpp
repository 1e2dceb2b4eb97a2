#pragma once
// Internal to the workloads: the seeded draws every pair generator makes (the same sequence for
// the same seed on one standard library).

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <random>

#include "dyop/vec2.hpp"

namespace dyop::workloads {

class SeededRandom {
 public:
  explicit SeededRandom(std::uint64_t seed) : rng_(seed) {}
  double uniform(double lo, double hi) { return lo + (hi - lo) * unit_(rng_); }
  double log_uniform(double lo_exp, double hi_exp) { return std::pow(10.0, uniform(lo_exp, hi_exp)); }
  int below(int n) { return static_cast<int>(rng_() % static_cast<std::uint64_t>(n)); }
  bool coin() { return (rng_() & 1u) != 0; }
  Vec2<double> unit_vector() {
    const double t = uniform(0, 2 * 3.14159265358979323846);
    return {std::cos(t), std::sin(t)};
  }
  // A random order of the same three vertices (rotation, and reversal half the time).
  std::array<Vec2<double>, 3> shuffled(std::array<Vec2<double>, 3> t) {
    std::rotate(t.begin(), t.begin() + below(3), t.end());
    if (coin()) std::swap(t[1], t[2]);
    return t;
  }

 private:
  std::mt19937_64 rng_;
  std::uniform_real_distribution<double> unit_{0.0, 1.0};
};

}  // namespace dyop::workloads
