#pragma once
// Internal to the paper experiment and scene (scenes/paper_*.cpp): every method behind one
// signature, and the timing harness that runs one over the pairs of a step.

#include <vector>

#include "dyop/lin_canny.hpp"
#include "exact_reference/exact_reference.hpp"
#include "scenes/paper.hpp"

namespace dyop::scenes::paper {

// Every method behind one signature, so that all are called alike (one indirect call each).
using Fn = Result<float> (*)(const Triangle<float>&, const Triangle<float>&, LinCannyCache*);

/// `m`'s entry point (paper_methods.cpp).
Fn fn_of(Method m);

/// The index of the pair of types `i` < `j`, in 0 … `pair_count` - 1.
int pair_index(int i, int j);

/// One call of the narrow phase: a pair of one step.
struct Job {
  const Triangle<float>* a;  ///< A, in the step's frame
  const Triangle<float>* b;  ///< B, in the step's frame
  int pair;                  ///< `pair_index` of the two types (its warm-start cache)
};

/// Wall time of `jobs` through `fn` in microseconds; `caches` (one per pair) start from `start`.
double time_jobs(const std::vector<Job>& jobs, Fn fn, std::vector<LinCannyCache>& caches,
                 const std::vector<LinCannyCache>& start);

/// The exact signed separation of a pair, on the float vertices the methods were given.
workloads::ExactAnswer exact_of(const Triangle<float>& a, const Triangle<float>& b);

/// The touching band of a pair: `touching_tolerance` scaled by the larger triangle.
double band_of(const Triangle<float>& a, const Triangle<float>& b);

}  // namespace dyop::scenes::paper
