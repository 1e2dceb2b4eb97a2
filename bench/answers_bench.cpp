// build/bin/dyop_answers_bench: the plug-in's answers afresh of triangle pairs, replayed. A scene
// (default `tile-map-unfixed`, the tile map a loader brought over without fixing its edge data)
// runs under the plug-in with its answers recorded (`measurement::record_answers`: the shapes, the
// transforms, the memory with the masks the solver read); each benchmark then replays the same
// pairs, in the world's order: `plugin` through `collide_polygons` with a copy of each recorded
// memory (the same skips fail, the same masks are read), `box2d` through `b2CollidePolygons`.
// Time per call is the benchmark's; instructions per call by act come from callgrind
// (scripts/answer_instructions.sh).
//   DYOP_ANSWERS_SCENE=name  DYOP_ANSWERS_STEPS=n (default: the scene's own)
#include <benchmark/benchmark.h>

#include <box2d/b2_collision.h>

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "dyop/box2d.hpp"
#include "dyop/box2d_measurement.hpp"
#include "scenes/scene.hpp"

namespace {

using dyop::box2d::measurement::RecordedAnswer;

// The scene's answers, recorded once.
const std::vector<RecordedAnswer>& answers() {
  static const std::vector<RecordedAnswer> recorded = [] {
    const char* scene = std::getenv("DYOP_ANSWERS_SCENE");
    const char* steps = std::getenv("DYOP_ANSWERS_STEPS");
    const std::string name = scene ? scene : "tile-map-unfixed";
    const dyop::scenes::SceneInfo* info = dyop::scenes::find_scene(name);
    if (!info) {
      std::fprintf(stderr, "dyop_answers_bench: no scene %s\n", name.c_str());
      std::exit(2);
    }
    std::vector<RecordedAnswer> out;
    dyop::box2d::measurement::record_answers(&out);
    dyop::scenes::run_scene(name, dyop::box2d::Backend::Dyop,
                            steps ? std::atoi(steps) : info->default_steps, 0);
    dyop::box2d::measurement::record_answers(nullptr);
    std::fprintf(stderr, "dyop_answers_bench: %zu answers of %s\n", out.size(), name.c_str());
    return out;
  }();
  return recorded;
}

void bm_plugin(benchmark::State& state) {
  const std::vector<RecordedAnswer>& all = answers();
  dyop::box2d::install(dyop::box2d::Backend::Dyop);
  b2Manifold manifold;
  std::size_t i = 0;
  for (auto _ : state) {
    const RecordedAnswer& r = all[i];
    dyop::box2d::ContactMemory memory = r.memory;
    dyop::box2d::collide_polygons(&manifold, dyop::box2d::Backend::Dyop, r.a, r.xf_a, r.b, r.xf_b,
                                  &memory);
    benchmark::DoNotOptimize(manifold);
    if (++i == all.size()) i = 0;
  }
  dyop::box2d::uninstall();
  state.SetItemsProcessed(state.iterations());
}

void bm_box2d(benchmark::State& state) {
  const std::vector<RecordedAnswer>& all = answers();
  b2Manifold manifold;
  std::size_t i = 0;
  for (auto _ : state) {
    const RecordedAnswer& r = all[i];
    b2CollidePolygons(&manifold, &r.a, r.xf_a, &r.b, r.xf_b);
    benchmark::DoNotOptimize(manifold);
    if (++i == all.size()) i = 0;
  }
  state.SetItemsProcessed(state.iterations());
}

BENCHMARK(bm_plugin)->Name("BM_answers/plugin");
BENCHMARK(bm_box2d)->Name("BM_answers/box2d");

}  // namespace

BENCHMARK_MAIN();
