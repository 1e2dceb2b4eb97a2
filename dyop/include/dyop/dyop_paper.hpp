#pragma once
/// \file
/// `dyop_paper`: the paper's equations 3–8 taken literally, for reproduction only.
///
/// Per direction, the vertex nearest the pivot and the edge PQ nearest the pivot; the edge as
/// `y = M x + C` (eqs. 3–4), the parallel line through the vertex (eq. 5), and the depth
/// `C_PQ − C_i` when M = 0 (eq. 7) or `|C_i − C_PQ| / sqrt(X_P² + Y_P²)` otherwise (eq. 8). Eq. 8
/// divides by P's distance from the origin instead of `sqrt(1 + M²)`, so its depth is wrong
/// except by accident (Figure 6: 0.0292043 printed where the true distance is 0.0580101), and it
/// depends on where the origin is. Point in triangle is tested by the paper's area sums with a
/// relative tolerance (equality of float sums never holds exactly).
///
/// A vertical edge has no slope, and an edge whose P lies at the origin makes eq. 8 divide by
/// zero: such a query returns `Status::Invalid` with a reason, never inf or NaN.
/// Use `dyop` or `dyop_fast` for anything but reproducing the paper. Conventions:
/// `dyop/result.hpp`; the normal is the pivot edge's unit normal.

#include "dyop/result.hpp"
#include "dyop/triangle.hpp"

namespace dyop {

/// Numbers of one direction of the paper's computation, as its Figure 6 prints them.
template <class T>
struct PaperLines {
  T m = 0;              ///< M_PQ, slope of the pivot edge (eq. 3)
  T c = 0;              ///< C_PQ, intercept of the pivot edge (eq. 4)
  T c_vertex = 0;       ///< C_i-PQ, intercept of the parallel through the pivot vertex (eq. 5)
  T depth_eq8 = 0;      ///< the paper's penetration depth: eq. 7 when M = 0, eq. 8 otherwise
  T true_distance = 0;  ///< the correct line distance |C_i − C_PQ| / sqrt(1 + M²)
};

/// Eqs. 3–8 for vertex `x` against the line through `p` and `q`. `ok()` is false (and the numbers
/// zero) for a vertical line, when eq. 8 would divide by zero (p at the origin), or when the
/// slope or eq. 8's value is not finite.
template <class T>
struct PaperLinesOrError {
  InvalidReason reason = InvalidReason::None;                ///< None when the numbers are valid
  PaperLines<T> lines;                                       ///< valid only when `reason == None`
  bool ok() const { return reason == InvalidReason::None; }  ///< true when `reason == None`
};

/// The paper's lines (eqs. 3–8) for vertex `x` against the line through `p` and `q`.
template <class T>
PaperLinesOrError<T> paper_lines(const Vec2<T>& p, const Vec2<T>& q, const Vec2<T>& x);

/// The paper's method on two triangles, literally (world coordinates, no local frame).
template <class T>
Result<T> dyop_paper(const Triangle<T>& a, const Triangle<T>& b, const Query<T>& query = {});

/// \cond EXPLICIT_INSTANTIATIONS
extern template PaperLinesOrError<float> paper_lines(const Vec2<float>&, const Vec2<float>&,
                                                     const Vec2<float>&);
extern template PaperLinesOrError<double> paper_lines(const Vec2<double>&, const Vec2<double>&,
                                                      const Vec2<double>&);
extern template Result<float> dyop_paper(const Triangle<float>&, const Triangle<float>&,
                                         const Query<float>&);
extern template Result<double> dyop_paper(const Triangle<double>&, const Triangle<double>&,
                                          const Query<double>&);
/// \endcond

}  // namespace dyop
