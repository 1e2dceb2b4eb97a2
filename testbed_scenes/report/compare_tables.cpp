// `dyop compare`'s Markdown tables: the main table, the skip section's, the paper experiment's
// and the in-world runs'.
#include "report/compare_tables.hpp"

#include <algorithm>
#include <cstdint>
#include <optional>
#include <string>

#include "report/format.hpp"
#include "scenes/skips.hpp"

namespace dyop::report {
namespace {

// The tables are about scenes throughout; their names read better unqualified.
using namespace dyop::scenes;

// Only the exact backends promise equal hashes: a difference there is flagged.
std::string hashes_equal(const SceneMetrics& on, const SceneMetrics& off) {
  if (on.hash == off.hash) return "yes";
  return skips_keep_the_answer(on.backend) ? "NO" : "no";
}

// "n (p %)" skipped of the evaluations.
std::string skipped_share(std::uint64_t n, std::uint64_t of) {
  return std::to_string(n) + (of > 0 ? " (" + fmt("%.0f", 100.0 * n / of) + " %)" : "");
}

std::uint64_t skipped(const SceneMetrics& m, box2d::Skip why) {
  return m.skips ? (*m.skips)[static_cast<int>(why)] : 0;
}

}  // namespace

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
    out << "| " << m.scene << " | " << m.backend << " | " << m.steps << " | " << m.triangle_pairs
        << " | " << fmt("%.3g", m.step_ms_median) << " | " << fmt("%.0f", m.narrowphase_ns_per_pair)
        << " | " << (ratio ? fmt("%.2f", *ratio) : "–") << " | " << metres(m.max_penetration)
        << " | " << metres(m.mean_penetration) << " | " << metres(m.pd_error_max) << " | "
        << metres(m.pd_error_mean) << " | " << m.misclassified << " | " << top << " | "
        << fmt("%.3g", m.kinetic_energy_final) << " | " << (m.nan_detected ? "YES" : "no") << " | "
        << (m.fallbacks ? std::to_string(*m.fallbacks) : "–") << " |\n";
  }
}

void write_skip_tables(const CompareRun& run, std::ostream& out) {
  const std::string on = skip_argument(run.options.skips);
  out << "Skips `" << on << "` against `none`, run back to back (narrow phase: ns per contact "
      << "update; step: median wall time):\n\n"
      << "| scene | backend | steps | ns/pair on | ns/pair off | on/off | step ms on | step ms off "
         "| on/off | hashes equal | evaluations | skipped bounds | skipped warm-axis |\n"
      << "|---|---|--:|--:|--:|--:|--:|--:|--:|---|--:|--:|--:|\n";
  for (const SkipMeasurement& m : run.skips) {
    const std::uint64_t of = m.on.plugin_evaluations.value_or(0);
    out << "| " << m.on.scene << " | " << m.on.backend << " | " << m.on.steps << " | "
        << fmt("%.1f", m.on.narrowphase_ns_per_pair) << " | "
        << fmt("%.1f", m.off.narrowphase_ns_per_pair) << " | "
        << fmt("%.2f", narrowphase_ratio(m.on, m.off)) << " | " << fmt("%.3g", m.on.step_ms_median)
        << " | " << fmt("%.3g", m.off.step_ms_median) << " | "
        << fmt("%.2f", m.on.step_ms_median / m.off.step_ms_median) << " | "
        << hashes_equal(m.on, m.off) << " | " << of << " | "
        << skipped_share(skipped(m.on, box2d::Skip::Bounds), of) << " | "
        << skipped_share(skipped(m.on, box2d::Skip::WarmAxis), of) << " |\n";
  }

  bool breakdown = false;
  for (const SkipMeasurement& m : run.skips) breakdown = breakdown || !m.alone.empty();
  if (breakdown) {
    out << "\nEach skip alone against `none` (`" << box2d::name(skip_target_backend)
        << "`; `lin-canny-cache` changes nothing but `lin-canny`):\n\n"
        << "| scene | skips | ns/pair | × none | step ms | × none | hashes equal | skipped bounds "
           "| skipped warm-axis |\n"
        << "|---|---|--:|--:|--:|--:|---|--:|--:|\n";
    for (const SkipMeasurement& m : run.skips) {
      if (m.alone.empty()) continue;
      std::vector<const SceneMetrics*> rows = {&m.off};
      for (const SceneMetrics& a : m.alone) rows.push_back(&a);
      rows.push_back(&m.on);
      for (const SceneMetrics* r : rows) {
        out << "| " << r->scene << " | " << (r->skip_config ? skip_argument(*r->skip_config) : "")
            << " | " << fmt("%.1f", r->narrowphase_ns_per_pair) << " | "
            << fmt("%.2f", narrowphase_ratio(*r, m.off)) << " | " << fmt("%.3g", r->step_ms_median)
            << " | " << fmt("%.2f", r->step_ms_median / m.off.step_ms_median) << " | "
            << hashes_equal(*r, m.off) << " | " << skipped(*r, box2d::Skip::Bounds) << " | "
            << skipped(*r, box2d::Skip::WarmAxis) << " |\n";
      }
    }
  }

  bool lin_canny = false;
  for (const SkipMeasurement& m : run.skips) {
    lin_canny = lin_canny || m.on.backend == box2d::name(box2d::Backend::LinCanny);
  }
  if (!lin_canny) return;
  out << "\n`lin-canny` with skips `" << on << "` against `none` (its answer may change: see "
      << "the text):\n\n"
      << "| scene | hashes equal | contact updates on / off | max penetration m on / off "
         "| pd error max m on / off | misclassified on / off | KE final J on / off |\n"
      << "|---|---|--:|--:|--:|--:|--:|\n";
  for (const SkipMeasurement& m : run.skips) {
    if (m.on.backend != box2d::name(box2d::Backend::LinCanny)) continue;
    out << "| " << m.on.scene << " | " << (m.on.hash == m.off.hash ? "yes" : "no") << " | "
        << m.on.contact_updates << " / " << m.off.contact_updates << " | "
        << metres(m.on.max_penetration) << " / " << metres(m.off.max_penetration) << " | "
        << metres(m.on.pd_error_max) << " / " << metres(m.off.pd_error_max) << " | "
        << m.on.misclassified << " / " << m.off.misclassified << " | "
        << fmt("%.3g", m.on.kinetic_energy_final) << " / "
        << fmt("%.3g", m.off.kinetic_energy_final) << " |\n";
  }
}

void write_paper_tables(const paper::Experiment& e, std::ostream& out) {
  const auto& types = paper::triangle_types();
  out << "Time to compute the penetration depth of every bounding-box-overlapping pair a "
         "triangle type is in, over all "
      << e.steps << " steps (µs, median of " << e.repetitions << " repetitions):\n\n"
      << "| type | size | pairs |";
  for (const auto& m : e.methods) out << ' ' << name(m.method) << " |";
  out << " lin-canny-warm / dyop | lin-canny-cold / dyop |\n|--:|--:|--:|";
  for (std::size_t i = 0; i < e.methods.size() + 2; ++i) out << "--:|";
  out << '\n';
  auto figures = [&](const Variant& which) -> const paper::MethodFigures& {
    for (const auto& m : e.methods) {
      if (m.method == which) return m;
    }
    return e.methods.front();
  };
  const auto& dyop = figures({Method::Dyop, false});
  const auto& warm = figures({Method::LinCanny, true});
  const auto& cold = figures({Method::LinCanny, false});
  for (int k = 0; k < paper::type_count; ++k) {
    const auto& t = types[k];
    const double size =
        std::max({(t[1] - t[0]).norm(), (t[2] - t[1]).norm(), (t[0] - t[2]).norm()});
    out << "| " << k + 1 << " | " << fmt("%.2f", size) << " | " << e.pairs_per_type[k] << " |";
    for (const auto& m : e.methods) out << ' ' << fmt("%.2f", m.us_per_type[k]) << " |";
    out << ' ' << fmt("%.2f", warm.us_per_type[k] / dyop.us_per_type[k]) << " | "
        << fmt("%.2f", cold.us_per_type[k] / dyop.us_per_type[k]) << " |\n";
  }
  out << "\nEvery method over the same pairs (" << e.pairs_tested
      << " bounding-box-overlapping pairs, " << e.pairs_penetrating
      << " of them penetrating; and all " << paper::pair_count << " pairs × " << e.steps
      << " steps without a broad phase), errors against the exact rational reference:\n\n"
      << "| method | µs, overlapping pairs | ns/pair | × dyop | µs, all pairs | × dyop "
         "| depth error max | depth error mean | misclassified | invalid |\n"
      << "|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|\n";
  for (const auto& m : e.methods) {
    out << "| " << name(m.method) << " | " << fmt("%.1f", m.us_total) << " | "
        << fmt("%.1f", m.ns_per_pair) << " | " << fmt("%.2f", m.us_total / dyop.us_total) << " | "
        << fmt("%.1f", m.us_all_pairs) << " | " << fmt("%.2f", m.us_all_pairs / dyop.us_all_pairs)
        << " | " << metres(m.error_max) << " | " << metres(m.error_mean) << " | " << m.misclassified
        << " | " << m.invalid << " |\n";
  }
  out << "\nThe paper (its Figure 7): DyOP-PD 10.765 ms against Lin–Canny 23.259 ms on average "
         "over its 90 steps, Lin–Canny / DyOP = 2.16. Here, on the overlapping pairs: "
         "Lin–Canny warm-started / dyop = "
      << fmt("%.2f", warm.us_total / dyop.us_total)
      << ", cold / dyop = " << fmt("%.2f", cold.us_total / dyop.us_total)
      << "; the paper's literal method (dyop-paper) against warm Lin–Canny: "
      << fmt("%.2f", warm.us_total / figures({Method::DyopPaper, false}).us_total) << ".\n";
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

void write_slide_tables(const std::vector<scenes::SlideRun>& runs, std::ostream& out) {
  auto percent = [](double fraction) { return fmt("%.1f", 100 * fraction) + " %"; };
  out << "| runner | largest vertical speed (m/s) | largest angular speed (rad/s) | smallest "
         "travel | resting box jitter (m) |\n|---|--:|--:|--:|--:|\n";
  for (const scenes::SlideRun& r : runs) {
    const scenes::SceneMetrics& m = r.metrics;
    if (!m.slide) continue;
    out << "| " << m.backend << " | " << fmt("%.4f", m.slide->max_vertical_speed) << " | "
        << fmt("%.4f", m.slide->max_angular_speed) << " | " << percent(m.slide->min_travel)
        << " | " << (m.top_displacement ? metres(*m.top_displacement) : "n/a") << " |\n";
  }
  if (runs.empty() || !runs.front().metrics.slide) return;
  out << "\n| slider |";
  for (const scenes::SlideRun& r : runs) out << ' ' << r.metrics.backend << " |";
  out << "\n|---|";
  for (std::size_t i = 0; i < runs.size(); ++i) out << "---|";
  out << '\n';
  const std::vector<scenes::SliderFigures>& sliders = runs.front().metrics.slide->sliders;
  for (std::size_t k = 0; k < sliders.size(); ++k) {
    out << "| " << sliders[k].body << " on " << sliders[k].ground
        << (sliders[k].rolling ? " (rolling)" : "") << " |";
    for (const scenes::SlideRun& r : runs) {
      const scenes::SliderFigures& f = r.metrics.slide->sliders.at(k);
      out << " vy " << fmt("%.3f", f.max_vertical_speed) << ", ω "
          << fmt("%.2f", f.max_angular_speed) << ", " << percent(f.travel) << " |";
    }
    out << '\n';
  }
}

}  // namespace dyop::report
