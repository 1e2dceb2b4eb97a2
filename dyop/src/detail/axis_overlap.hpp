#pragma once
// Internal: the overlap of a pair along one candidate axis of the Minkowski difference.

#include "detail/pair_frame.hpp"

namespace dyop::detail {

template <class T>
struct AxisOverlap {
  int axis = -1;    // 0..2: A's edge `axis`; 3..5: B's edge `axis - 3`
  T overlap = 0;    // max_A(u·a) − min_B(u·b) for u = frame.axis(axis); negative: apart
  int deep = 0;     // CCW index of the other triangle's vertex that realises it
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

// Index and value of the smallest of three (first on ties). GCC compiles the index to branches:
// where a long chain waits on it (the axis a Depth query settles on, then its overlap, status and
// normal) a predicted branch lets the chain start early, and that wins even though random pairs
// mispredict it about once per query (measured: 19 ns per Depth query, 32 ns with `min3_select`).
template <class T>
inline void min3(T d0, T d1, T d2, T& value, int& index) {
  const Least3<T> l = least3(d0, d1, d2);
  value = l.value;
  index = l.two ? 2 : (l.one ? 1 : 0);
}

// `pick ? a : b` for indices, by masks: GCC compiles an int ternary to a branch.
inline int select_index(bool pick, int a, int b) {
  const int mask = -static_cast<int>(pick);
  return (a & mask) | (b & ~mask);
}

// `min3` without branches, where little waits on the index and its outcome is unpredictable (a
// manifold's incident edge, the deep vertex of the chosen axis: with `min3` a Manifold query
// mispredicts 4.9 times, with this 2.1 times, and takes 53 ns instead of 65).
template <class T>
inline void min3_select(T d0, T d1, T d2, T& value, int& index) {
  const Least3<T> l = least3(d0, d1, d2);
  value = l.value;
  index = select_index(l.two, 2, static_cast<int>(l.one));
}

// Axis of A's edge i: the edge line is A's support; B's deepest vertex is the least along n.
template <class T>
inline AxisOverlap<T> overlap_on_a_edge(const PairFrame<T>& f, int i) {
  const Vec2<T>& n = f.ta.normal(i);
  AxisOverlap<T> r;
  r.axis = i;
  T least;
  min3_select(n.dot(f.b[0]), n.dot(f.b[1]), n.dot(f.b[2]), least, r.deep);
  r.overlap = n.dot(f.a[i]) - least;
  return r;
}

// Axis of B's edge j (u = −n_j): overlap = n_j·b_j − min_A(n_j·a); the deep vertex is A's.
template <class T>
inline AxisOverlap<T> overlap_on_b_edge(const PairFrame<T>& f, int j) {
  const Vec2<T>& n = f.tb.normal(j);
  AxisOverlap<T> r;
  r.axis = 3 + j;
  T least;
  min3_select(n.dot(f.a[0]), n.dot(f.a[1]), n.dot(f.a[2]), least, r.deep);
  r.overlap = n.dot(f.b[j]) - least;
  return r;
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

// Index of the least of v[first], v[first+1], v[first+2] (the first on ties).
template <class T>
inline int argmin3(const std::array<T, 6>& v, int first) {
  T least;
  int index;
  min3(v[first], v[first + 1], v[first + 2], least, index);
  return first + index;
}

template <class T>
inline AxisOverlap<T> overlap_on_axis(const PairFrame<T>& f, int k) {
  return k < 3 ? overlap_on_a_edge(f, k) : overlap_on_b_edge(f, k - 3);
}

}  // namespace dyop::detail
