// `dyop compare`'s in-world section: its runs, table, CSV, chart and Markdown.
#include "report/compare_in_world.hpp"

#include <algorithm>
#include <sstream>
#include <thread>

#include "report/compare_summary.hpp"
#include "report/format.hpp"
#include "report/gnuplot.hpp"
#include "experiments/progress.hpp"
#include "scenes/scene.hpp"

namespace dyop::report {

using experiments::InWorldRatio;

Records in_world_records(const std::vector<InWorldRatio>& rows) {
  Records out({{"scene", "scene", "", -14},
               {"backend", "backend", "", -10},
               {"steps", "steps", "", 6},
               {"repetitions", "runs", "runs", 5},
               {"narrowphase_ms_own", "narrow phase ms own", "np_ms_own", 10},
               {"narrowphase_ms", "narrow phase ms", "np_ms", 10},
               {"narrowphase_ratio", "× own", "np_xown", 8},
               {"step_ms_own", "step ms own", "step_ms_own", 11},
               {"step_ms", "step ms", "", 10},
               {"step_ratio", "× own", "step_xown", 9},
               {"step_ms_median_own", "", "", 10, where::files},
               {"step_ms_median", "", "", 10, where::files},
               {"contact_updates_own", "contact updates own", "updates_own", 11},
               {"contact_updates", "contact updates, plug-in", "updates", 10},
               {"solve_toi_ratio", "SolveTOI × own", "toi_xown", 8},
               {"toi_swept_own", "swept for TOI own", "toi_swept_own", 11},
               {"toi_swept", "swept for TOI, plug-in", "toi_swept", 10},
               {"contacts_made", "plug-in: contacts made", "made", 9},
               {"kept", "kept", "kept", 9},
               {"skipped", "skipped", "skipped", 9},
               {"answered", "answered afresh", "answered", 9}});
  for (const InWorldRatio& r : rows) {
    out.add(
        {Value::text(r.scene),
         Value::text(box2d::name(r.backend)),
         Value::count(r.steps),
         Value::count(r.repetitions),
         Value::number(r.own.narrowphase_ms, "%.2f"),
         Value::number(r.plugin.narrowphase_ms, "%.2f"),
         Value::number(r.narrowphase_ratio(), "%.2f"),
         Value::number(r.own.step_ms, "%.1f"),
         Value::number(r.plugin.step_ms, "%.1f"),
         Value::number(r.step_ratio(), "%.2f"),
         Value::number(r.own.step_ms_median, "%.3f"),
         Value::number(r.plugin.step_ms_median, "%.3f"),
         Value::count(static_cast<std::int64_t>(r.own.contact_updates)),
         Value::count(static_cast<std::int64_t>(r.plugin.contact_updates)),
         r.own.solve_toi_ms > 0 ? Value::number(r.solve_toi_ratio(), "%.2f") : Value::text("n/a"),
         Value::count(static_cast<std::int64_t>(r.own.toi_swept)),
         Value::count(static_cast<std::int64_t>(r.plugin.toi_swept)),
         Value::count(static_cast<std::int64_t>(r.plugin.contacts_made)),
         Value::count(static_cast<std::int64_t>(r.plugin.kept)),
         Value::count(static_cast<std::int64_t>(r.plugin.skipped)),
         Value::count(static_cast<std::int64_t>(r.plugin.answered))});
  }
  return out;
}

void InWorldSection::run(const SectionContext& c) {
  using experiments::detail::fixed;
  quick_ = c.options.quick;
  const int reps = experiments::in_world_repetitions(c.options.quick);
  for (const scenes::SceneInfo* s : c.scenes) {
    if (std::string(s->name) == "paper") continue;  // no Box2D world
    if (c.options.quick && experiments::left_out_of_quick_sections(s->name)) continue;
    const int steps = c.steps(*s);
    for (box2d::Backend b : experiments::in_world_backends(c.options)) {
      const double start = c.elapsed();
      rows_.push_back(experiments::measure_in_world(s->name, b, reps, [&](const scenes::Runner& r) {
        return scenes::run_scene(s->name, r, steps, c.options.seed, c.options.skips);
      }));
      const InWorldRatio& m = rows_.back();
      c.progress << "[in-world] " << s->name << " / " << box2d::name(b) << " against "
                 << scenes::box2d_own << ", " << reps << " times each: narrow phase "
                 << fixed(m.narrowphase_ratio(), 2) << "x, step " << fixed(m.step_ratio(), 2)
                 << "x, " << fixed(c.elapsed() - start, 2) << " s (total " << fixed(c.elapsed(), 1)
                 << " s)\n"
                 << std::flush;
    }
  }
}

void InWorldSection::write_tables(std::ostream& out) const {
  out << "\nIn the world, against Box2D's own contact (plug-in not installed):\n\n";
  in_world_records(rows_).write_markdown(out);
}

// Narrow-phase and step ratios to Box2D's own contact: clustered bars, one group per scene, one
// bar per backend, narrow phase above and step below.
void InWorldSection::write_files(ReportDirectory& dir, Charts& charts) const {
  dir.write("inworld.csv", [&](std::ostream& o) { in_world_records(rows_).write_csv(o); });
  std::vector<box2d::Backend> backends;
  std::vector<std::string> scene_order;
  for (const InWorldRatio& r : rows_) {
    if (std::find(backends.begin(), backends.end(), r.backend) == backends.end()) {
      backends.push_back(r.backend);
    }
    if (scene_order.empty() || scene_order.back() != r.scene) scene_order.push_back(r.scene);
  }
  auto ratio = [&](const std::string& scene, box2d::Backend backend, bool step) {
    for (const InWorldRatio& r : rows_) {
      if (r.scene == scene && r.backend == backend) {
        return step ? r.step_ratio() : r.narrowphase_ratio();
      }
    }
    return missing_figure;
  };
  for (const bool step : {false, true}) {
    dir.write(step ? "inworld_step.dat" : "inworld_collide.dat", [&](std::ostream& o) {
      o << "scene";
      for (const box2d::Backend b : backends) o << ' ' << box2d::name(b);
      o << '\n';
      for (const std::string& s : scene_order) {
        std::vector<double> ratios;
        for (const box2d::Backend b : backends) ratios.push_back(ratio(s, b, step));
        write_data_line(o, s, ratios);
      }
    });
  }
  std::ostringstream bars;
  bars << "set multiplot layout 2,1 title 'In the world: time with the plug-in over time with "
          "Box2D''s own contact (below 1: the plug-in is faster)'\n"
       << "set style data histograms\nset style histogram clustered gap 1\n"
       << "set style fill solid 0.85 border -1\nset grid ytics\nset yrange [0:*]\n"
       << "set xtics nomirror font ',9'\nset key outside right top\n"
       << "set arrow 1 from graph 0, first 1 to graph 1, first 1 nohead dt 2\n";
  for (const bool step : {false, true}) {
    bars << "set title '"
         << (step ? "whole step (b2World::Step)" : "narrow phase (b2Profile::collide)")
         << "'\nset ylabel '× " << scenes::box2d_own << "'\n"
         << "plot for [i=2:" << backends.size() + 1 << "] "
         << dir.quoted(step ? "inworld_step.dat" : "inworld_collide.dat")
         << " using i:xtic(1) title columnheader(i)\n";
  }
  bars << "unset multiplot\n";
  charts.draw(dir, "inworld", "svg size 1000,760 dynamic font 'sans,11' background '#ffffff'",
              bars.str());
}

void InWorldSection::write_markdown(std::ostream& o, const Charts& charts) const {
  o << "## In the world, against Box2D's own contact\n\n"
    << "What a user who installs the plug-in feels: each Box2D scene runs under Box2D's own "
       "contact with the plug-in **not installed** (`"
    << scenes::box2d_own << "`) and under the backend, alternately (own, backend, own, backend, "
    << "...; " << experiments::in_world_repetitions(quick_)
    << " runs of each) in this process, same seed and steps as the table above. Each side's "
       "figure is the median over its runs of the narrow phase (`b2Profile::collide`, summed "
       "over steps 2..N) and of the whole step (`b2World::Step`'s wall time, summed over the "
       "same steps: the solver and the time-of-impact pass included). **× own** is the "
       "backend's figure over Box2D's own: below 1 the plug-in is faster. The worlds evolve "
       "alike but not bit for bit (`box2d` excepted), so each side's contact updates are "
       "given, and the plug-in's evaluations over its whole first run by kind: contacts made, "
       "evaluations that kept the manifold, skipped, and answered afresh (what costs). "
       "Machine: "
    << std::thread::hardware_concurrency()
    << " hardware threads; ratios move between machines of one kind, name the machine with "
       "them.\n\n";
  in_world_records(rows_).write_markdown(o);
  o << '\n';
  charts.image(o, "inworld", "narrow-phase and step time against Box2D's own contact");
}

std::string InWorldSection::files() const {
  return "`inworld.csv` (every scene and backend against Box2D's own contact)";
}

void InWorldSection::summarize(SummaryFigures& figures) const {
  for (const InWorldRatio& r : rows_) {
    if (r.backend == box2d::Backend::Dyop) {
      figures.wall_times.push_back({r.scene, r.narrowphase_ratio(), r.step_ratio()});
    }
  }
}

}  // namespace dyop::report
