// `dyop compare`'s CSV files: the main table, the skip runs, the in-world runs, and the paper
// experiment's.
#include <algorithm>
#include <optional>

#include "report/compare_report_files.hpp"
#include "report/compare_tables.hpp"
#include "report/format.hpp"
#include "scenes/metrics_io.hpp"
#include "scenes/skips.hpp"

namespace dyop::report {

void write_in_world_csv(const std::vector<scenes::InWorldRatio>& rows, std::ostream& out) {
  out << "scene,backend,steps,repetitions,narrowphase_ms_own,narrowphase_ms,narrowphase_ratio,"
         "step_ms_own,step_ms,step_ratio,step_ms_median_own,step_ms_median,contact_updates_own,"
         "contact_updates\n";
  for (const scenes::InWorldRatio& r : rows) {
    out << r.scene << ',' << r.backend << ',' << r.steps << ',' << r.repetitions << ','
        << fmt("%.6g", r.own.narrowphase_ms) << ',' << fmt("%.6g", r.plugin.narrowphase_ms) << ','
        << fmt("%.6g", r.narrowphase_ratio()) << ',' << fmt("%.6g", r.own.step_ms) << ','
        << fmt("%.6g", r.plugin.step_ms) << ',' << fmt("%.6g", r.step_ratio()) << ','
        << fmt("%.6g", r.own.step_ms_median) << ',' << fmt("%.6g", r.plugin.step_ms_median) << ','
        << r.own.contact_updates << ',' << r.plugin.contact_updates << '\n';
  }
}

namespace detail {

using namespace dyop::scenes;

void write_compare_csv(const CompareRun& run, std::ostream& o) {
  o << csv_header() << ",ratio_to_box2d\n";
  for (const SceneMetrics& m : run.rows) {
    const std::optional<double> r = ratio_to_box2d(run, m);
    o << csv_row(m) << ',' << (r ? fmt("%.6g", *r) : "") << '\n';
  }
}

// One row per run with skips on (the `--skip` one, then each skip alone) against its `none` run.
void write_skips_csv(const CompareRun& run, std::ostream& o) {
  o << "scene,backend,steps,skips,contact_updates_on,contact_updates_off,"
       "narrowphase_ns_per_pair_on,narrowphase_ns_per_pair_off,narrowphase_ratio,"
       "narrowphase_ms_on,narrowphase_ms_off,step_ms_median_on,step_ms_median_off,step_ratio,"
       "hash_on,hash_off,hashes_equal,plugin_evaluations";
  for (int s = 0; s < box2d::skip_count; ++s) {
    o << ",skipped_" << box2d::name(static_cast<box2d::Skip>(s));
  }
  o << '\n';
  for (const SkipMeasurement& m : run.skips) {
    std::vector<const SceneMetrics*> on = {&m.on};
    for (const SceneMetrics& a : m.alone) on.push_back(&a);
    for (const SceneMetrics* r : on) {
      // A skip list has commas: quoted, as CSV does.
      o << r->scene << ',' << r->backend << ',' << r->steps << ",\""
        << (r->skip_config ? skip_argument(*r->skip_config) : "") << "\"," << r->contact_updates
        << ',' << m.off.contact_updates << ',' << fmt("%.6g", r->narrowphase_ns_per_pair) << ','
        << fmt("%.6g", m.off.narrowphase_ns_per_pair) << ','
        << fmt("%.6g", narrowphase_ratio(*r, m.off)) << ','
        << fmt("%.6g", r->narrowphase_ms_total) << ',' << fmt("%.6g", m.off.narrowphase_ms_total)
        << ',' << fmt("%.6g", r->step_ms_median) << ',' << fmt("%.6g", m.off.step_ms_median)
        << ',' << fmt("%.6g", r->step_ms_median / m.off.step_ms_median) << ','
        << hash_hex(r->hash) << ',' << hash_hex(m.off.hash) << ','
        << (r->hash == m.off.hash ? "true" : "false") << ',' << r->plugin_evaluations.value_or(0);
      for (int s = 0; s < box2d::skip_count; ++s) o << ',' << (r->skips ? (*r->skips)[s] : 0);
      o << '\n';
    }
  }
}

// type, size, then one column per method (µs); `sep` ',' for CSV, ' ' for gnuplot.
void write_figure7_data(const CompareRun& run, std::ostream& o, char sep) {
  const paper::Experiment& e = *run.paper;
  o << "type" << sep << "size" << sep << "pairs";
  for (const auto& m : e.methods) o << sep << name(m.method);
  o << '\n';
  for (int k = 0; k < paper::type_count; ++k) {
    const auto& t = paper::triangle_types()[k];
    const double size =
        std::max({(t[1] - t[0]).norm(), (t[2] - t[1]).norm(), (t[0] - t[2]).norm()});
    o << k + 1 << sep << fmt("%.4g", size) << sep << e.pairs_per_type[k];
    for (const auto& m : e.methods) o << sep << fmt("%.6g", m.us_per_type[k]);
    o << '\n';
  }
}

void write_paper_methods_csv(const CompareRun& run, std::ostream& o) {
  const paper::Experiment& e = *run.paper;
  o << "method,us_overlapping_pairs,ns_per_pair,us_all_pairs,error_max,error_mean,"
       "misclassified,invalid,pairs_tested,pairs_penetrating,steps,repetitions\n";
  for (const auto& m : e.methods) {
    o << name(m.method) << ',' << fmt("%.6g", m.us_total) << ','
      << fmt("%.6g", m.ns_per_pair) << ',' << fmt("%.6g", m.us_all_pairs) << ','
      << fmt("%.6g", m.error_max) << ',' << fmt("%.6g", m.error_mean) << ',' << m.misclassified
      << ',' << m.invalid << ',' << e.pairs_tested << ',' << e.pairs_penetrating << ',' << e.steps
      << ',' << e.repetitions << '\n';
  }
}

// One row per runner and slider; the resting box's jitter is the runner's, repeated on its rows.
void write_slide_csv(const CompareRun& run, std::ostream& o) {
  o << "runner,body,ground,rolling,steps,internal_edges,max_vertical_speed,max_angular_speed,"
       "travel,resting_jitter\n";
  for (const SlideRun& r : run.slide) {
    const SceneMetrics& m = r.metrics;
    if (!m.slide) continue;
    for (const SliderFigures& f : m.slide->sliders) {
      o << m.backend << ',' << f.body << ',' << f.ground << ',' << (f.rolling ? "true" : "false")
        << ',' << m.steps << ','
        << (m.backend == box2d_own ? "" : run.options.skips.internal_edges ? "true" : "false")
        << ',' << fmt("%.6g", f.max_vertical_speed) << ',' << fmt("%.6g", f.max_angular_speed)
        << ',' << fmt("%.6g", f.travel) << ','
        << (m.top_displacement ? fmt("%.6g", *m.top_displacement) : "") << '\n';
    }
  }
}

}  // namespace detail
}  // namespace dyop::report
