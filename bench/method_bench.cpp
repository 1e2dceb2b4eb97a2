// Google Benchmark suite: BM_<method>/<class>/<level>/<precision>, one pair per iteration over
// at least 8192 distinct seeded pairs per class (prepared outside the timed loop), so the branch
// predictor cannot learn the set. Compare methods by their ratio to BM_box2d/<class>/manifold/float
// in the same run: the machines are shared and noisy.
#include <benchmark/benchmark.h>

#include <map>
#include <string>

#include "dyop/method.hpp"
#include "workloads/pair_sets.hpp"

namespace {

using namespace dyop;
using workloads::BenchClass;
using workloads::PairSet;

constexpr int kPairs = 8192;
constexpr std::uint64_t kSeed = 2026;

template <class T>
const PairSet<T>& pairs_of(BenchClass c) {
  static std::map<BenchClass, PairSet<T>> sets;
  auto it = sets.find(c);
  if (it == sets.end()) it = sets.emplace(c, workloads::make_pair_set<T>(c, kPairs, kSeed)).first;
  return it->second;
}

const char* level_name(Level l) {
  switch (l) {
    case Level::Overlap: return "overlap";
    case Level::Depth: return "depth";
    case Level::Contact: return "contact";
    case Level::Manifold: return "manifold";
  }
  return "?";
}

template <class T>
const char* precision_name() {
  return std::is_same_v<T, float> ? "float" : "double";
}

template <class T>
void bm_method(benchmark::State& state, Method m, BenchClass c, Level l) {
  const PairSet<T>& s = pairs_of<T>(c);
  const Query<T> q{l};
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(penetrate(m, s.a[i], s.b[i], q));
    if (++i == s.size()) i = 0;
  }
  state.SetItemsProcessed(state.iterations());
}

// Temporal coherence: each pair has its own cache, and every pass over the set alternates between
// two frames of a small motion, so each query starts from the features of the previous frame.
template <class T>
void bm_lin_canny_warm(benchmark::State& state, BenchClass c, Level l) {
  const PairSet<T>& s = pairs_of<T>(c);
  const Query<T> q{l};
  std::vector<LinCannyCache> cache(s.size());
  for (std::size_t k = 0; k < s.size(); ++k) lin_canny(s.a[k], s.b[k], q, &cache[k]);
  std::size_t i = 0;
  bool next_frame = true;
  for (auto _ : state) {
    benchmark::DoNotOptimize(lin_canny(s.a[i], next_frame ? s.b_next[i] : s.b[i], q, &cache[i]));
    if (++i == s.size()) {
      i = 0;
      next_frame = !next_frame;
    }
  }
  state.SetItemsProcessed(state.iterations());
}

#ifdef DYOP_WITH_BOX2D
// Box2D's own narrow phase, which always builds the full manifold.
void bm_box2d(benchmark::State& state, BenchClass c) {
  static std::map<BenchClass, workloads::Box2DPairSet> sets;
  auto it = sets.find(c);
  if (it == sets.end()) it = sets.emplace(c, workloads::make_box2d_pair_set(pairs_of<float>(c))).first;
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
#endif

template <class T>
void register_precision() {
  for (BenchClass c : workloads::all_bench_classes) {
    for (Level l : {Level::Overlap, Level::Depth, Level::Contact, Level::Manifold}) {
      const std::string tail = std::string("/") + workloads::name(c) + "/" + level_name(l) + "/" +
                               precision_name<T>();
      for (Method m : all_methods) {
        benchmark::RegisterBenchmark(("BM_" + std::string(name(m)) + tail).c_str(), bm_method<T>,
                                     m, c, l);
      }
      benchmark::RegisterBenchmark(("BM_lin-canny-warm" + tail).c_str(), bm_lin_canny_warm<T>, c,
                                   l);
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
#ifdef DYOP_WITH_BOX2D
  for (BenchClass c : workloads::all_bench_classes) {
    benchmark::RegisterBenchmark(
        (std::string("BM_box2d/") + workloads::name(c) + "/manifold/float").c_str(), bm_box2d, c);
  }
#endif
  register_precision<float>();
  register_precision<double>();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
