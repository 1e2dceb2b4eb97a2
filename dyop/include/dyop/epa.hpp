#pragma once
/// \file
/// `epa`: GJK + EPA in 2D (van den Bergen 2001), what general engines use.
///
/// GJK iterates a simplex of support points of the Minkowski difference A − B towards the origin:
/// it ends with the distance when the origin is outside, or with a triangle enclosing the origin.
/// EPA then expands that polygon towards the boundary of A − B, always splitting the edge closest
/// to the origin, until the new support point does not move it further than `epa_tolerance`;
/// that edge's distance is the depth and its normal the axis. Tolerances are relative to the
/// pair's size. Computed in a local frame. Conventions: `dyop/result.hpp`.

#include "dyop/result.hpp"
#include "dyop/triangle.hpp"

namespace dyop {

/// Relative convergence tolerance of GJK and EPA (times the larger triangle's size). Why: the
/// Minkowski difference of two triangles has at most 6 edges, so EPA ends exactly after a few
/// steps; the tolerance only has to absorb the rounding of a support dot product, a few eps.
template <class T>
constexpr T epa_tolerance() {
  return T(16) * Eigen::NumTraits<T>::epsilon();
}

/// Upper bound on GJK and EPA iterations each. Why: the difference has 9 vertices at most and 6
/// edges, so an exact run needs fewer; the bound only stops a rounding-induced cycle.
constexpr int epa_max_iterations = 32;

/// GJK distance / EPA depth of `a` and `b` at `query.level`.
template <class T>
Result<T> epa(const Triangle<T>& a, const Triangle<T>& b, const Query<T>& query = {});

extern template Result<float> epa(const Triangle<float>&, const Triangle<float>&,
                                  const Query<float>&);
extern template Result<double> epa(const Triangle<double>&, const Triangle<double>&,
                                   const Query<double>&);

}  // namespace dyop
