#pragma once
// Internal: exact penetration depth by certifying all six candidate axes.
//
// `sat` and `dyop` share this: the set of axes and their arithmetic are the same, so both are
// exact and give bit-identical answers. The only use of an order is the early exit of the
// `Overlap` level, which tries `first` and `second` (dyop: the pivot's two axes) before the rest.
// Every other level needs all six overlaps of a touching or penetrating pair, so they are
// computed without branching on their values (the outcomes are unpredictable on real inputs).

#include "detail/finish.hpp"

namespace dyop::detail {

template <class T>
inline const AxisOverlap<T>& least_of(const AxisOverlap<T>& x, const AxisOverlap<T>& y) {
  return y.overlap < x.overlap ? y : x;  // ties keep x, the lower axis index
}

template <class T>
Result<T> certify_axes(const PairFrame<T>& f, const Query<T>& q, int first, int second) {
  const T band = touching_band(f);
  Result<T> r;
  if (q.level == Level::Overlap && (overlap_on_axis(f, first).overlap < -band ||
                                    overlap_on_axis(f, second).overlap < -band)) {
    r.status = Status::Separated;
    return r;
  }
  const AxisOverlap<T> best_a = least_of(
      least_of(overlap_on_a_edge(f, 0), overlap_on_a_edge(f, 1)), overlap_on_a_edge(f, 2));
  const AxisOverlap<T> best_b = least_of(
      least_of(overlap_on_b_edge(f, 0), overlap_on_b_edge(f, 1)), overlap_on_b_edge(f, 2));
  const AxisOverlap<T>& least = least_of(best_a, best_b);
  r.status = classify(least.overlap, band);
  if (r.status == Status::Separated) {
    fill_separated(f, q.level, r);
  } else {
    fill_from_axis(f, q.level, least, r);
  }
  fill_manifold(f, q, pick_reference(best_a, best_b, q.face_hysteresis), r);
  return r;
}

}  // namespace dyop::detail
