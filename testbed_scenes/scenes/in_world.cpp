#include "scenes/in_world.hpp"

#include <ostream>
#include <stdexcept>

#include "report/format.hpp"

namespace dyop::scenes {
namespace {

using detail::fmt;

// The medians of one side's runs.
InWorldSide side_of(const std::vector<SceneMetrics>& runs) {
  std::vector<double> collide, step, step_median;
  for (const SceneMetrics& m : runs) {
    collide.push_back(m.narrowphase_ms_total);
    step.push_back(m.step_ms_total);
    step_median.push_back(m.step_ms_median);
  }
  return {median(collide), median(step), median(step_median), runs.front().contact_updates};
}

}  // namespace

int in_world_repetitions(bool quick) { return quick ? 2 : 3; }

InWorldRatio measure_in_world(const std::string& scene, box2d::Backend backend, int repetitions,
                              const std::function<SceneMetrics(const Runner&)>& run) {
  if (repetitions < 1) throw std::invalid_argument("in-world runs need at least one repetition");
  std::vector<SceneMetrics> own, plugin;
  for (int i = 0; i < repetitions; ++i) {
    own.push_back(run(std::nullopt));
    plugin.push_back(run(backend));
  }
  InWorldRatio r;
  r.scene = scene;
  r.backend = box2d::name(backend);
  r.steps = own.front().steps;
  r.repetitions = repetitions;
  r.own = side_of(own);
  r.plugin = side_of(plugin);
  return r;
}

void write_in_world_table(const std::vector<InWorldRatio>& rows, std::ostream& out) {
  out << "| scene | backend | steps | runs | narrow phase ms own | narrow phase ms | × own | "
         "step ms own | step ms | × own | contact updates own / plug-in |\n"
         "|---|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|\n";
  for (const InWorldRatio& r : rows) {
    out << "| " << r.scene << " | " << r.backend << " | " << r.steps << " | " << r.repetitions
        << " | " << fmt("%.2f", r.own.narrowphase_ms) << " | " << fmt("%.2f", r.plugin.narrowphase_ms)
        << " | " << fmt("%.2f", r.narrowphase_ratio()) << " | " << fmt("%.1f", r.own.step_ms)
        << " | " << fmt("%.1f", r.plugin.step_ms) << " | " << fmt("%.2f", r.step_ratio()) << " | "
        << r.own.contact_updates << " / " << r.plugin.contact_updates << " |\n";
  }
}

void write_in_world_csv(const std::vector<InWorldRatio>& rows, std::ostream& out) {
  out << "scene,backend,steps,repetitions,narrowphase_ms_own,narrowphase_ms,narrowphase_ratio,"
         "step_ms_own,step_ms,step_ratio,step_ms_median_own,step_ms_median,contact_updates_own,"
         "contact_updates\n";
  for (const InWorldRatio& r : rows) {
    out << r.scene << ',' << r.backend << ',' << r.steps << ',' << r.repetitions << ','
        << fmt("%.6g", r.own.narrowphase_ms) << ',' << fmt("%.6g", r.plugin.narrowphase_ms) << ','
        << fmt("%.6g", r.narrowphase_ratio()) << ',' << fmt("%.6g", r.own.step_ms) << ','
        << fmt("%.6g", r.plugin.step_ms) << ',' << fmt("%.6g", r.step_ratio()) << ','
        << fmt("%.6g", r.own.step_ms_median) << ',' << fmt("%.6g", r.plugin.step_ms_median) << ','
        << r.own.contact_updates << ',' << r.plugin.contact_updates << '\n';
  }
}

}  // namespace dyop::scenes
