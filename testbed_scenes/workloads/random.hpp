#pragma once
/// \file
/// The one random generator of the testbed, the solver's and the testbed's tests, the benchmarks,
/// the stress runs and the scenes (the bridge's tests, built without the testbed, draw from
/// std::mt19937_64: tests/box2d_bridge/support/draws.hpp): SplitMix64 (Steele, Lea & Flood,
/// "Fast splittable pseudorandom number generators", 2014), chosen over the standard library's
/// engines and distributions because the distributions are not specified bit for bit: a seed must
/// give the same pairs, the same scene and the same hash with any compiler and standard library.
///
/// Every draw is built from the 64 random bits with + − × ÷ and √ only, which IEEE 754 rounds
/// exactly, except `log_uniform`, which goes through `std::pow` (the C library's last bit).

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <utility>

#include "dyop/vec2.hpp"

namespace dyop::workloads {

class Random {
 public:
  explicit Random(std::uint64_t seed) : state_(seed) {}

  /// The next 64 random bits.
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }

  /// Uniform in [0, 1), 53 random bits.
  double unit() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }

  /// Uniform in [lo, hi).
  double uniform(double lo, double hi) { return lo + (hi - lo) * unit(); }

  /// Uniform in [lo, hi) as a float (what Box2D takes).
  float uniformf(double lo, double hi) { return static_cast<float>(uniform(lo, hi)); }

  /// Uniform integer in [0, n).
  int below(int n) { return static_cast<int>(unit() * n); }

  /// True or false, each half the time.
  bool coin() { return (next() >> 63) != 0; }

  /// 10^e for e uniform in [lo_exp, hi_exp): spread evenly over orders of magnitude.
  double log_uniform(double lo_exp, double hi_exp) {
    return std::pow(10.0, uniform(lo_exp, hi_exp));
  }

  /// A direction uniform on the circle: a point uniform in the unit disc (by rejection), scaled to
  /// length 1.
  Vec2<double> unit_vector() {
    for (;;) {
      const double x = uniform(-1, 1);
      const double y = uniform(-1, 1);
      const double r2 = x * x + y * y;
      // Below 1e-6 the rounding of p would show in its direction.
      if (r2 <= 1 && r2 > 1e-6) return Vec2<double>(x, y) / std::sqrt(r2);
    }
  }

  /// A point uniform in the square [lo, hi)².
  Vec2<double> point_in(double lo, double hi) {
    const double x = uniform(lo, hi);
    const double y = uniform(lo, hi);
    return {x, y};
  }

  /// The polygon `v[0..count)` in a random order of the same cycle: rotated, and reversed half the
  /// time.
  void shuffle(Vec2<double>* v, int count) {
    std::rotate(v, v + below(count), v + count);
    if (coin()) std::reverse(v + 1, v + count);
  }

  /// The same three vertices in a random order: rotated, and reversed half the time.
  std::array<Vec2<double>, 3> shuffled(std::array<Vec2<double>, 3> t) {
    shuffle(t.data(), 3);
    return t;
  }

 private:
  std::uint64_t state_;
};

}  // namespace dyop::workloads
