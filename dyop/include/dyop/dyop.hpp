#pragma once
/// \file
/// DyOP-PD, the Dynamic Pivot Point technique (the paper and its corrections: `docs/paper.md`),
/// reconstructed and corrected.
///
/// The pivot is the centre of the intersection box of the two triangles' AABBs (per axis the
/// midpoint of [max(minA, minB), min(maxA, maxB)]: the centre of the gap when the boxes are apart),
/// recomputed every query so it moves with the objects. In each direction (A into B, B into A) the
/// pivot picks the vertex of one triangle nearest to it and the edge of the other nearest to it;
/// the edge's supporting line is taken in normal form `n·x = c` (unit n), never slope–intercept.
///
/// - `dyop` (exact): all six candidate axes certify the minimum, so touching and penetrating
///   answers equal `sat`'s bit for bit; for a pair found apart the pivot's features (its vertex of
///   one triangle against its edge of the other, both ways) give the closest pair, accepted when
///   the gap along their direction proves it (else all 18 vertex–edge pairs decide). The six
///   axes are evaluated at once, branch-free, not the pivot's edges first: choosing them costs
///   more than the axes an early exit could skip (docs/paper.md).
/// - `dyop_fast` (approximate by design, the paper's heuristic with corrected maths): the depth in
///   a direction is the signed distance of the pivot's vertex from the pivot's edge line; the pair
///   penetrates when a pivot vertex lies inside the other triangle (orientation signs, not the
///   paper's area sums); the depth is the smaller of the penetrating directions'. It misses
///   penetrations where no pivot vertex is inside, and its depth is not always the minimum.
///   When it finds no penetration, `separation` is the larger of the two signed distances (≥ 0).
/// Conventions: `dyop/result.hpp`.

#include "dyop/result.hpp"
#include "dyop/triangle.hpp"

namespace dyop {

/// Exact DyOP-PD: the pivot's choice first, then certification (equal to `sat`).
template <class T>
Result<T> dyop(const Triangle<T>& a, const Triangle<T>& b, const Query<T>& query = {});

/// The pivot heuristic alone, without certification: fast, approximate.
template <class T>
Result<T> dyop_fast(const Triangle<T>& a, const Triangle<T>& b, const Query<T>& query = {});

/// \cond EXPLICIT_INSTANTIATIONS
extern template Result<float> dyop(const Triangle<float>&, const Triangle<float>&,
                                   const Query<float>&);
extern template Result<double> dyop(const Triangle<double>&, const Triangle<double>&,
                                    const Query<double>&);
extern template Result<float> dyop_fast(const Triangle<float>&, const Triangle<float>&,
                                        const Query<float>&);
extern template Result<double> dyop_fast(const Triangle<double>&, const Triangle<double>&,
                                         const Query<double>&);
/// \endcond

}  // namespace dyop
