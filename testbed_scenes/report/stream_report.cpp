#include "report/bench_sections.hpp"

#include <ostream>
#include <sstream>

#include "report/gnuplot.hpp"

namespace dyop::report {
namespace {

using experiments::StreamResult;
using experiments::StreamRunnerResult;

double share(std::uint64_t part, std::uint64_t whole) {
  return whole > 0 ? static_cast<double>(part) / static_cast<double>(whole) : 0;
}

// Face agreement is only defined where both manifolds have points; no such call: nothing to miss.
double face_share(const experiments::StreamAgreement& a) {
  return a.both_points > 0 ? share(a.same_face, a.both_points) : 1;
}

}  // namespace

Records stream_records(const std::vector<StreamResult>& results) {
  const unsigned files = where::files;
  const unsigned shown = where::table | where::markdown;
  Records out({{"scene", "scene", "", -13},
               {"steps", "steps", "", 6, files},
               {"contacts", "contacts", "", 8, files},
               {"calls", "calls", "", 8},
               {"world_evaluations", "world evaluations", "", 8, files},
               {"world_share", "of the world's", "world%", 6, shown},
               {"triangle_calls", "triangle calls", "", 8, files},
               {"triangle_share", "triangle pairs", "tri%", 6, shown},
               {"calls_with_points", "calls with points", "", 8, files},
               {"points_share", "with points", "pts%", 6, shown},
               {"runner", "runner", "", -10},
               {"ns_per_call", "ns/call", "", 8},
               {"ratio_vs_box2d_own", "× box2d-own", "xb2own", 7},
               {"same_point_count", "same count", "", 8, files},
               {"point_count_differs", "count differs", "count!=", 8, shown},
               {"both_points", "both with points", "", 8, files},
               {"same_face", "same face", "", 8, files},
               {"face_differs", "face differs", "face!=", 8, shown},
               {"same_face_share", "same face (of both with points)", "", 8, where::markdown},
               {"normal_angle_max_rad", "normal max (rad)", "normal", 9},
               {"separation_diff_max_m", "separation max (m)", "sep_m", 9}});
  for (const StreamResult& r : results) {
    for (const StreamRunnerResult& x : r.runners) {
      const experiments::StreamAgreement& a = x.agreement;
      auto percent = [](double v) { return Value::number(100 * v, "%.1f"); };
      out.add({Value::text(r.scene),
               Value::count(r.steps),
               Value::count(static_cast<std::int64_t>(r.contacts)),
               Value::count(static_cast<std::int64_t>(r.calls)),
               Value::count(static_cast<std::int64_t>(r.world_evaluations)),
               percent(share(r.calls, r.world_evaluations)),
               Value::count(static_cast<std::int64_t>(r.triangle_calls)),
               percent(share(r.triangle_calls, r.calls)),
               Value::count(static_cast<std::int64_t>(r.calls_with_points)),
               percent(share(r.calls_with_points, r.calls)),
               Value::text(scenes::name(x.runner)),
               Value::number(x.ns_per_call, "%.1f"),
               Value::number(x.ratio_vs_box2d_own, "%.3f"),
               Value::count(static_cast<std::int64_t>(a.same_point_count)),
               Value::count(static_cast<std::int64_t>(a.calls - a.same_point_count)),
               Value::count(static_cast<std::int64_t>(a.both_points)),
               Value::count(static_cast<std::int64_t>(a.same_face)),
               Value::count(static_cast<std::int64_t>(a.both_points - a.same_face)),
               Value::number(100 * face_share(a), "%.3f%%"),
               Value::number(a.normal_angle_max, "%.2e"),
               Value::metres(a.separation_diff_max)});
    }
  }
  return out;
}

std::string write_stream_outputs(const std::vector<StreamResult>& results, ReportDirectory& dir) {
  dir.write("streams.csv", [&](std::ostream& o) { stream_records(results).write_csv(o); });
  // One row per scene, one column per plug-in backend (box2d-own is 1 by definition).
  const std::size_t backends = results.empty() ? 0 : results.front().runners.size() - 1;
  dir.write("streams.dat", [&](std::ostream& o) {
    o << "# scene";
    for (std::size_t k = 0; k < backends; ++k)
      o << ' ' << scenes::name(results.front().runners[k].runner);
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
           << (k == 0 ? ":xtic(1)" : "") << " title '"
           << scenes::name(results.front().runners[k].runner) << "'";
  }
  script << "\n";
  if (backends > 0)
    dir.chart("streams", "svg size 1100,500 dynamic background rgb 'white'", script.str());

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
        "![contact streams](streams.svg)\n\n";
  stream_records(results).write_markdown(md);
  return md.str();
}

}  // namespace dyop::report
