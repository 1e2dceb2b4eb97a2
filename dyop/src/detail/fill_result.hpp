#pragma once
// Internal: filling a method's `Result` from what it found (the axis it settled on, or a proof
// of separation), computing only what the query's level asks for. One set of helpers serves
// every method.

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>
#if defined(__SSE2__)
#include <xmmintrin.h>
#endif

#include "detail/axis_overlap.hpp"
#include "detail/clip_manifold.hpp"
#include "detail/closest_features.hpp"
#include "dyop/result.hpp"

namespace dyop::detail {

template <class T>
inline T touching_band(const PairFrame<T>& f) {
  return touching_tolerance<T>() * f.scale;
}

// The level whose fields a query fills besides the manifold: a manifold without witnesses
// (`Query::witnesses` false) fills only the Depth level's (the manifold is filled on its own).
template <class T>
inline Level fields_level(const Query<T>& q) {
  return q.level == Level::Manifold && !q.witnesses ? Level::Depth : q.level;
}

// Status of a signed overlap (positive: penetrating) against the touching band: counted, not
// branched on (which status a random pair has is not predictable).
template <class T>
inline Status status_of_overlap(T overlap, T band) {
  static_assert(static_cast<int>(Status::Separated) == 0 &&
                static_cast<int>(Status::Touching) == 1 &&
                static_cast<int>(Status::Penetrating) == 2);
  const int above = static_cast<int>(overlap >= -band) + static_cast<int>(overlap > band);
  return static_cast<Status>(above);
}

// The touching band to judge `overlap` by, with the shapes' sizes measured only where it matters:
// `bound_band` (the band of an upper bound on the pair's scale, free to read) where `overlap` lies
// beyond it, since `status_of_overlap` then gives the status the exact band gives; the exact band
// (`exact_band()`, which measures) where it lies within, and wherever `needed` (another reader).
// So the band returned is the exact one whenever the status is `Touching`.
template <class T, class ExactBand>
[[gnu::always_inline]] inline T status_band(T overlap, T bound_band, bool needed,
                                            const ExactBand& exact_band) {
  return needed || !(std::abs(overlap) > bound_band) ? exact_band() : bound_band;
}

template <class T>
inline Feature input_feature(const Triangle<T>& t, Feature f) {
  if (f.type == Feature::Type::Vertex) f.index = static_cast<std::uint8_t>(t.input_vertex(f.index));
  if (f.type == Feature::Type::Edge) f.index = static_cast<std::uint8_t>(t.input_edge(f.index));
  return f;
}

// The Depth level's fields of a touching or penetrating pair answered by axis `ax` (its overlap
// is the depth). Always inlined: as a call it cost a Depth query about 6 % of its time (measured:
// docs/measurements.md, "Choices in the code").
template <class T>
[[gnu::always_inline]] inline void fill_depth_from_axis(const PairFrame<T>& f,
                                                        const AxisOverlap<T>& ax, Result<T>& r) {
  r.separation = -ax.overlap;
  r.depth = ax.overlap > 0 ? ax.overlap : T(0);
  r.normal = f.axis(ax.axis);
}

// A touching or penetrating pair answered by axis `ax`: the fields of `level`.
template <class T>
void fill_from_axis(const PairFrame<T>& f, Level level, const AxisOverlap<T>& ax, Result<T>& r) {
  if (level == Level::Overlap) return;
  fill_depth_from_axis(f, ax, r);
  if (level == Level::Depth) return;
  const Vec2<T> u = r.normal;
  if (ax.axis < 3) {  // A's face, B's deepest vertex
    const Vec2<T>& deep = f.b[ax.deep];
    r.witness_b = deep + f.origin;
    r.witness_a = deep + ax.overlap * u + f.origin;
    r.feature_a = input_feature(f.ta, {Feature::Type::Edge, static_cast<std::uint8_t>(ax.axis)});
    r.feature_b = input_feature(f.tb, {Feature::Type::Vertex, static_cast<std::uint8_t>(ax.deep)});
  } else {  // B's face, A's deepest vertex
    const Vec2<T>& deep = f.a[ax.deep];
    r.witness_a = deep + f.origin;
    r.witness_b = deep - ax.overlap * u + f.origin;
    r.feature_a = input_feature(f.ta, {Feature::Type::Vertex, static_cast<std::uint8_t>(ax.deep)});
    r.feature_b =
        input_feature(f.tb, {Feature::Type::Edge, static_cast<std::uint8_t>(ax.axis - 3)});
  }
}

// A pair proven apart, with its closest features `c`: distance and witnesses as the level asks.
template <class T>
void fill_closest(const PairFrame<T>& f, Level level, const Closest<T>& c, Result<T>& r) {
  r.status = Status::Separated;
  if (level == Level::Overlap) return;
  r.separation = c.distance;
  r.depth = 0;
  r.normal = c.normal;
  if (level == Level::Depth) return;
  r.witness_a = c.point_a + f.origin;
  r.witness_b = c.point_b + f.origin;
  r.feature_a = input_feature(f.ta, c.feature_a);
  r.feature_b = input_feature(f.tb, c.feature_b);
}

// A pair apart, answered with the gap along its least axis `ax` alone (`Apart::Gap`): no
// distance, witnesses or features. The gap is `-ax.overlap`, at least 0: a pair proven apart by
// its distance while its least overlap lies in the touching band may have a rounded overlap of
// either sign there.
template <class T>
void fill_gap(const PairFrame<T>& f, Level level, const AxisOverlap<T>& ax, Result<T>& r) {
  r.status = Status::Separated;
  if (level == Level::Overlap) return;
  r.separation = std::max(T(0), -ax.overlap);
  r.depth = 0;
  r.normal = f.axis(ax.axis);
}

// A pair proven apart whose closest features are still to be found, by `find` (by default all
// 18 vertex–edge pairs), only when the level asks for more than the status.
template <class T, class Find = AllFeatures<T>>
void fill_separated(const PairFrame<T>& f, Level level, Result<T>& r, const Find& find = {}) {
  r.status = Status::Separated;
  if (level == Level::Overlap) return;
  fill_closest(f, level, find(f), r);
}

// Box2D's reference-face rule: B's best face only when it beats A's by more than the hysteresis.
// Field by field, by selects: whose face it is does not predict.
template <class T>
inline AxisOverlap<T> pick_reference(const AxisOverlap<T>& best_a, const AxisOverlap<T>& best_b,
                                     T hysteresis) {
  const bool b = best_b.overlap < best_a.overlap - hysteresis;
  return {select_index(b, best_b.axis, best_a.axis), b ? best_b.overlap : best_a.overlap,
          select_index(b, best_b.deep, best_a.deep)};
}

// Box2D's reference face from all six overlaps: each triangle's best face, then the hysteresis.
template <class T>
inline AxisOverlap<T> reference_face(const std::array<T, 6>& overlap, T hysteresis) {
  const int a = argmin3(overlap, 0);
  const int b = argmin3(overlap, 3);
  return pick_reference(AxisOverlap<T>{a, overlap[a], 0}, AxisOverlap<T>{b, overlap[b], 0},
                        hysteresis);
}

// An axis of the other shape whose direction (A to B) meets the reference face's at a cosine
// above this lies flush with it for `Manifold::lead` (about 1.1°). Why: two faces lying flush
// give the same depth; as the pair moves their overlaps part by at most 0.02 of its shift, and as
// it turns by what the turn moves any face.
template <class T>
constexpr T flush_cosine() {
  return T(1) - T(2e-4);
}

// Bit k set: `overlap[k] < limit`. Four lanes at a time for float arrays of an even size (the
// last two lanes of a size not a multiple of four loaded alone).
template <std::size_t Max, class T>
unsigned below(const std::array<T, Max>& overlap, T limit) {
#if defined(__SSE2__)
  if constexpr (std::is_same_v<T, float> && Max % 2 == 0) {
    const __m128 l = _mm_set1_ps(limit);
    unsigned bits = 0;
    std::size_t k = 0;
    for (; k + 4 <= Max; k += 4) {
      const __m128 lt = _mm_cmplt_ps(_mm_loadu_ps(overlap.data() + k), l);
      bits |= static_cast<unsigned>(_mm_movemask_ps(lt)) << k;
    }
    if (k < Max) {
      const __m128 two =
          _mm_loadl_pi(_mm_setzero_ps(), reinterpret_cast<const __m64*>(overlap.data() + k));
      bits |= (static_cast<unsigned>(_mm_movemask_ps(_mm_cmplt_ps(two, l))) & 3u) << k;
    }
    return bits;
  }
#endif
  unsigned bits = 0;
  for (std::size_t k = 0; k < Max; ++k) bits |= static_cast<unsigned>(overlap[k] < limit) << k;
  return bits;
}

// `Manifold::lead` of a manifold on axis `reference` of frame `f` (axes 0..`count_a` − 1 are A's,
// then B's up to `count` ≤ `Max`): the least overlap of the other axes set in `axes`, but the
// other shape's lying flush with the face (`flush_cosine`), minus the face's; +infinity for none,
// and for a lead of `reach` or more (`Query::lead_reach`): only axes within it are looked at.
template <std::size_t Max, class F, class T>
T lead_over(const F& f, const std::array<T, Max>& overlap, int count_a, int count, unsigned axes,
            int reference, T reach) {
  const T face = overlap[reference];
  const unsigned near =
      below(overlap, face + reach) & axes & ~(1u << reference) & ((1u << count) - 1);
  T lead = std::numeric_limits<T>::infinity();
  if (near == 0) return lead;
  const Vec2<T> u = f.axis(reference);
  const bool on_a = reference < count_a;
  for (int k = 0; k < count; ++k) {
    if (((near >> k) & 1u) == 0) continue;
    const bool flush = ((k < count_a) != on_a) && u.dot(f.axis(k)) >= flush_cosine<T>();
    if (!flush) lead = std::min(lead, overlap[k] - face);
  }
  return lead;
}

// The manifold on `reference`, when its separation is within the margin.
template <class T>
void fill_manifold(const PairFrame<T>& f, const Query<T>& q, const AxisOverlap<T>& reference,
                   Result<T>& r) {
  if (q.level != Level::Manifold) return;
  if (-reference.overlap > q.margin) {
    set_reference_face(f, reference.axis, r.manifold);
  } else {
    clip_manifold(f, reference.axis, q.margin, r.manifold);
  }
}

// The whole answer of a method that settles on one axis (`ax.overlap` > 0: penetrating); the
// manifold, when asked for, is built on that axis's face.
template <class T>
Result<T> answer_from_axis(const PairFrame<T>& f, const Query<T>& q, const AxisOverlap<T>& ax) {
  Result<T> r;
  r.status = status_of_overlap(ax.overlap, touching_band(f));
  fill_from_axis(f, q.level, ax, r);
  fill_manifold(f, q, ax, r);
  return r;
}

}  // namespace dyop::detail
