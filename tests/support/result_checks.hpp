#pragma once
// Test support: what the typed suites check of any method's `Result`.

#include <Eigen/Core>

#include <cmath>

#include "dyop/result.hpp"

namespace dyop::test_support {

// A tolerance relative to the answer's scale for exact methods compared with hand-worked
// answers: 100 epsilons of the precision, far above the few roundings of one query and far below
// any error a wrong feature or axis makes.
template <class T>
T tol() {
  return T(100) * Eigen::NumTraits<T>::epsilon();
}

// True when every number of `r` is finite: distance, depth, normal, witnesses, the manifold's
// normal and its points.
template <class T>
bool all_finite(const Result<T>& r) {
  bool ok = std::isfinite(r.separation) && std::isfinite(r.depth) && r.normal.allFinite() &&
            r.witness_a.allFinite() && r.witness_b.allFinite() && r.manifold.normal.allFinite();
  for (int i = 0; i < r.manifold.point_count; ++i) {
    ok = ok && r.manifold.points[i].point.allFinite() &&
         std::isfinite(r.manifold.points[i].separation);
  }
  return ok;
}

}  // namespace dyop::test_support
