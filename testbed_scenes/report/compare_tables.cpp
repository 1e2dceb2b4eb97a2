// `dyop compare`'s main table (Markdown); each section writes its own (report/compare_*.cpp).
#include "report/compare_tables.hpp"

#include <optional>
#include <string>

#include "report/format.hpp"

namespace dyop::report {
using namespace dyop::scenes;  // the table is about scenes throughout
using namespace dyop::experiments;

void write_compare_table(const CompareRun& run, std::ostream& out) {
  out << "| scene | backend | steps | triangle pairs | step ms (median) | narrow phase ns/pair "
         "| × box2d | max penetration m | mean penetration m | pd error max m | pd error mean m "
         "| misclassified | top displacement m | KE final J | NaN | fallbacks |\n"
      << "|---|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|---|--:|\n";
  for (const SceneMetrics& m : run.rows) {
    const std::optional<double> ratio = ratio_to_box2d(run, m);
    std::string top = "–";
    if (m.top_displacement) {
      top = fmt("%.3f", *m.top_displacement) +
            (*m.top_displacement <= standing_displacement ? " (stands)" : " (FELL)");
    }
    out << "| " << m.scene << " | " << name(m.runner) << " | " << m.steps << " | "
        << m.triangle_pairs << " | " << fmt("%.3g", m.step_ms_median) << " | "
        << fmt("%.0f", m.narrowphase_ns_per_pair) << " | " << (ratio ? fmt("%.2f", *ratio) : "–")
        << " | " << metres(m.max_penetration) << " | " << metres(m.mean_penetration) << " | "
        << metres(m.pd_error_max) << " | " << metres(m.pd_error_mean) << " | " << m.misclassified
        << " | " << top << " | " << fmt("%.3g", m.kinetic_energy_final) << " | "
        << (m.nan_detected ? "YES" : "no") << " | "
        << (m.fallbacks ? std::to_string(*m.fallbacks) : "–") << " |\n";
  }
}

}  // namespace dyop::report
