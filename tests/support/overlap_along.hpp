#pragma once
// Test support: the overlap of a triangle pair along a direction, in double, the quantity a
// penetrating pair's depth minimises over directions.

#include <algorithm>
#include <cmath>

#include "dyop/vec2.hpp"
#include "workloads/raw_pair.hpp"

namespace dyop::test_support {

// max over A of n·a − min over B of n·b, in a frame on A's first vertex (metres along unit `n`).
// A penetrating pair's normal is a minimum-translation axis exactly when this equals its depth,
// whichever axis wins a tie.
inline double overlap_along(const workloads::RawPair& p, const Vec2<double>& n) {
  double most_a = -HUGE_VAL;
  double least_b = HUGE_VAL;
  for (int i = 0; i < 3; ++i) {
    most_a = std::max(most_a, n.dot(p.a[i] - p.a[0]));
    least_b = std::min(least_b, n.dot(p.b[i] - p.a[0]));
  }
  return most_a - least_b;
}

}  // namespace dyop::test_support
