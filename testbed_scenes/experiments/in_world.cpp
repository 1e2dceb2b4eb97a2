#include "experiments/in_world.hpp"

#include <stdexcept>

namespace dyop::experiments {
namespace {

// The medians of one side's runs.
InWorldSide side_of(const std::vector<scenes::SceneMetrics>& runs) {
  std::vector<double> collide, step, toi, step_median;
  for (const scenes::SceneMetrics& m : runs) {
    collide.push_back(m.narrowphase_ms_total);
    step.push_back(m.step_ms_total);
    toi.push_back(m.solve_toi_ms_total);
    step_median.push_back(m.step_ms_median);
  }
  InWorldSide side{scenes::median(collide), scenes::median(step), scenes::median(toi),
                   scenes::median(step_median), runs.front().contact_updates};
  const scenes::SceneMetrics& first = runs.front();
  side.toi_swept = first.toi_swept;
  side.contacts_made = first.contacts_made.value_or(0);
  side.kept = first.recycled.value_or(0);
  if (first.skips) {
    for (const std::uint64_t n : *first.skips) side.skipped += n;
  }
  side.answered = first.answered.value_or(0);
  return side;
}

}  // namespace

int in_world_repetitions(bool quick) { return quick ? 2 : 3; }

InWorldRatio measure_in_world(const std::string& scene, box2d::Backend backend, int repetitions,
                              const std::function<scenes::SceneMetrics(const scenes::Runner&)>& run,
                              std::vector<scenes::SceneMetrics>* plugin_runs) {
  if (repetitions < 1) throw std::invalid_argument("in-world runs need at least one repetition");
  std::vector<scenes::SceneMetrics> own, plugin;
  for (int i = 0; i < repetitions; ++i) {
    own.push_back(run(std::nullopt));
    plugin.push_back(run(backend));
  }
  InWorldRatio r;
  r.scene = scene;
  r.backend = backend;
  r.steps = own.front().steps;
  r.repetitions = repetitions;
  r.own = side_of(own);
  r.plugin = side_of(plugin);
  if (plugin_runs) *plugin_runs = std::move(plugin);
  return r;
}

}  // namespace dyop::experiments
