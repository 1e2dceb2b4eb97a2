#include "experiments/compare.hpp"

#include <algorithm>
#include <ostream>

#include "experiments/progress.hpp"
#include "scenes/scene.hpp"

namespace dyop::experiments {
namespace {

using detail::fixed;

template <std::size_t N>
bool listed(const std::array<const char*, N>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

}  // namespace

// The configurations one after the other, repetition after repetition: the machines are shared,
// so what is compared is measured as close together in time as possible.
SkipMeasurement measure_skips(const scenes::SceneInfo& s, box2d::Backend b, int steps,
                              const CompareOptions& options) {
  std::vector<box2d::Config> configs = {box2d::Config::no_skips(), options.skips};
  if (is_skip_target(s.name, b)) {
    for (const scenes::SkipSwitch& sw : scenes::skip_switches()) {
      if (sw.field == &box2d::Config::lin_canny_cache) continue;
      box2d::Config alone = box2d::Config::no_skips();
      alone.*(sw.field) = true;
      configs.push_back(alone);
    }
  }
  std::vector<std::optional<scenes::SceneMetrics>> fastest(configs.size());
  for (int r = 0; r < skip_repetitions(options.quick); ++r) {
    for (std::size_t i = 0; i < configs.size(); ++i) {
      scenes::SceneMetrics run = scenes::run_scene(s.name, b, steps, options.seed, configs[i]);
      if (!fastest[i] || run.narrowphase_ms_total < fastest[i]->narrowphase_ms_total) {
        fastest[i] = std::move(run);
      }
    }
  }
  SkipMeasurement m{*fastest[0], *fastest[1], {}};
  for (std::size_t i = 2; i < fastest.size(); ++i) m.alone.push_back(*fastest[i]);
  return m;
}

int skip_repetitions(bool quick) { return quick ? 1 : 3; }

bool is_skip_target(const std::string& scene, const scenes::Runner& runner) {
  return runner == skip_target_backend && listed(skip_target_scenes, scene);
}

bool skips_keep_the_answer(const scenes::Runner& runner) {
  return runner != box2d::Backend::LinCanny && runner != box2d::Backend::DyopFast;
}

double narrowphase_ratio(const scenes::SceneMetrics& on, const scenes::SceneMetrics& off) {
  return on.narrowphase_ns_per_pair / off.narrowphase_ns_per_pair;
}

int compare_steps(const CompareOptions& options, const scenes::SceneInfo& s) {
  return options.steps.value_or(options.quick ? s.compare_quick_steps : s.default_steps);
}

int paper_repetitions(bool quick) { return quick ? 41 : 201; }

std::vector<box2d::Backend> compare_backends(const CompareOptions& options) {
  std::vector<box2d::Backend> out;
  for (box2d::Backend b : box2d::all_backends) {
    const bool named =
        std::find(options.backends.begin(), options.backends.end(), b) != options.backends.end();
    const bool by_default =
        !options.quick || b == box2d::Backend::Dyop || b == box2d::Backend::Box2D;
    if (options.backends.empty() ? by_default : named) out.push_back(b);
  }
  return out;
}

bool left_out_of_quick_sections(const std::string& name) {
  return name == "rain-tall" || name == "tumbler";
}

std::vector<box2d::Backend> in_world_backends(const CompareOptions& options) {
  if (!options.backends.empty() || !options.quick) return compare_backends(options);
  return {box2d::Backend::Dyop};
}

std::vector<const scenes::SceneInfo*> selected_scenes(const CompareOptions& options) {
  std::vector<const scenes::SceneInfo*> scenes;
  for (const scenes::SceneInfo& s : scenes::scene_catalog()) {
    if (options.scenes.empty() ||
        std::find(options.scenes.begin(), options.scenes.end(), s.name) != options.scenes.end()) {
      scenes.push_back(&s);
    }
  }
  return scenes;
}

CompareRun run_compare(const CompareOptions& options, std::ostream& progress,
                       const std::function<double()>& elapsed) {
  CompareRun run;
  run.options = options;
  const std::vector<const scenes::SceneInfo*> scenes = selected_scenes(options);
  const std::vector<box2d::Backend> backends = compare_backends(options);
  const int total = static_cast<int>(scenes.size() * backends.size());
  int done = 0;
  for (const scenes::SceneInfo* s : scenes) {
    const int steps = compare_steps(options, *s);
    for (box2d::Backend b : backends) {
      const double start = elapsed();
      scenes::Drawing final_state;
      const bool snapshot = b == box2d::Backend::Dyop;
      run.rows.push_back(scenes::run_scene(s->name, b, steps, options.seed, options.skips,
                                           snapshot ? &final_state : nullptr));
      if (snapshot) run.snapshots.emplace_back(s->name, std::move(final_state));
      ++done;
      progress << '[' << done << '/' << total << "] " << s->name << " / " << box2d::name(b) << ", "
               << steps << " steps: " << fixed(elapsed() - start, 2) << " s (total "
               << fixed(elapsed(), 1) << " s)\n"
               << std::flush;
    }
  }
  return run;
}

std::optional<double> ratio_to_box2d(const CompareRun& run, const scenes::SceneMetrics& m) {
  for (const scenes::SceneMetrics& r : run.rows) {
    if (r.scene == m.scene && r.runner == box2d::Backend::Box2D && r.narrowphase_ns_per_pair > 0) {
      return m.narrowphase_ns_per_pair / r.narrowphase_ns_per_pair;
    }
  }
  return std::nullopt;
}

}  // namespace dyop::experiments
