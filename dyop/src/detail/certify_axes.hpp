#pragma once
// Internal: exact penetration depth by certifying all six candidate axes, in a given order.
//
// `sat` tries the axes in index order; `dyop` puts the pivot's two axes first so that a separated
// pair usually exits on the first axis tried. The set of axes and their arithmetic are the same,
// so both are exact and give bit-identical depths.

#include "detail/finish.hpp"

namespace dyop::detail {

template <class T>
Result<T> certify_axes(const PairFrame<T>& f, const Query<T>& q, int first, int second) {
  const T band = touching_band(f);
  Result<T> r;
  AxisOverlap<T> best_a;
  AxisOverlap<T> best_b;
  best_a.overlap = best_b.overlap = std::numeric_limits<T>::infinity();
  bool apart = false;
  auto visit = [&](int k) {
    const AxisOverlap<T> ax = overlap_on_axis(f, k);
    AxisOverlap<T>& best = k < 3 ? best_a : best_b;
    // Ties go to the lower axis index, so that the visiting order never changes the answer.
    if (ax.overlap < best.overlap || (ax.overlap == best.overlap && ax.axis < best.axis)) best = ax;
    apart = apart || ax.overlap < -band;
    // A manifold needs every axis (the best face of each triangle); the other levels stop here.
    return apart && q.level != Level::Manifold;
  };
  bool done = visit(first) || visit(second);
  for (int k = 0; k < 6 && !done; ++k) {
    if (k != first && k != second) done = visit(k);
  }
  if (apart) {
    r.status = Status::Separated;
    fill_separated(f, q.level, r);
    if (q.level == Level::Manifold) {
      fill_manifold(f, q, pick_reference(best_a, best_b, q.face_hysteresis), r);
    }
    return r;
  }
  const AxisOverlap<T>& least = best_b.overlap < best_a.overlap ? best_b : best_a;
  r.status = classify(least.overlap, band);
  fill_from_axis(f, q.level, least, r);
  fill_manifold(f, q, pick_reference(best_a, best_b, q.face_hysteresis), r);
  return r;
}

}  // namespace dyop::detail
