#pragma once
// Internal: exact penetration depth by certifying all six candidate axes.
//
// `sat` and `dyop` share this, so both are exact and their depths bit-identical. The six overlaps
// are computed together, lane-wise and without branches on the data: on two triangles that is
// cheaper than trying the axes one by one in any order. `find` locates the closest features of a
// pair found apart (dyop passes its pivot's guess, certified; sat passes the full search).

#include "detail/allowed_axes.hpp"
#include "detail/fill_result.hpp"

namespace dyop::detail {

// The status from the least overlap of all six axes (`least`); a pair found apart is answered
// whole here (true), a touching or penetrating one is left to the caller (false).
// Always inlined: the plain path then costs what it did before the allowed-axes rule split it
// up (measured: docs/measurements.md, "Choices in the code").
template <class T, class Find>
[[gnu::always_inline]] inline bool answer_if_apart(const PairFrame<T>& f, const Query<T>& q,
                                                   const std::array<T, 6>& overlap, int least,
                                                   const Find& find, Result<T>& r) {
  const T band = touching_band(f);
  const Level level = fields_level(q);
  r.status = status_of_overlap(overlap[least], band);
  // A least overlap inside the band proves only that the pair does not overlap by more than the
  // band: a gap along an edge normal can be far less than the distance (two slivers end to end),
  // and a gap far below the coordinates' rounding comes out as a small overlap of either sign
  // (slivers 1e148 long, 3e139 apart end to end: found by fuzz_batch and fuzz_sat), so the
  // distance decides.
  // With `Apart::Gap` a pair the distance proves apart is still answered with its gap (at least
  // 0), as every other pair apart: `separation` then exceeds the margin exactly when the least
  // overlap is below `-margin`, where the masks are not read (`certify_axes`), so a caller may
  // run a pair without masks first and find them only when that answer is not apart beyond it.
  const bool gap_in_band = r.status == Status::Touching;
  const Closest<T> near = gap_in_band ? find(f) : Closest<T>{};
  const bool apart_in_band = gap_in_band && near.distance > band;
  if (apart_in_band && q.apart == Apart::Distance) {
    fill_closest(f, level, near, r);
  } else if ((apart_in_band || r.status == Status::Separated) && q.apart == Apart::Gap) {
    fill_gap(f, level, AxisOverlap<T>{least, overlap[least], 0}, r);
  } else if (r.status == Status::Separated) {
    fill_separated(f, level, r, find);
  } else {
    return false;
  }
  return true;
}

// A touching or penetrating pair answered on axis `axis`.
template <class T>
[[gnu::always_inline]] inline void answer_on_axis(const PairFrame<T>& f, Level level,
                                                  const std::array<T, 6>& overlap, int axis,
                                                  Result<T>& r) {
  if (level >= Level::Contact) {
    // The same arithmetic again on one axis, now keeping the deep vertex.
    fill_from_axis(f, level, overlap_on_axis(f, axis), r);
  } else if (level == Level::Depth) {
    fill_depth_from_axis(f, AxisOverlap<T>{axis, overlap[axis], 0}, r);
  }
}

// The answer when the masks refuse the plain one (`Query::internal_edges`), into `r` (as
// default-initialised): the status over all six axes, the depth, normal and reference face over
// the usable ones.
template <class T, class Find>
[[gnu::noinline]] void certify_allowed_axes(const PairFrame<T>& f, const Query<T>& q,
                                            const std::array<T, 6>& overlap, const Find& find,
                                            Result<T>& r) {
  const AllowedAxes<T> allowed = allowed_axes(f, q, overlap);
  if (!answer_if_apart(f, q, overlap, allowed.least, find, r)) {
    const int axis = allowed.any() ? allowed.least_usable_axis() : allowed.least;
    answer_on_axis(f, fields_level(q), overlap, axis, r);
  }
  if (q.level != Level::Manifold) return;
  // No usable axis: no contact from this pair (another pair of the two bodies carries it), and
  // the face fields name the least axis.
  if (!allowed.any()) {
    set_reference_face(f, allowed.least, r.manifold);
    return;
  }
  const AxisOverlap<T> reference = allowed.reference(q.face_hysteresis);
  fill_manifold(f, q, reference, r);
  if (r.manifold.point_count > 0) {
    r.manifold.lead = lead_over(f, overlap, 3, 6, allowed.usable, reference.axis, q.lead_reach);
  }
}

template <class T, class Find = AllFeatures<T>>
Result<T> certify_axes(const PairFrame<T>& f, const Query<T>& q, const Find& find = {}) {
  const std::array<T, 6> overlap = all_overlaps(f);
  Result<T> r;
  const int best_a = argmin3(overlap, 0);
  const int best_b = argmin3(overlap, 3);
  const int least = select_index(overlap[best_b] < overlap[best_a], best_b, best_a);  // ties: A's
  const AxisOverlap<T> reference =
      pick_reference(AxisOverlap<T>{best_a, overlap[best_a], 0},
                     AxisOverlap<T>{best_b, overlap[best_b], 0}, q.face_hysteresis);
  // With masks, the plain answer stands when the pair is apart beyond the margin (the status,
  // gap and normal are decided over all six axes, and the manifold is empty either way), or when
  // the masks allow the axis of its depth and normal (`least`) and its reference face: the push is
  // then the least of all, along a direction the outline allows, and whether the other triangle
  // reaches that edge does not matter (an edge it does not reach is refused only as a larger
  // push through the body). Otherwise the full rule, out of line. A pyramid of split boxes has
  // masks on every pair: one or two mask checks each keep it near the plain cost (measured:
  // docs/measurements.md, "Choices in the code").
  if (q.internal_edges.any() && overlap[least] >= -q.margin &&
      !(axis_allowed(f, q, least) &&
        (reference.axis == least || axis_allowed(f, q, reference.axis)))) {
    // Filled, not returned: one named result on every path keeps the return value optimisation
    // of the plain path (measured: docs/measurements.md, "Choices in the code").
    certify_allowed_axes(f, q, overlap, find, r);
    return r;
  }
  if (!answer_if_apart(f, q, overlap, least, find, r)) {
    answer_on_axis(f, fields_level(q), overlap, least, r);
  }
  fill_manifold(f, q, reference, r);
  if (r.manifold.point_count > 0) {
    r.manifold.lead = lead_over(f, overlap, 3, 6, 63u, reference.axis, q.lead_reach);
  }
  return r;
}

}  // namespace dyop::detail
