#pragma once
// Internal: exact penetration depth by certifying all six candidate axes.
//
// `sat` and `dyop` share this, so both are exact and their depths bit-identical. The six overlaps
// are computed together, lane-wise and without branches on the data: on two triangles that is
// cheaper than trying the axes one by one in any order. `find` locates the closest features of a
// pair found apart (dyop passes its pivot's guess, certified; sat passes the full search).

#include "detail/fill_result.hpp"

namespace dyop::detail {

template <class T, class Find = AllFeatures<T>>
Result<T> certify_axes(const PairFrame<T>& f, const Query<T>& q, const Find& find = {}) {
  const std::array<T, 6> overlap = all_overlaps(f);
  const int best_a = argmin3(overlap, 0);
  const int best_b = argmin3(overlap, 3);
  const int least = overlap[best_b] < overlap[best_a] ? best_b : best_a;  // ties: A's face
  Result<T> r;
  const T band = touching_band(f);
  r.status = status_of_overlap(overlap[least], band);
  // A gap inside the band proves only that the pair does not overlap: along an edge normal it can
  // be far less than the distance (two slivers end to end), so the distance decides.
  const bool gap_in_band = r.status == Status::Touching && overlap[least] < 0;
  const Closest<T> near = gap_in_band ? find(f) : Closest<T>{};
  if (gap_in_band && near.distance > band) {
    fill_closest(f, q.level, near, r);
  } else if (r.status == Status::Separated && q.apart == Apart::Gap) {
    fill_gap(f, q.level, AxisOverlap<T>{least, overlap[least], 0}, r);
  } else if (r.status == Status::Separated) {
    fill_separated(f, q.level, r, find);
  } else if (q.level >= Level::Contact) {
    // The same arithmetic again on one axis, now keeping the deep vertex.
    fill_from_axis(f, q.level, overlap_on_axis(f, least), r);
  } else {
    fill_from_axis(f, q.level, AxisOverlap<T>{least, overlap[least], 0}, r);
  }
  fill_manifold(f, q,
                pick_reference(AxisOverlap<T>{best_a, overlap[best_a], 0},
                               AxisOverlap<T>{best_b, overlap[best_b], 0}, q.face_hysteresis),
                r);
  return r;
}

}  // namespace dyop::detail
