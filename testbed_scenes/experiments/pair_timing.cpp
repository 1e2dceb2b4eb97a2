#include "experiments/pair_timing.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <type_traits>

#include "dyop/batch.hpp"
#include "dyop/method.hpp"
#include "adapters/pair_function.hpp"
#include "workloads/batch_arrays.hpp"
#ifdef DYOP_WITH_BOX2D
#include "box2d_reference/box2d_pair_set.hpp"
#endif

namespace dyop::experiments {

using adapters::Call;
using adapters::pair_function;

namespace {

// Keeps results alive without storing them: the compiler cannot drop a call whose result feeds
// a volatile.
volatile double g_sink = 0;

// Shortest timed pass. One sweep over 8192 pairs took 40 µs to 4 ms; timed alone, such short
// sweeps measured the fast methods up to 1.8× slower than Google Benchmark's long runs did in
// the same build (dyop Depth 34 against 19 ns), while Box2D's longer sweeps agreed. A pass
// therefore repeats the sweep until it lasts this long.
constexpr double kMinPassNs = 20e6;

// Median over `passes` timed passes of the time per pair (ns); `sweep(i)` runs over all `pairs`
// once (i counts the sweeps, for runners that alternate frames).
template <class Sweep>
double median_ns(std::size_t pairs, int passes, Sweep&& sweep) {
  using Clock = std::chrono::steady_clock;
  double sink = 0;
  int sweeps = 0;
  const auto first = Clock::now();
  sink += sweep(sweeps++);  // also warms the caches
  const double once = std::chrono::duration<double, std::nano>(Clock::now() - first).count();
  const int per_pass = std::max(1, static_cast<int>(std::ceil(kMinPassNs / std::max(once, 1.0))));
  std::vector<double> ns;
  for (int p = 0; p < passes; ++p) {
    const auto start = Clock::now();
    for (int r = 0; r < per_pass; ++r) sink += sweep(sweeps++);
    const auto stop = Clock::now();
    ns.push_back(std::chrono::duration<double, std::nano>(stop - start).count() /
                 (static_cast<double>(pairs) * per_pass));
  }
  g_sink = sink;
  std::nth_element(ns.begin(), ns.begin() + ns.size() / 2, ns.end());
  return ns[ns.size() / 2];
}

// The set as the batch kernel takes it (its CCW vertices).
template <class T>
workloads::BatchArrays<T> batch_arrays(const workloads::PairSet<T>& s) {
  return workloads::BatchArrays<T>(s.size(), [&](std::size_t k, int side, int i) {
    return (side == 0 ? s.a[k] : s.b[k]).vertex(i);
  });
}

}  // namespace

std::vector<NarrowPhase> bench_phases() { return adapters::narrow_phases(nullptr, true); }

bool supports(const NarrowPhase& p, Level level, bool is_float) {
  return has(p, level) && (is_float || runs_double(p)) && built(p);
}

template <class T>
std::vector<Answer<T>> answers(const NarrowPhase& p, const workloads::PairSet<T>& set) {
  std::vector<Answer<T>> out(set.size());
  auto keep = [&](std::size_t k, const auto& res) {
    out[k].status = res.status;
    out[k].separation = static_cast<T>(res.separation);
    out[k].normal = res.normal.template cast<T>();
  };
  if (call_of(p) == Call::Batch) {
    workloads::BatchArrays<T> o = batch_arrays(set);
    penetrate_batch(o.pairs(), Level::Depth, o.out());
    for (std::size_t k = 0; k < set.size(); ++k) {
      out[k] = {o.status[k], o.separation[k], Vec2<T>(o.normal_x[k], o.normal_y[k])};
    }
    return out;
  }
  const PairFunction<T> run = pair_function<T>(p);
  if (run == nullptr) return out;
  const bool warm = p.method && p.method->warm;
  for (std::size_t k = 0; k < set.size(); ++k) {
    PairState cache;
    if (warm) run(set.a[k], set.b_next[k], Query<T>{}, &cache);  // the previous frame
    keep(k, run(set.a[k], set.b[k], Query<T>{}, &cache));
  }
  return out;
}

template <class T>
double time_per_pair(const NarrowPhase& p, const workloads::PairSet<T>& set, Level level,
                     int passes) {
  const std::size_t n = set.size();
  const Query<T> q{level};
  switch (call_of(p)) {
    case Call::PerPair: {
      const adapters::Variant v = *p.method;
      if (!v.warm) {
        return median_ns(n, passes, [&](int) {
          double sink = 0;
          for (std::size_t k = 0; k < n; ++k) {
            sink += penetrate(v.method, set.a[k], set.b[k], q).separation;
          }
          return sink;
        });
      }
      // Every pass is one frame of a small motion: the caches hold the previous frame's features.
      std::vector<PairState> cache(n);
      for (std::size_t k = 0; k < n; ++k)
        penetrate(v.method, set.a[k], set.b_next[k], q, &cache[k]);
      return median_ns(n, passes, [&](int pass) {
        const std::vector<Triangle<T>>& b = pass % 2 == 0 ? set.b : set.b_next;
        double sink = 0;
        for (std::size_t k = 0; k < n; ++k) {
          sink += penetrate(v.method, set.a[k], b[k], q, &cache[k]).separation;
        }
        return sink;
      });
    }
    case Call::Batch: {
      workloads::BatchArrays<T> o = batch_arrays(set);
      const PairBatch<T> batch = o.pairs();
      const BatchOutput<T> view = o.out();
      return median_ns(n, passes, [&](int) {
        penetrate_batch(batch, level, view);
        return static_cast<double>(o.status[n / 2]);
      });
    }
    case Call::Box2D:
#ifdef DYOP_WITH_BOX2D
      if constexpr (std::is_same_v<T, float>) {
        const workloads::Box2DPairSet s = workloads::make_box2d_pair_set(set);
        return median_ns(n, passes, [&](int) {
          double sink = 0;
          b2Manifold manifold;
          for (std::size_t k = 0; k < n; ++k) {
            b2CollidePolygons(&manifold, &s.shape_a[k], s.xf_a[k], &s.shape_b[k], s.xf_b[k]);
            sink += manifold.pointCount;
          }
          return sink;
        });
      }
#endif
      return 0;
  }
  return 0;
}

template std::vector<Answer<float>> answers(const NarrowPhase&, const workloads::PairSet<float>&);
template std::vector<Answer<double>> answers(const NarrowPhase&, const workloads::PairSet<double>&);
template double time_per_pair(const NarrowPhase&, const workloads::PairSet<float>&, Level, int);
template double time_per_pair(const NarrowPhase&, const workloads::PairSet<double>&, Level, int);

}  // namespace dyop::experiments
