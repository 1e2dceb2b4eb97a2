#pragma once
/// \file
/// `sat`: the exact reference.
///
/// Algorithm: the Minkowski difference of two convex polygons has as edge normals exactly the edge
/// normals of A and the negated edge normals of B, so the penetration depth is the minimum, over
/// those six unit axes u, of the overlap `max_A(u·a) − min_B(u·b)`; a negative overlap proves the
/// pair apart, and the Euclidean distance is then the least of the 18 vertex–edge distances.
/// Computed in a frame centred on A's first vertex, so accuracy is relative to the triangles'
/// size, not to their distance from the origin. Conventions: `dyop/result.hpp`.

#include "dyop/result.hpp"
#include "dyop/triangle.hpp"

namespace dyop {

/// Exact penetration depth / distance of `a` and `b` at `query.level`.
template <class T>
Result<T> sat(const Triangle<T>& a, const Triangle<T>& b, const Query<T>& query = {});

/// \cond EXPLICIT_INSTANTIATIONS
extern template Result<float> sat(const Triangle<float>&, const Triangle<float>&,
                                  const Query<float>&);
extern template Result<double> sat(const Triangle<double>&, const Triangle<double>&,
                                   const Query<double>&);
/// \endcond

}  // namespace dyop
