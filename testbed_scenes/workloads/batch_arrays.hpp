#pragma once
/// \file
/// Pairs as the batch kernel (`dyop/batch.hpp`) takes them: one array per coordinate (structure
/// of arrays), with the output arrays beside them, owned together. Every caller of
/// `penetrate_batch` in the testbed, the benchmarks and the fuzzers fills one of these.

#include <cstddef>
#include <vector>

#include "dyop/batch.hpp"

namespace dyop::workloads {

template <class T>
class BatchArrays {
 public:
  /// `rows` pairs; `vertex(k, side, i)` gives vertex `i` of pair `k`'s A (`side` 0) or B (1) as
  /// a `Vec2<T>`, in world coordinates, any winding.
  template <class VertexOf>
  BatchArrays(std::size_t rows, VertexOf vertex)
      : status(rows), separation(rows), normal_x(rows), normal_y(rows) {
    for (auto& c : coords_) c.resize(rows);
    for (std::size_t k = 0; k < rows; ++k) {
      for (int side = 0; side < 2; ++side) {
        for (int i = 0; i < 3; ++i) {
          const Vec2<T> v = vertex(k, side, i);
          coords_[6 * side + 2 * i][k] = v.x();
          coords_[6 * side + 2 * i + 1][k] = v.y();
        }
      }
    }
  }

  /// The input, row k being pair k.
  PairBatch<T> pairs() const {
    const auto& c = coords_;
    return {c[0].data(),  c[1].data(),  c[2].data(),  c[3].data(), c[4].data(),
            c[5].data(),  c[6].data(),  c[7].data(),  c[8].data(), c[9].data(),
            c[10].data(), c[11].data(), status.size()};
  }

  /// Where `penetrate_batch` writes: the arrays below.
  BatchOutput<T> out() {
    return {status.data(), separation.data(), normal_x.data(), normal_y.data()};
  }

  std::vector<Status> status;  ///< per row, written by `penetrate_batch`
  std::vector<T> separation;   ///< per row (Level::Depth)
  std::vector<T> normal_x;     ///< per row (Level::Depth)
  std::vector<T> normal_y;     ///< per row (Level::Depth)

 private:
  std::vector<T> coords_[12];  // ax0, ay0, ax1, ay1, ax2, ay2, then B's likewise
};

}  // namespace dyop::workloads
