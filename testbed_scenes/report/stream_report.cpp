#include "report/stream_report.hpp"

#include <ostream>
#include <sstream>

#include "report/format.hpp"
#include "report/gnuplot.hpp"

namespace dyop::report {
namespace {

using scenes::StreamResult;
using scenes::StreamRunnerResult;

double share(std::uint64_t part, std::uint64_t whole) {
  return whole > 0 ? static_cast<double>(part) / static_cast<double>(whole) : 0;
}

// Face agreement is only defined where both manifolds have points; no such call: nothing to miss.
double face_share(const scenes::StreamAgreement& a) {
  return a.both_points > 0 ? share(a.same_face, a.both_points) : 1;
}

}  // namespace

void write_stream_table(const std::vector<StreamResult>& results, std::ostream& out) {
  out << table_line("%-13s %-10s %8s %6s %6s %6s %8s %7s %8s %8s %9s %9s\n", "scene", "runner",
                    "calls", "world%", "tri%", "pts%", "ns/call", "xb2own", "count!=", "face!=",
                    "normal", "sep_m");
  for (const StreamResult& r : results) {
    for (const StreamRunnerResult& x : r.runners) {
      const scenes::StreamAgreement& a = x.agreement;
      out << table_line(
          "%-13s %-10s %8llu %6.1f %6.1f %6.1f %8.1f %7.3f %8llu %8llu %9.2e %9.2e\n",
          r.scene.c_str(), x.runner.c_str(), static_cast<unsigned long long>(r.calls),
          100 * share(r.calls, r.world_evaluations), 100 * share(r.triangle_calls, r.calls),
          100 * share(r.calls_with_points, r.calls), x.ns_per_call, x.ratio_vs_box2d_own,
          static_cast<unsigned long long>(a.calls - a.same_point_count),
          static_cast<unsigned long long>(a.both_points - a.same_face), a.normal_angle_max,
          a.separation_diff_max);
    }
  }
}

void write_stream_csv(const std::vector<StreamResult>& results, std::ostream& out) {
  out << "scene,steps,contacts,calls,world_evaluations,triangle_calls,calls_with_points,runner,ns_per_call,"
         "ratio_vs_box2d_own,same_point_count,both_points,same_face,normal_angle_max_rad,"
         "separation_diff_max_m\n";
  for (const StreamResult& r : results) {
    for (const StreamRunnerResult& x : r.runners) {
      const scenes::StreamAgreement& a = x.agreement;
      out << r.scene << ',' << r.steps << ',' << r.contacts << ',' << r.calls << ','
          << r.world_evaluations << ',' << r.triangle_calls << ',' << r.calls_with_points << ',' << x.runner << ','
          << fmt("%.6g", x.ns_per_call) << ',' << fmt("%.6g", x.ratio_vs_box2d_own) << ','
          << a.same_point_count << ',' << a.both_points << ',' << a.same_face << ','
          << fmt("%.6g", a.normal_angle_max) << ',' << fmt("%.6g", a.separation_diff_max) << '\n';
    }
  }
}

std::string write_stream_outputs(const std::vector<StreamResult>& results,
                                 ReportDirectory& dir) {
  dir.write("streams.csv", [&](std::ostream& o) { write_stream_csv(results, o); });
  // One row per scene, one column per plug-in backend (box2d-own is 1 by definition).
  const std::size_t backends = results.empty() ? 0 : results.front().runners.size() - 1;
  dir.write("streams.dat", [&](std::ostream& o) {
    o << "# scene";
    for (std::size_t k = 0; k < backends; ++k) o << ' ' << results.front().runners[k].runner;
    o << " (ratio of ns per call to box2d-own)\n";
    for (const StreamResult& r : results) {
      std::vector<double> ratios;
      for (std::size_t k = 0; k < backends; ++k) ratios.push_back(r.runners[k].ratio_vs_box2d_own);
      write_data_line(o, r.scene, ratios);
    }
  });
  std::ostringstream script;
  script << "set title 'Contact streams: ns per call relative to b2CollidePolygons (box2d-own = "
            "1)'\n"
            "set style data histograms\nset style histogram clustered gap 1\n"
            "set style fill solid 0.8 border -1\nset boxwidth 0.9\nset grid ytics\n"
            "set key outside right top\nset xtics nomirror\nset ylabel 'ratio to box2d-own'\n"
            "set yrange [0:*]\nset arrow from graph 0, first 1 to graph 1, first 1 nohead dt 2\n"
            "plot ";
  for (std::size_t k = 0; k < backends; ++k) {
    script << (k ? ", \\\n     " : "") << dir.quoted("streams.dat") << " using " << k + 2
           << (k == 0 ? ":xtic(1)" : "") << " title '" << results.front().runners[k].runner << "'";
  }
  script << "\n";
  if (backends > 0) dir.chart("streams", "svg size 1100,500 dynamic background rgb 'white'", script.str());

  std::ostringstream md;
  md << "## Contact streams\n\nEvery polygon-pair contact update of each Box2D scene's `Collide`, "
        "recorded under Box2D's own contact ("
     << (results.empty() ? 0 : results.front().steps)
     << " steps, step 1 left out), then replayed through the plug-in's `collide_polygons` with one "
        "`ContactMemory` per contact (default skips) and through `b2CollidePolygons` directly "
        "(box2d-own). `of the world's`: the calls' share of the world's own polygon-pair "
        "evaluations in the same steps (the rest are Box2D's time-of-impact re-evaluations, not "
        "recorded). Times: best pass, ns per call over the whole stream; `× box2d-own` in the "
        "same run. Agreement with `b2CollidePolygons`, call by call: same point count; same "
        "reference face among calls where both have points; largest world-normal angle (rad) and "
        "deepest-separation difference (m) among those calls.\n\n"
        "![contact streams](streams.svg)\n\n"
        "| scene | runner | calls | of the world's | triangle pairs | with points | ns/call | "
        "× box2d-own | same count | same face | normal max (rad) | separation max (m) |\n"
        "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const StreamResult& r : results) {
    for (const StreamRunnerResult& x : r.runners) {
      const scenes::StreamAgreement& a = x.agreement;
      md << "| " << r.scene << " | " << x.runner << " | " << r.calls << " | "
         << fmt("%.1f%%", 100 * share(r.calls, r.world_evaluations)) << " | "
         << fmt("%.1f%%", 100 * share(r.triangle_calls, r.calls)) << " | "
         << fmt("%.1f%%", 100 * share(r.calls_with_points, r.calls)) << " | "
         << fmt("%.1f", x.ns_per_call) << " | " << fmt("%.3f", x.ratio_vs_box2d_own) << " | "
         << fmt("%.3f%%", 100 * share(a.same_point_count, a.calls)) << " ("
         << a.calls - a.same_point_count << " differ) | " << fmt("%.3f%%", 100 * face_share(a))
         << " (" << a.both_points - a.same_face << " differ) | " << fmt("%.2e", a.normal_angle_max)
         << " | " << metres(a.separation_diff_max) << " |\n";
    }
  }
  return md.str();
}

}  // namespace dyop::report
