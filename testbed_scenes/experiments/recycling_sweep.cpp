#include "experiments/recycling_sweep.hpp"

#include <chrono>
#include <memory>
#include <ostream>
#include <stdexcept>

#include "dyop/box2d_measurement.hpp"
#include "scenes/scene.hpp"

namespace dyop::experiments {
namespace {

// Creates `name` for `runner`, runs `steps` with the manifolds checked or not, and measures.
// `floor`: re-installed never to recompute before the first step (no contact exists yet).
scenes::SceneMetrics run(const std::string& name, const scenes::Runner& runner, int steps,
                         std::uint64_t seed, const box2d::Config& config, bool check,
                         bool floor = false) {
  const std::unique_ptr<scenes::Scene> scene = scenes::make_scene(name, runner, seed, config);
  if (floor && runner) {
    const box2d::InstallResult r = box2d::measurement::install_never_recompute(*runner, config);
    if (!r.ok()) throw std::runtime_error(std::string("cannot install the floor: ") + r.message);
  }
  if (check) scene->check_manifolds();
  for (int i = 0; i < steps; ++i) scene->step();
  return scene->metrics();
}

}  // namespace

std::vector<RecyclingRecord> run_recycling_sweep(const RecyclingSweepOptions& options,
                                                 std::ostream& progress) {
  std::vector<RecyclingRecord> out;
  const box2d::Backend backend = box2d::Backend::Dyop;
  for (const std::string& name : options.scenes) {
    const auto start = std::chrono::steady_clock::now();
    const int steps = options.steps(name);
    box2d::Config config = options.config;

    config.recycle_distance = 0;
    RecyclingRecord own{name, SweepRow::Own,
                        0,    std::nullopt,
                        0,    run(name, std::nullopt, steps, options.seed, config, true)};
    out.push_back(std::move(own));

    for (const float distance : options.distances) {
      config.recycle_distance = distance;
      std::vector<scenes::SceneMetrics> timed;
      RecyclingRecord r{name, SweepRow::Plugin, distance, std::nullopt, 0, std::nullopt};
      r.timing = measure_in_world(
          name, backend, options.repetitions,
          [&](const scenes::Runner& runner) {
            return run(name, runner, steps, options.seed, config, false);
          },
          &timed);
      const scenes::SceneMetrics& first = timed.front();
      const double evaluations = double(first.plugin_evaluations.value_or(0));
      r.recycled_share = evaluations > 0 ? double(first.recycled.value_or(0)) / evaluations : 0;
      r.accuracy = run(name, backend, steps, options.seed, config, true);
      out.push_back(std::move(r));
    }

    config.recycle_distance = 0;
    RecyclingRecord floor{name, SweepRow::Floor, 0, std::nullopt, 0, std::nullopt};
    floor.timing =
        measure_in_world(name, backend, options.repetitions, [&](const scenes::Runner& runner) {
          return run(name, runner, steps, options.seed, config, false, true);
        });
    out.push_back(std::move(floor));
    progress << "compare: recycling sweep " << name << " ("
             << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()
             << " s)" << std::endl;
  }
  return out;
}

}  // namespace dyop::experiments
