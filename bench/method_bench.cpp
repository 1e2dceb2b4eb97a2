// Google Benchmark suite: BM_<method>/<class>/<level>/<precision> for every row of the method
// registry (dyop/method.hpp) at every level and precision it has (a warm-startable method as
// <name>-cold and <name>-warm), one pair per iteration over 131,072 distinct seeded pairs per
// class (prepared outside the timed loop), so that no branch predictor learns the set: an AMD
// EPYC (AVX-512) host learned a repeated set of 8192 and timed data-dependent branches as free.
// Compare methods by their ratio to BM_box2d/<class>/manifold/float in the same run: the
// machines are shared and noisy. Batch kernel benchmarks time a whole
// batch per iteration; their items_per_second is pairs per second and their label names the kernel
// that ran (BM_batch: the one Auto picks here; BM_batch-<kernel>: each forced, skipped where the
// CPU lacks it). BM_stream/<scene>/<backend>
// replays a Box2D scene's recorded contact updates, one per iteration (box2d-own:
// b2CollidePolygons).
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <map>
#include <optional>
#include <string>

#include "dyop/batch.hpp"
#include "dyop/method.hpp"
#include "workloads/batch_arrays.hpp"
#include "workloads/pair_sets.hpp"
#ifdef DYOP_WITH_BOX2D
#include "adapters/narrow_phase.hpp"
#include "box2d_reference/box2d_pair_set.hpp"
#include "experiments/contact_stream.hpp"
#endif

namespace {

using namespace dyop;
using workloads::InputClass;
using workloads::PairSet;

constexpr int kPairs = 131072;
constexpr std::uint64_t kSeed = 2026;

// The pairs per class: kPairs, or DYOP_BENCH_PAIRS (e.g. 8192, to see whether a host's branch
// predictor learns a small set: then the methods' times drop, b2CollidePolygons' less).
int pair_count() {
  static const int n = [] {
    const char* v = std::getenv("DYOP_BENCH_PAIRS");
    const int parsed = v ? std::atoi(v) : 0;
    return parsed > 0 ? parsed : kPairs;
  }();
  return n;
}

template <class T>
const PairSet<T>& pairs_of(InputClass c) {
  static std::map<InputClass, PairSet<T>> sets;
  auto it = sets.find(c);
  if (it == sets.end()) {
    it = sets.emplace(c, workloads::make_pair_set<T>(c, pair_count(), kSeed)).first;
  }
  return it->second;
}

template <class T>
const char* precision_name() {
  return std::is_same_v<T, float> ? "float" : "double";
}

// `witnesses`: `Query::witnesses` (false only at Level::Manifold, for the manifold alone).
template <class T>
void bm_method(benchmark::State& state, Method m, InputClass c, Level l, bool witnesses) {
  const PairSet<T>& s = pairs_of<T>(c);
  Query<T> q{l};
  q.witnesses = witnesses;
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(penetrate(m, s.a[i], s.b[i], q));
    if (++i == s.size()) i = 0;
  }
  state.SetItemsProcessed(state.iterations());
}

// Temporal coherence, for the methods that keep warm-start state: each pair has its own cache,
// and every pass over the set alternates between two frames of a small motion, so each query
// starts from the features of the previous frame.
template <class T>
void bm_warm(benchmark::State& state, Method m, InputClass c, Level l) {
  const PairSet<T>& s = pairs_of<T>(c);
  const Query<T> q{l};
  std::vector<PairState> cache(s.size());
  for (std::size_t k = 0; k < s.size(); ++k) penetrate(m, s.a[k], s.b[k], q, &cache[k]);
  std::size_t i = 0;
  bool next_frame = true;
  for (auto _ : state) {
    benchmark::DoNotOptimize(penetrate(m, s.a[i], next_frame ? s.b_next[i] : s.b[i], q, &cache[i]));
    if (++i == s.size()) {
      i = 0;
      next_frame = !next_frame;
    }
  }
  state.SetItemsProcessed(state.iterations());
}

// `pairs` 0: the class's distinct pairs (in cache); otherwise a streaming set of that many.
template <class T>
void bm_batch(benchmark::State& state, InputClass c, Level l, std::size_t pairs,
              BatchKernel kernel) {
  if (!batch_kernel_available(kernel)) {
    state.SkipWithError("this CPU lacks the kernel's instructions");
    return;
  }
  state.SetLabel(name(batch_kernel_used(kernel)));
  const PairSet<T>& s = pairs_of<T>(c);
  // A streaming set repeats the distinct pairs; `state.iterations()` counts batches.
  workloads::BatchArrays<T> arrays(pairs == 0 ? s.size() : pairs,
                                   [&](std::size_t k, int side, int i) {
                                     const std::size_t d = k % s.size();
                                     return (side == 0 ? s.a[d] : s.b[d]).vertex(i);
                                   });
  const PairBatch<T> in = arrays.pairs();
  const BatchOutput<T> out = arrays.out();
  for (auto _ : state) {
    penetrate_batch(in, l, out, kernel);
    benchmark::DoNotOptimize(arrays.status.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(in.count));
}

#ifdef DYOP_WITH_BOX2D
// Box2D's own narrow phase, which always builds the full manifold.
void bm_box2d(benchmark::State& state, InputClass c) {
  static std::map<InputClass, workloads::Box2DPairSet> sets;
  auto it = sets.find(c);
  if (it == sets.end())
    it = sets.emplace(c, workloads::make_box2d_pair_set(pairs_of<float>(c))).first;
  const workloads::Box2DPairSet& s = it->second;
  b2Manifold manifold;
  std::size_t i = 0;
  for (auto _ : state) {
    b2CollidePolygons(&manifold, &s.shape_a[i], s.xf_a[i], &s.shape_b[i], s.xf_b[i]);
    benchmark::DoNotOptimize(manifold);
    if (++i == s.size()) i = 0;
  }
  state.SetItemsProcessed(state.iterations());
}

// A scene's recorded contact stream (every Collide update of steps 2..300, recorded once, outside
// timing), one call per iteration with one memory per contact, as in the world. 300 steps (5 s):
// dropped bodies have landed, so the stream holds first contacts and resting pairs alike.
constexpr int kStreamSteps = 300;

const experiments::ContactStream& stream_of(const std::string& scene) {
  static std::map<std::string, experiments::ContactStream> streams;
  auto it = streams.find(scene);
  if (it == streams.end()) {
    it = streams.emplace(scene, experiments::record_stream(scene, kStreamSteps, kSeed)).first;
  }
  return it->second;
}

// `backend` nullopt: `b2CollidePolygons` directly (box2d-own). Memories start over, untimed, at
// each wrap, so every pass over the stream starts as the world did; `masks`: each contact's
// internal-edge masks given, as a world's contact holds them (else none: the same pairs plain).
void bm_stream(benchmark::State& state, const std::string& scene,
               std::optional<box2d::Backend> backend, bool masks) {
  const experiments::ContactStream& s = stream_of(scene);
  const auto fresh = [&] {
    std::vector<box2d::ContactMemory> m(s.contacts.size());
    for (std::size_t k = 0; masks && k < m.size(); ++k)
      m[k].internal_edges = s.contacts[k].internal_edges;
    return m;
  };
  std::vector<box2d::ContactMemory> memory = fresh();
  b2Manifold manifold;
  std::size_t i = 0;
  for (auto _ : state) {
    const experiments::StreamCall& call = s.calls[i];
    const experiments::StreamContact& c = s.contacts[static_cast<std::size_t>(call.contact)];
    if (backend) {
      box2d::collide_polygons(&manifold, *backend, c.shape_a, call.xf_a, c.shape_b, call.xf_b,
                              &memory[static_cast<std::size_t>(call.contact)]);
    } else {
      b2CollidePolygons(&manifold, &c.shape_a, call.xf_a, &c.shape_b, call.xf_b);
    }
    benchmark::DoNotOptimize(manifold);
    if (++i == s.calls.size()) {
      state.PauseTiming();
      i = 0;
      memory = fresh();
      state.ResumeTiming();
    }
  }
  state.SetItemsProcessed(state.iterations());
}

void register_streams() {
  for (const char* scene : {"rain", "pyramid"}) {
    const std::string head = std::string("BM_stream/") + scene + "/";
    for (box2d::Backend b : box2d::all_backends) {
      benchmark::RegisterBenchmark((head + box2d::name(b)).c_str(), bm_stream, scene,
                                   std::optional<box2d::Backend>(b), false);
    }
    benchmark::RegisterBenchmark((head + scenes::box2d_own).c_str(), bm_stream, scene,
                                 std::optional<box2d::Backend>(), false);
  }
  // The internal-edge rule's price per pair: the same calls with their masks and without.
  for (const char* scene : {"tiles", "slide", "tile-map"}) {
    const std::string head = std::string("BM_stream/") + scene + "/";
    for (const bool masks : {false, true}) {
      benchmark::RegisterBenchmark((head + (masks ? "dyop-masks" : "dyop")).c_str(), bm_stream,
                                   scene, std::optional<box2d::Backend>(box2d::Backend::Dyop),
                                   masks);
    }
    benchmark::RegisterBenchmark((head + scenes::box2d_own).c_str(), bm_stream, scene,
                                 std::optional<box2d::Backend>(), false);
  }
}
#endif

// Every benchmark of one row of the registry in precision T.
template <class T>
void register_method(const MethodInfo& row) {
  if (!row.runs_double() && !std::is_same_v<T, float>) return;
  for (InputClass c : workloads::bench_classes) {
    for (Level l : all_levels) {
      if (!row.has(l)) continue;
      const std::string tail =
          std::string("/") + workloads::name(c) + "/" + name(l) + "/" + precision_name<T>();
      const auto bm = [&](const char* spelling) { return "BM_" + std::string(spelling) + tail; };
      switch (row.entry) {
        case Entry::PerPair:
          benchmark::RegisterBenchmark(bm(adapters::variant_name(row.method, false)).c_str(),
                                       bm_method<T>, row.method, c, l, true);
          if (row.warm_start()) {
            benchmark::RegisterBenchmark(bm(adapters::variant_name(row.method, true)).c_str(),
                                         bm_warm<T>, row.method, c, l);
          }
          if (l == Level::Manifold && row.manifold_only()) {
            // The manifold alone (`Query::witnesses` false): what b2CollidePolygons computes.
            const std::string only = "BM_" + std::string(row.name) + "/" + workloads::name(c) +
                                     "/manifold-only/" + precision_name<T>();
            benchmark::RegisterBenchmark(only.c_str(), bm_method<T>, row.method, c, l, false);
          }
          break;
        case Entry::Batch:
          benchmark::RegisterBenchmark(bm(row.name).c_str(), bm_batch<T>, c, l, 0,
                                       BatchKernel::Auto);
          if (c == InputClass::Overlapping || c == InputClass::Mixed) {
            // Streaming: 1M pairs, far beyond the caches (the memory floor).
            benchmark::RegisterBenchmark(bm((std::string(row.name) + "-stream-1M").c_str()).c_str(),
                                         bm_batch<T>, c, l, std::size_t{1} << 20,
                                         BatchKernel::Auto);
            for (BatchKernel k : batch_kernels) {
              if (k == BatchKernel::Auto) continue;  // the row above
              const std::string forced = std::string(row.name) + "-" + name(k);
              benchmark::RegisterBenchmark(bm(forced.c_str()).c_str(), bm_batch<T>, c, l, 0, k);
            }
          }
          break;
      }
    }
  }
}

#ifdef DYOP_WITH_BOX2D
// Box2D's b2CollidePolygons, the production reference: float, its whole manifold.
void register_box2d() {
  for (InputClass c : workloads::bench_classes) {
    const std::string name = std::string("BM_") + adapters::name(adapters::NarrowPhase::box2d()) +
                             "/" + workloads::name(c) + "/" + dyop::name(Level::Manifold) +
                             "/float";
    benchmark::RegisterBenchmark(name.c_str(), bm_box2d, c);
  }
}
#endif

}  // namespace

int main(int argc, char** argv) {
  for (const MethodInfo& row : method_table) {
    register_method<float>(row);
    register_method<double>(row);
  }
#ifdef DYOP_WITH_BOX2D
  register_box2d();
  register_streams();
#endif
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
