#pragma once
// Internal: the overlap of a pair along one candidate axis of the Minkowski difference.

#if defined(__SSE2__)
#include <xmmintrin.h>
#endif

#include "detail/pair_frame.hpp"

namespace dyop::detail {

template <class T>
struct AxisOverlap {
  int axis = -1;  // 0..2: A's edge `axis`; 3..5: B's edge `axis - 3`
  T overlap = 0;  // max_A(u·a) − min_B(u·b) for u = frame.axis(axis); negative: apart
  int deep = 0;   // CCW index of the other triangle's vertex that realises it
};

// The least of three (first on ties) and the two comparisons that found it.
template <class T>
struct Least3 {
  T value;
  bool one;  // d1 < d0
  bool two;  // d2 < min(d0, d1): the least is d2
};

template <class T>
inline Least3<T> least3(T d0, T d1, T d2) {
  const bool one = d1 < d0;
  const T m = one ? d1 : d0;
  const bool two = d2 < m;
  return {two ? d2 : m, one, two};
}

// `pick ? a : b` for indices, by masks: GCC compiles an int ternary to a branch.
inline int select_index(bool pick, int a, int b) {
  const int mask = -static_cast<int>(pick);
  return (a & mask) | (b & ~mask);
}

// Index and value of the smallest of three (first on ties), without a branch on the data: which
// of three random values is least is a coin toss no predictor can learn, except one that has seen
// the same inputs in the same order before. Over a repeated set of 8192 random pairs the AMD EPYC
// (AVX-512) host learned such branches and a branchy index looked faster; over 131,072 pairs the
// per-pair path with its branches cost `dyop` Depth 38.5 ns, without them 24.8 ns (docs/design.md,
// "Per pair").
template <class T>
inline void min3(T d0, T d1, T d2, T& value, int& index) {
  const Least3<T> l = least3(d0, d1, d2);
  value = l.value;
  index = select_index(l.two, 2, static_cast<int>(l.one));
}

// All six overlaps (index k as in `AxisOverlap::axis`), without the deep vertices: what the
// Depth level needs, computed with no branch on the data.
template <class T>
inline std::array<T, 6> all_overlaps(const PairFrame<T>& f) {
  std::array<T, 6> out;
  for (int i = 0; i < 3; ++i) {
    const Vec2<T>& n = f.ta.normal(i);
    out[i] = n.dot(f.a[i]) - std::min(std::min(n.dot(f.b[0]), n.dot(f.b[1])), n.dot(f.b[2]));
  }
  for (int j = 0; j < 3; ++j) {
    const Vec2<T>& n = f.tb.normal(j);
    out[3 + j] = n.dot(f.b[j]) - std::min(std::min(n.dot(f.a[0]), n.dot(f.a[1])), n.dot(f.a[2]));
  }
  return out;
}

#if defined(__SSE2__)
// One triangle's edge normals against the pair's vertices, its edge i in lane i: the products the
// float `all_overlaps` and the rule's `edge_bits` start from.
struct LaneProducts {
  __m128 line;      // n_i · (own vertex i)
  __m128 along[3];  // n_i · (other vertex w), for w = 0, 1, 2
};

inline LaneProducts lane_products(const Triangle<float>& t, const std::array<Vec2<float>, 3>& own,
                                  const std::array<Vec2<float>, 3>& other) {
  const __m128 nx = _mm_setr_ps(t.normal(0).x(), t.normal(1).x(), t.normal(2).x(), 0.0f);
  const __m128 ny = _mm_setr_ps(t.normal(0).y(), t.normal(1).y(), t.normal(2).y(), 0.0f);
  const auto along = [&](const __m128& x, const __m128& y) {
    return _mm_add_ps(_mm_mul_ps(nx, x), _mm_mul_ps(ny, y));
  };
  LaneProducts p;
  p.line = along(_mm_setr_ps(own[0].x(), own[1].x(), own[2].x(), 0.0f),
                 _mm_setr_ps(own[0].y(), own[1].y(), own[2].y(), 0.0f));
  for (int w = 0; w < 3; ++w) {
    p.along[w] = along(_mm_set1_ps(other[w].x()), _mm_set1_ps(other[w].y()));
  }
  return p;
}

// The same for float, each triangle's three axes in the lanes of one SSE register: the same
// products, sums and minima in the same order (`std::min(x, y)` is `_mm_min_ps(y, x)`, to the
// sign of a zero), so the same bits (tested against the generic one).
inline std::array<float, 6> all_overlaps(const PairFrame<float>& f) {
  const auto overlaps = [](const LaneProducts& p) {
    return _mm_sub_ps(p.line, _mm_min_ps(p.along[2], _mm_min_ps(p.along[1], p.along[0])));
  };
  alignas(16) float a[4];
  alignas(16) float b[4];
  _mm_store_ps(a, overlaps(lane_products(f.ta, f.a, f.b)));
  _mm_store_ps(b, overlaps(lane_products(f.tb, f.b, f.a)));
  return {a[0], a[1], a[2], b[0], b[1], b[2]};
}
#endif

// Index of the least of v[first], v[first+1], v[first+2] (the first on ties).
template <class T>
inline int argmin3(const std::array<T, 6>& v, int first) {
  T least;
  int index;
  min3(v[first], v[first + 1], v[first + 2], least, index);
  return first + index;
}

// The sine of the largest angle between an edge and the face of an axis at which the edge still
// lies flat on that face (`realised_inside`). Why 1e-3: a body resting or gliding on a flat ground
// turns by about 1e-6 rad from rounding alone, which must not decide whether its outline face
// answers; a body tipped by a step is turned by 1e-2 rad and more, and a face so turned is not
// flat (along it, 1e-3 rad is 0.25 mm of depth over a 0.25 m edge: far below Box2D's 5 mm slop).
template <class T>
constexpr T flat_face_sine() {
  return T(1e-3);
}

// True when an axis along which the other shape's vertices `v[0..count)` project to `d` (the
// same index) is realised inside the other body: at its deepest vertex (the least projection,
// first on ties) when that vertex is closed (its bit set in `closed`), unless an edge of the
// other shape at that vertex is an outline edge (its bit clear in `internal`: bit j for the edge
// from vertex j to j + 1, modulo `count`) lying flat on the axis's face (`flat_face_sine`): the
// axis is then realised along that outline face as well, and which of its ends a rounding made
// the deepest does not decide whether the pair answers.
template <class T, class V>
bool realised_inside(const T* d, const V* v, int count, unsigned closed, unsigned internal) {
  if (closed == 0) return false;
  int deep = 0;
  for (int w = 1; w < count; ++w) deep = d[w] < d[deep] ? w : deep;
  if (((closed >> deep) & 1u) == 0) return false;
  const T sine = flat_face_sine<T>();
  const auto flat_outline = [&](int edge, int end) {
    const T rise = d[end] - d[deep];
    return ((internal >> edge) & 1u) == 0 &&
           rise * rise <= sine * sine * (v[end] - v[deep]).squaredNorm();
  };
  const int after = deep + 1 == count ? 0 : deep + 1;
  const int before = deep == 0 ? count - 1 : deep - 1;
  if (flat_outline(deep, after) || flat_outline(before, before)) return false;
  return true;
}

// Axis k (as `AxisOverlap::axis`) with the other triangle's deepest vertex. Axis of A's edge i:
// the edge line is A's support, overlap = n_i·a_i − min_B(n_i·b). Axis of B's edge j (u = −n_j):
// overlap = n_j·b_j − min_A(n_j·a), the deep vertex A's. The face's triangle and the other's
// vertices are selected, not branched on: whose face a random pair settles on does not predict.
template <class T>
inline AxisOverlap<T> overlap_on_axis(const PairFrame<T>& f, int k) {
  // Looked up by index: GCC compiles a choice between references to a branch.
  const Triangle<T>* const face_triangle[2] = {&f.ta, &f.tb};
  const std::array<Vec2<T>, 3>* const vertices[2] = {&f.a, &f.b};
  const int on_b = static_cast<int>(k >= 3);
  const int e = k - 3 * on_b;
  const Vec2<T>& n = face_triangle[on_b]->normal(e);
  const std::array<Vec2<T>, 3>& own = *vertices[on_b];
  const std::array<Vec2<T>, 3>& other = *vertices[1 - on_b];
  AxisOverlap<T> r;
  r.axis = k;
  T least;
  min3(n.dot(other[0]), n.dot(other[1]), n.dot(other[2]), least, r.deep);
  r.overlap = n.dot(own[e]) - least;
  return r;
}

}  // namespace dyop::detail
