#include "experiments/rain_scaling.hpp"

#include <algorithm>
#include <chrono>
#include <map>
#include <ostream>
#include <stdexcept>

#include "experiments/progress.hpp"
#include "experiments/in_world.hpp"
#include "scenes/scene.hpp"

namespace dyop::experiments {
namespace {

using detail::fixed;

scenes::SceneMetrics run_rain(const scenes::Runner& runner, int falling,
                              const ScalingOptions& options) {
  const std::unique_ptr<scenes::Scene> scene = scenes::make_rain(falling, runner, options.seed);
  for (int i = 0; i < options.steps; ++i) scene->step();
  return scene->metrics();
}

ScalingRecord record_of(const scenes::SceneMetrics& m, int falling) {
  ScalingRecord r;
  r.runner = m.runner;
  r.falling = falling;
  r.triangles = m.triangles;
  r.steps = m.steps;
  r.step_ms_median = m.step_ms_median;
  const double measured = m.steps - 1;  // step 1 is not in the narrow-phase figures
  r.narrowphase_ms_per_step = m.narrowphase_ms_total / measured;
  r.narrowphase_ns_per_pair = m.narrowphase_ns_per_pair;
  r.pairs_per_step = static_cast<double>(m.triangle_pairs) / measured;
  r.pd_error_max = m.pd_error_max;
  r.fallbacks = m.fallbacks.value_or(0);
  r.nan_detected = m.nan_detected;
  return r;
}

}  // namespace

std::vector<ScalingRecord> run_rain_scaling(const ScalingOptions& options, std::ostream& progress) {
  if (options.steps < 2) throw std::invalid_argument("scaling runs need at least 2 steps");
  for (int n : options.sizes) {
    if (n < 1) throw std::invalid_argument("scaling sizes must be at least 1 triangle");
  }
  std::vector<ScalingRecord> records;
  for (int n : options.sizes) {
    std::vector<scenes::SceneMetrics> own_runs;
    for (box2d::Backend b : box2d::all_backends) {
      const auto start = std::chrono::steady_clock::now();
      scenes::SceneMetrics backend_run;
      const InWorldRatio pair =
          measure_in_world("rain-" + std::to_string(n), b, 1, [&](const scenes::Runner& runner) {
            scenes::SceneMetrics m = run_rain(runner, n, options);
            (runner ? backend_run : own_runs.emplace_back()) = m;
            return m;
          });
      records.push_back(record_of(backend_run, n));
      records.back().ratio_vs_own = pair.narrowphase_ratio();
      records.back().step_ratio_vs_own = pair.step_ratio();
      const double s =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      progress << "dyop bench: rain " << n << " triangles, " << box2d::name(b) << ": "
               << fixed(records.back().narrowphase_ms_per_step, 2) << " ms narrow phase per step, "
               << fixed(pair.narrowphase_ratio(), 2) << "x Box2D's own (step "
               << fixed(pair.step_ratio(), 2) << "x; " << fixed(s, 1) << " s with the own run)\n";
    }
    // Box2D's own contact at this size: the run of median narrow-phase time.
    std::sort(own_runs.begin(), own_runs.end(),
              [](const scenes::SceneMetrics& x, const scenes::SceneMetrics& y) {
                return x.narrowphase_ms_total < y.narrowphase_ms_total;
              });
    records.push_back(record_of(own_runs[own_runs.size() / 2], n));
    records.back().ratio_vs_own = records.back().step_ratio_vs_own = 1;
  }
  std::map<int, double> box2d_ms;
  for (const ScalingRecord& r : records) {
    if (r.runner == box2d::Backend::Box2D) box2d_ms[r.falling] = r.narrowphase_ms_per_step;
  }
  for (ScalingRecord& r : records) {
    const double base = box2d_ms[r.falling];
    r.ratio_vs_box2d = base > 0 ? r.narrowphase_ms_per_step / base : 0;
  }
  return records;
}

}  // namespace dyop::experiments
