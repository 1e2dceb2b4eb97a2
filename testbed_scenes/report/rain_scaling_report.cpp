#include "report/bench_sections.hpp"

#include <algorithm>
#include <sstream>

#include "report/gnuplot.hpp"

namespace dyop::report {

using experiments::ScalingRecord;

Records scaling_records(const std::vector<ScalingRecord>& records) {
  Records out({{"runner", "runner", "", -10},
               {"falling", "falling", "", 7},
               {"triangles", "triangles", "", 9},
               {"steps", "steps", "", 6, where::files},
               {"step_ms_median", "step ms (median)", "step_ms", 10},
               {"narrowphase_ms_per_step", "narrow phase ms/step", "np_ms", 10},
               {"narrowphase_ns_per_pair", "ns per pair", "np_ns/pair", 10},
               {"pairs_per_step", "pairs per step", "pairs/step", 10},
               {"ratio_vs_box2d", "× box2d", "xbox2d", 8},
               {"ratio_vs_own", "narrow phase × own", "np_xown", 8},
               {"step_ratio_vs_own", "step × own", "step_xown", 9},
               {"pd_error_max", "depth error max (m)", "pd_err_max", 10},
               {"fallbacks", "fallbacks", "fallb", 5},
               {"nan_detected", "NaN", "nan", 3}});
  for (const ScalingRecord& r : records) {
    out.add({Value::text(scenes::name(r.runner)), Value::count(r.falling),
             Value::count(r.triangles), Value::count(r.steps),
             Value::number(r.step_ms_median, "%.3f"),
             Value::number(r.narrowphase_ms_per_step, "%.3f"),
             Value::number(r.narrowphase_ns_per_pair, "%.1f"),
             Value::number(r.pairs_per_step, "%.0f"), Value::number(r.ratio_vs_box2d, "%.3f"),
             Value::number(r.ratio_vs_own, "%.3f"), Value::number(r.step_ratio_vs_own, "%.3f"),
             Value::metres(r.pd_error_max), Value::count(static_cast<std::int64_t>(r.fallbacks)),
             Value::count(r.nan_detected ? 1 : 0)});
  }
  return out;
}

std::string write_scaling_outputs(const std::vector<ScalingRecord>& records, ReportDirectory& dir) {
  dir.write("scaling.csv", [&](std::ostream& o) { scaling_records(records).write_csv(o); });
  // One data block per runner (gnuplot's `index`), in the order of the records.
  std::vector<scenes::Runner> runners;
  for (const ScalingRecord& r : records) {
    if (std::find(runners.begin(), runners.end(), r.runner) == runners.end()) {
      runners.push_back(r.runner);
    }
  }
  dir.write("rain_scaling.dat", [&](std::ostream& o) {
    for (const scenes::Runner& b : runners) {
      o << "# " << scenes::name(b) << ": falling step_ms_median narrowphase_ms_per_step\n";
      for (const ScalingRecord& r : records) {
        if (r.runner == b) {
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
    for (std::size_t i = 0; i < runners.size(); ++i) {
      script << (i ? ", \\\n     " : "") << dir.quoted("rain_scaling.dat") << " index " << i
             << " using 1:" << panel[0] << " with linespoints lw 2 title '"
             << scenes::name(runners[i]) << "'";
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
        "process.\n\n![rain scaling](rain_scaling.svg)\n\n";
  scaling_records(records).write_markdown(md);
  return md.str();
}

}  // namespace dyop::report
