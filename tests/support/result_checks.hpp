#pragma once
// Test support: what the typed suites check of any method's `Result`.

#include <Eigen/Core>
#include <gtest/gtest.h>

#include <cmath>
#include <string>

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

// A feature type as failure messages name it.
inline const char* type_name(Feature::Type t) {
  switch (t) {
    case Feature::Type::Vertex:
      return "vertex";
    case Feature::Type::Edge:
      return "edge";
    case Feature::Type::None:
      break;
  }
  return "none";
}

// Success when `r`'s features are `a` on A and `b` on B (caller's indices); otherwise a message
// naming the features found and the ones expected.
template <class T>
::testing::AssertionResult has_features(const Result<T>& r, Feature a, Feature b) {
  const auto same = [](Feature x, Feature y) { return x.type == y.type && x.index == y.index; };
  if (same(r.feature_a, a) && same(r.feature_b, b)) return ::testing::AssertionSuccess();
  const auto text = [](Feature f) {
    return std::string(type_name(f.type)) + " " + std::to_string(f.index);
  };
  return ::testing::AssertionFailure()
         << "features A " << text(r.feature_a) << ", B " << text(r.feature_b) << "; expected A "
         << text(a) << ", B " << text(b);
}

}  // namespace dyop::test_support
