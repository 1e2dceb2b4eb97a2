#include "report/rain_scaling_report.hpp"

#include <sstream>

#include "report/format.hpp"
#include "report/gnuplot.hpp"

namespace dyop::report {

using scenes::ScalingRecord;

void write_scaling_table(const std::vector<ScalingRecord>& records, std::ostream& out) {
  out << table_line("%-10s %7s %9s %10s %10s %10s %10s %8s %8s %8s %10s %5s\n", "backend",
                    "falling", "triangles", "step_ms", "np_ms", "np_ns/pair", "pairs/step",
                    "xbox2d", "np_xown", "step_xown", "pd_err_max", "fallb");
  for (const ScalingRecord& r : records) {
    out << table_line(
        "%-10s %7d %9d %10.3f %10.3f %10.1f %10.0f %8.3f %8.3f %8.3f %10.2e %5llu%s\n",
        r.backend.c_str(), r.falling, r.triangles, r.step_ms_median, r.narrowphase_ms_per_step,
        r.narrowphase_ns_per_pair, r.pairs_per_step, r.ratio_vs_box2d, r.ratio_vs_own,
        r.step_ratio_vs_own, r.pd_error_max, static_cast<unsigned long long>(r.fallbacks),
        r.nan_detected ? " NaN" : "");
  }
}

void write_scaling_csv(const std::vector<ScalingRecord>& records, std::ostream& out) {
  out << "backend,falling,triangles,steps,step_ms_median,narrowphase_ms_per_step,"
         "narrowphase_ns_per_pair,pairs_per_step,ratio_vs_box2d,ratio_vs_own,step_ratio_vs_own,"
         "pd_error_max,fallbacks,nan_detected\n";
  for (const ScalingRecord& r : records) {
    out << r.backend << ',' << r.falling << ',' << r.triangles << ',' << r.steps << ','
        << fmt("%.6g", r.step_ms_median) << ',' << fmt("%.6g", r.narrowphase_ms_per_step) << ','
        << fmt("%.6g", r.narrowphase_ns_per_pair) << ',' << fmt("%.6g", r.pairs_per_step) << ','
        << fmt("%.6g", r.ratio_vs_box2d) << ',' << fmt("%.6g", r.ratio_vs_own) << ','
        << fmt("%.6g", r.step_ratio_vs_own) << ',' << fmt("%.6g", r.pd_error_max) << ','
        << r.fallbacks << ',' << (r.nan_detected ? 1 : 0) << '\n';
  }
}

std::string write_scaling_outputs(const std::vector<ScalingRecord>& records,
                                  ReportDirectory& dir) {
  dir.write("scaling.csv", [&](std::ostream& o) { write_scaling_csv(records, o); });
  // One data block per backend (gnuplot's `index`), in the order of the records.
  std::vector<std::string> backends;
  for (const ScalingRecord& r : records) {
    bool seen = false;
    for (const std::string& b : backends) seen = seen || b == r.backend;
    if (!seen) backends.push_back(r.backend);
  }
  dir.write("rain_scaling.dat", [&](std::ostream& o) {
    for (const std::string& b : backends) {
      o << "# " << b << ": falling step_ms_median narrowphase_ms_per_step\n";
      for (const ScalingRecord& r : records) {
        if (r.backend == b) {
          write_data_line(o, std::to_string(r.falling),
                          {r.step_ms_median, r.narrowphase_ms_per_step});
        }
      }
      o << "\n\n";
    }
  });
  std::ostringstream script;
  script << "set multiplot layout 1,2 title 'rain: time per step against falling triangles'\n"
            "set logscale xy\nset grid\nset key top left\nset xlabel 'falling triangles'\n"
            "set xtics (100, 300, 1000, 3000)\n";
  const char* panels[2][2] = {{"3", "narrow phase (Box2D collide) ms per step"},
                              {"2", "whole step ms (median)"}};
  for (const auto& panel : panels) {
    script << "set ylabel '" << panel[1] << "'\nplot ";
    for (std::size_t i = 0; i < backends.size(); ++i) {
      script << (i ? ", \\\n     " : "") << dir.quoted("rain_scaling.dat") << " index " << i
             << " using 1:" << panel[0] << " with linespoints lw 2 title '" << backends[i] << "'";
    }
    script << "\n";
  }
  script << "unset multiplot\n";
  dir.chart("rain_scaling", "svg size 1100,500 dynamic background rgb 'white'", script.str());

  std::ostringstream md;
  md << "## Scaling: the rain scene\n\n`rain` with 100 to 3000 falling triangles into a bin of "
        "triangle fixtures, every backend, "
     << (records.empty() ? 0 : records.front().steps)
     << " steps of 1/60 s. Narrow phase: Box2D's `collide` time (every contact update, Box2D's "
        "own per-contact work included), per step; `× box2d` compares it with `b2CollidePolygons` "
        "through the plug-in at the same size. `× own` compares the narrow phase and the whole "
        "step (`b2World::Step`, summed over steps 2..N) with a run of Box2D's own contact, the "
        "plug-in not installed (`box2d-own`), made just before the backend's in the same "
        "process.\n\n![rain scaling](rain_scaling.svg)\n\n"
        "| backend | falling | triangles | step ms (median) | narrow phase ms/step | ns per pair | "
        "pairs per step | × box2d | narrow phase × own | step × own | depth error max (m) | "
        "fallbacks |\n"
        "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const ScalingRecord& r : records) {
    md << "| " << r.backend << " | " << r.falling << " | " << r.triangles << " | "
       << fmt("%.3f", r.step_ms_median) << " | " << fmt("%.3f", r.narrowphase_ms_per_step)
       << " | " << fmt("%.1f", r.narrowphase_ns_per_pair) << " | "
       << fmt("%.0f", r.pairs_per_step) << " | " << fmt("%.3f", r.ratio_vs_box2d) << " | "
       << fmt("%.3f", r.ratio_vs_own) << " | " << fmt("%.3f", r.step_ratio_vs_own) << " | "
       << metres(r.pd_error_max) << " | " << r.fallbacks
       << (r.nan_detected ? " (NaN)" : "") << " |\n";
  }
  return md.str();
}

}  // namespace dyop::report
