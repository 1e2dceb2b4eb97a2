#pragma once
// Internal to the paper experiment and scene (scenes/paper_*.cpp): every method behind one
// signature, and the timing harness that runs one over the pairs of a step.

#include <vector>

#include "adapters/narrow_phase.hpp"
#include "dyop/method.hpp"
#include "exact_reference/exact_reference.hpp"
#include "scenes/paper.hpp"

namespace dyop::scenes::paper {

// The paper asks for penetration depths: pairs apart need only the proof (`Apart::Gap`).
inline constexpr Query<float> depth_query{Level::Depth, 0, 0, Apart::Gap};

// One method of the experiment behind one call, so that all are called alike (one indirect call
// each): its single-pair entry point, started from the pair's cache when warm.
struct PairCall {
  PairFunction<float> run = nullptr;
  bool warm = false;
  Result<float> operator()(const Triangle<float>& a, const Triangle<float>& b,
                           PairState* cache) const {
    return run(a, b, depth_query, warm ? cache : nullptr);
  }
};

/// `p`'s call.
PairCall pair_call(const adapters::NarrowPhase& p);

/// The index of the pair of types `i` < `j`, in 0 … `pair_count` - 1.
int pair_index(int i, int j);

/// One call of the narrow phase: a pair of one step.
struct Job {
  const Triangle<float>* a;  ///< A, in the step's frame
  const Triangle<float>* b;  ///< B, in the step's frame
  int pair;                  ///< `pair_index` of the two types (its warm-start cache)
};

/// Wall time of `jobs` through `call` in microseconds; `caches` (one per pair) start from `start`.
double time_jobs(const std::vector<Job>& jobs, const PairCall& call, std::vector<PairState>& caches,
                 const std::vector<PairState>& start);

/// The exact signed separation of a pair, on the float vertices the methods were given.
workloads::ExactAnswer exact_of(const Triangle<float>& a, const Triangle<float>& b);

/// The touching band of a pair: `touching_tolerance` scaled by the larger triangle.
double band_of(const Triangle<float>& a, const Triangle<float>& b);

}  // namespace dyop::scenes::paper
