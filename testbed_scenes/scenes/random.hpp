#pragma once
/// \file
/// The scenes' random numbers: SplitMix64 (Steele, Lea & Flood 2014), chosen over the standard
/// library's distributions because those are not specified bit for bit: a seed must give the same
/// scene, and the same hash, with any compiler and library.

#include <cstdint>

namespace dyop::scenes {

class Rng {
 public:
  explicit Rng(std::uint64_t seed) : state_(seed) {}

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

 private:
  std::uint64_t state_;
};

}  // namespace dyop::scenes
