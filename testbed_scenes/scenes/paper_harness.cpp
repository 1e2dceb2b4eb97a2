// The paper experiment's timing harness: one method over the pairs of a step, timed as a whole.
#include "scenes/paper_harness.hpp"

#include <algorithm>
#include <chrono>

#include "adapters/pair_function.hpp"

namespace dyop::scenes::paper {
namespace {

// The result of summing depths is stored here so that the timed calls cannot be optimised away.
volatile double g_sink = 0;

}  // namespace

PairCall pair_call(const adapters::NarrowPhase& p) {
  return {adapters::pair_function<float>(p), p.method && p.method->warm};
}

int pair_index(int i, int j) { return i * (2 * type_count - i - 1) / 2 + (j - i - 1); }

double time_jobs(const std::vector<Job>& jobs, const PairCall& call, std::vector<PairState>& caches,
                 const std::vector<PairState>& start) {
  caches = start;
  double sink = 0;
  const auto t0 = std::chrono::steady_clock::now();
  for (const Job& j : jobs) sink += call(*j.a, *j.b, &caches[j.pair]).depth;
  const auto t1 = std::chrono::steady_clock::now();
  g_sink = sink;
  return std::chrono::duration<double, std::micro>(t1 - t0).count();
}

workloads::ExactAnswer exact_of(const Triangle<float>& a, const Triangle<float>& b) {
  workloads::RawPair p;
  for (int i = 0; i < 3; ++i) {
    p.a[i] = a.vertex(i).cast<double>();
    p.b[i] = b.vertex(i).cast<double>();
  }
  return workloads::exact_separation(p);
}

double band_of(const Triangle<float>& a, const Triangle<float>& b) {
  return static_cast<double>(touching_tolerance<float>()) * std::max(a.size(), b.size());
}

}  // namespace dyop::scenes::paper
