#pragma once
// Internal: a pair of triangles moved into a common local frame.
//
// Every method subtracts A's first CCW vertex from all six vertices before any arithmetic, so the
// rounding error of a dot product is relative to the pair's extent, not to the distance from the
// world origin (a pair a million units away is as accurate as one at the origin). Results are
// moved back by adding `origin`.

#include <algorithm>
#include <array>

#include "dyop/triangle.hpp"

namespace dyop::detail {

template <class T>
struct PairFrame {
  const Triangle<T>& ta;
  const Triangle<T>& tb;
  Vec2<T> origin;
  std::array<Vec2<T>, 3> a;  // A's CCW vertices, local
  std::array<Vec2<T>, 3> b;  // B's CCW vertices, local
  T scale;                   // the larger triangle's size: unit of relative tolerances

  PairFrame(const Triangle<T>& ta_, const Triangle<T>& tb_)
      : ta(ta_), tb(tb_), origin(ta_.vertex(0)), scale(std::max(ta_.size(), tb_.size())) {
    for (int i = 0; i < 3; ++i) {
      a[i] = ta.vertex(i) - origin;
      b[i] = tb.vertex(i) - origin;
    }
  }

  // Axis k: 0..2 are A's edge normals, 3..5 B's negated edge normals. `axis(k)` points from A to B.
  // Selected by index and sign, not branched on: whose face a random pair settles on does not
  // predict (n·(−1) is −n bit for bit).
  Vec2<T> axis(int k) const {
    static constexpr T kSign[2] = {T(1), T(-1)};
    const bool on_b = k >= 3;
    return (on_b ? tb : ta).normal(k - 3 * static_cast<int>(on_b)) * kSign[on_b];
  }
};

// The next index around a triangle, looked up: a branch on `i == 2` mispredicts on random pairs.
inline int next3(int i) {
  static constexpr int kNext[3] = {1, 2, 0};
  return kNext[i];
}

}  // namespace dyop::detail
