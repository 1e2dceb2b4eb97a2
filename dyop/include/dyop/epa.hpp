#pragma once
/// \file
/// `epa`: GJK + EPA in 2D (van den Bergen 2001), what general engines use.
///
/// GJK iterates a simplex of support points of the Minkowski difference A − B (each a pair of
/// vertex indices) towards the origin: it ends with the distance when the origin is outside, or
/// with a triangle enclosing the origin. EPA then expands that polygon towards the boundary of
/// A − B, always splitting the edge closest to the origin, until the new support point lies no
/// farther than `epa_tolerance` beyond it; that edge's distance is the depth and its normal the
/// axis. When GJK ends within the touching band of its simplex (origin on a segment, a vertex or
/// a flat triangle), EPA starts from the simplex completed with supports on both sides, and its
/// signed depth tells touching from penetrating. Computed in a local frame; tolerances are
/// relative to the pair's size. Conventions: `dyop/result.hpp`.
///
/// What is EPA's own and what is borrowed:
/// - `Level::Depth`: `separation`, `depth` and `normal` are EPA's (penetrating, touching) or
///   GJK's (separated) own numbers, never recomputed on a candidate axis, so comparing them with
///   `sat` measures this method's error.
/// - Separated, `Level::Contact`: witnesses from the simplex's barycentric coordinates, features
///   from its vertex pairs (a vertex or an edge of each triangle).
/// - Penetrating or touching, `Level::Contact` and up: the candidate axis (an edge normal of A or
///   a negated one of B) nearest to EPA's normal names the features and the deepest vertex, and
///   `witness_a − witness_b` is EPA's depth along that axis.
/// - `Level::Manifold`: clipped on the face Box2D's rule picks (each triangle's face of least
///   overlap, B's only when better by more than `face_hysteresis`), as the exact methods do: a
///   body resting on another has faces parallel to within rounding, and a face chosen by nearness
///   to EPA's or GJK's normal would swap between them from step to step.
/// - `Level::Overlap`: GJK only, stopping at the first support point that proves a gap wider
///   than the touching band or at an enclosing simplex whose edges are all farther than it; EPA
///   runs only when the origin is within the band of the simplex's boundary.
/// - `iterations`: support evaluations of GJK plus those of EPA, at most 2·`epa_max_iterations`.

#include "dyop/result.hpp"
#include "dyop/triangle.hpp"

namespace dyop {

/// Relative convergence tolerance of GJK and EPA (times the larger triangle's size). Why: the
/// Minkowski difference of two triangles has at most 6 edges, so EPA ends exactly after a few
/// steps; the tolerance only has to absorb the rounding of a support dot product, a few eps.
/// The same length also makes two support points one point and a simplex triangle flat (height
/// below it): both are the rounding of a difference of vertices, a few eps of the size.
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

/// \cond EXPLICIT_INSTANTIATIONS
extern template Result<float> epa(const Triangle<float>&, const Triangle<float>&,
                                  const Query<float>&);
extern template Result<double> epa(const Triangle<double>&, const Triangle<double>&,
                                   const Query<double>&);
/// \endcond

}  // namespace dyop
