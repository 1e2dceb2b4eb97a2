#include "experiments/stress_answers.hpp"

#include <algorithm>
#include <cmath>

#include "dyop/batch.hpp"
#include "dyop/method.hpp"
#include "adapters/pair_function.hpp"
#include "workloads/batch_arrays.hpp"
#include "workloads/finite_fields.hpp"

namespace dyop::experiments {

using adapters::pair_function;
using adapters::runs_pairs;
namespace {

using workloads::finite_at;

template <class T>
StressAnswer answer_of(const Result<T>& r, bool finite) {
  StressAnswer a;
  a.status = r.status;
  a.separation = static_cast<double>(r.separation);
  a.finite = finite;
  return a;
}

// A narrow phase that answers single pairs. Box2D's answer has `Level::Contact`'s fields
// whatever the query asks, and no manifold of the library's kind to check.
template <class T>
std::vector<StressAnswer> pair_answers(const adapters::NarrowPhase& p,
                                       const std::vector<workloads::RawPair>& pairs,
                                       bool with_manifold) {
  const PairFunction<T> run = pair_function<T>(p);
  const bool box2d = adapters::call_of(p) == adapters::Call::Box2D;
  std::vector<StressAnswer> out(pairs.size());
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    const auto t = workloads::build<T>(pairs[k]);
    if (!t.a.ok() || !t.b.ok()) continue;
    PairState cache;
    const Result<T> r = run(t.a.triangle, t.b.triangle, Query<T>{Level::Depth}, &cache);
    bool finite = finite_at(r, box2d ? Level::Contact : Level::Depth);
    if (with_manifold && !box2d) {
      // A speculative margin of a hundredth of the larger triangle, as Box2D's skins are to a
      // metre-sized body: separated pairs within it get a manifold too.
      Query<T> q{Level::Manifold};
      q.margin = T(0.01) * std::max(t.a.triangle.size(), t.b.triangle.size());
      finite = finite && finite_at(run(t.a.triangle, t.b.triangle, q, &cache), q.level);
    }
    out[k] = answer_of(r, finite);
  }
  return out;
}

template <class T>
std::vector<StressAnswer> batch_answers(const std::vector<workloads::RawPair>& pairs) {
  const std::size_t n = pairs.size();
  workloads::BatchArrays<T> arrays(n, [&](std::size_t k, int side, int i) {
    return (side == 0 ? pairs[k].a[i] : pairs[k].b[i]).template cast<T>().eval();
  });
  const PairBatch<T> batch = arrays.pairs();
  const std::vector<Status>& status = arrays.status;
  const std::vector<T>& separation = arrays.separation;
  const std::vector<T>& nx = arrays.normal_x;
  const std::vector<T>& ny = arrays.normal_y;
  std::vector<StressAnswer> out(n);
  if (penetrate_batch(batch, Level::Depth, arrays.out()) != BatchError::None) {
    for (StressAnswer& a : out) a.verdict_mismatch = true;
    return out;
  }
  for (std::size_t k = 0; k < n; ++k) {
    const auto t = workloads::build<T>(pairs[k]);
    const BatchRowError e = batch_row_error(batch, k);
    StressAnswer& a = out[k];
    a.verdict_mismatch = e.a != t.a.error || e.b != t.b.error ||
                         (status[k] == Status::Invalid) != !(t.a.ok() && t.b.ok());
    if (status[k] == Status::Invalid) continue;
    a.status = status[k];
    a.separation = static_cast<double>(separation[k]);
    a.finite = std::isfinite(separation[k]) && std::isfinite(nx[k]) && std::isfinite(ny[k]);
  }
  return out;
}

}  // namespace

bool stress_runs(const adapters::NarrowPhase& p, bool is_float) {
  return adapters::call_of(p) == adapters::Call::Batch ||
         (is_float ? runs_pairs<float>(p) : runs_pairs<double>(p));
}

template <class T>
std::vector<StressAnswer> stress_answers(const adapters::NarrowPhase& p,
                                         const std::vector<workloads::RawPair>& pairs,
                                         bool with_manifold) {
  if (adapters::call_of(p) == adapters::Call::Batch) return batch_answers<T>(pairs);
  if (!runs_pairs<T>(p)) return std::vector<StressAnswer>(pairs.size());
  return pair_answers<T>(p, pairs, with_manifold);
}

template std::vector<StressAnswer> stress_answers<float>(const adapters::NarrowPhase&,
                                                         const std::vector<workloads::RawPair>&,
                                                         bool);
template std::vector<StressAnswer> stress_answers<double>(const adapters::NarrowPhase&,
                                                          const std::vector<workloads::RawPair>&,
                                                          bool);

}  // namespace dyop::experiments
