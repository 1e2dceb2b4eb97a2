#pragma once
// Prepared inputs for timing: the pairs of an input class as valid triangles of one precision,
// with what each method needs ready beforehand (as a simulation has its shapes ready), so that a
// timed loop does nothing but the narrow phase.

#include <cstdint>
#include <vector>

#include "dyop/lin_canny.hpp"
#include "dyop/method.hpp"
#include "workloads/input_classes.hpp"

namespace dyop::workloads {

/// One input class in precision T (`make_pairs` for T). Pairs whose triangles are invalid in T (a
/// float-degenerate sliver) are left out; `raw` keeps the kept pairs, rounded to T, for the exact
/// reference.
template <class T>
struct PairSet {
  std::vector<RawPair> raw;    ///< the kept pairs as T sees them (rounded to T)
  std::vector<Triangle<T>> a;  ///< A of each pair
  std::vector<Triangle<T>> b;  ///< B of each pair
  std::vector<Triangle<T>>
      b_next;  ///< B after a small rigid motion: the next frame, for warm starts
  std::size_t size() const { return a.size(); }
};

template <class T>
PairSet<T> make_pair_set(InputClass c, int count, std::uint64_t seed);

extern template PairSet<float> make_pair_set(InputClass, int, std::uint64_t);
extern template PairSet<double> make_pair_set(InputClass, int, std::uint64_t);

}  // namespace dyop::workloads
