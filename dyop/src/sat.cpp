// Exact penetration depth by the separating-axis theorem (the reference every method is compared
// with): the edge normals of the Minkowski difference A − B of two convex polygons are exactly A's
// edge normals and B's negated ones, so the depth is the least overlap max_A(u) − min_B(u) over
// those six unit axes, and a pair is apart when one overlap is negative (then the exact distance
// from the closest vertex–edge pair, or only the gap with `Apart::Gap`). The work is
// certify_axes's, shared with `dyop`; every figure is computed in A's local frame.

#include "dyop/sat.hpp"

#include "detail/certify_axes.hpp"

namespace dyop {

template <class T>
Result<T> sat(const Triangle<T>& a, const Triangle<T>& b, const Query<T>& query) {
  return detail::certify_axes(detail::PairFrame<T>(a, b), query);
}

template Result<float> sat(const Triangle<float>&, const Triangle<float>&, const Query<float>&);
template Result<double> sat(const Triangle<double>&, const Triangle<double>&, const Query<double>&);

}  // namespace dyop
