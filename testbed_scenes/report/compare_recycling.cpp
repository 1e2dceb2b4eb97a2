// `dyop compare`'s recycling section: run time against error of `Config::recycle_distance`, per
// scene, with the floor (`experiments/recycling_sweep.hpp`).
#include <cmath>
#include <sstream>

#include "experiments/recycling_sweep.hpp"
#include "report/compare_section.hpp"
#include "report/format.hpp"
#include "report/gnuplot.hpp"
#include "report/records.hpp"
#include "scenes/scene.hpp"

namespace dyop::report {
namespace {

using experiments::RecyclingRecord;
using experiments::SweepRow;

// The scenes swept: those whose contacts rest or pile up (where keeping pays or costs), and the
// slide, where bodies move fast over many edges. With `--quick` (when named by `--section`: the
// main command's run leaves the section out), the pyramid at off, the default and 20 mm; the full
// run sweeps them all.
const std::vector<std::string> kScenes = {"pyramid",   "stack",   "rain",
                                          "rain-tall", "tumbler", "slide"};
const std::vector<std::string> kQuickScenes = {"pyramid"};
const std::vector<float> kQuickDistances = {0.0f, box2d::default_recycle_distance, 0.02f};

const char* row_name(SweepRow r) {
  switch (r) {
    case SweepRow::Own:
      return scenes::box2d_own;
    case SweepRow::Plugin:
      return box2d::name(box2d::Backend::Dyop);  // the sweep's backend
    case SweepRow::Floor:
      return "floor";
  }
  return "?";
}

Value ratio(const RecyclingRecord& r, double (experiments::InWorldRatio::*f)() const) {
  return Value::number(r.timing ? ((*r.timing).*f)() : missing_figure, "%.2f");
}

Records sweep_records(const std::vector<RecyclingRecord>& rows) {
  Records out({{"scene", "scene", "", -10},
               {"runner", "runner", "", -10},
               {"recycle_distance_m", "distance [m]", "dist_m", 7},
               {"narrowphase_ratio", "narrow phase × own", "np_xown", 8},
               {"solve_toi_ratio", "SolveTOI × own", "toi_xown", 8},
               {"step_ratio", "step × own", "step_xown", 9},
               {"narrowphase_ms_own", "", "", 10, where::files},
               {"narrowphase_ms", "", "", 10, where::files},
               {"step_ms_own", "", "", 10, where::files},
               {"step_ms", "", "", 10, where::files},
               {"recycled_share", "kept [%]", "kept%", 6},
               {"kept_error_max_m", "kept vs fresh [m]", "kept_err", 9},
               {"stale", "stale", "", 7},
               {"depth_error_max_m", "depth error [m]", "depth_err", 9},
               {"normal_error_max_m", "normal error [m]", "norm_err", 9},
               {"max_penetration_m", "max penetration [m]", "max_pen", 9},
               {"top_displacement_m", "top drift [m]", "top", 9},
               {"slide_min_travel", "slide travel [%]", "travel%", 8},
               {"slide_max_vertical_speed", "slide max vy [m/s]", "vy", 8}});
  for (const RecyclingRecord& r : rows) {
    const scenes::SceneMetrics* a = r.accuracy ? &*r.accuracy : nullptr;
    const scenes::ManifoldErrors* e = a && a->manifold_errors ? &*a->manifold_errors : nullptr;
    const auto metres = [](bool has, double v) { return Value::metres(has ? v : missing_figure); };
    const bool slide = a && a->slide;
    out.add(
        {Value::text(r.scene), Value::text(row_name(r.row)),
         Value::number(r.row == SweepRow::Plugin ? r.distance : missing_figure, "%.3f"),
         ratio(r, &experiments::InWorldRatio::narrowphase_ratio),
         ratio(r, &experiments::InWorldRatio::solve_toi_ratio),
         ratio(r, &experiments::InWorldRatio::step_ratio),
         Value::number(r.timing ? r.timing->own.narrowphase_ms : missing_figure, "%.3f"),
         Value::number(r.timing ? r.timing->plugin.narrowphase_ms : missing_figure, "%.3f"),
         Value::number(r.timing ? r.timing->own.step_ms : missing_figure, "%.3f"),
         Value::number(r.timing ? r.timing->plugin.step_ms : missing_figure, "%.3f"),
         Value::number(r.row == SweepRow::Plugin ? 100 * r.recycled_share : missing_figure, "%.1f"),
         metres(e, e ? e->kept_max : 0),
         e ? Value::count(static_cast<std::int64_t>(e->stale)) : Value::text("n/a"),
         metres(e, e ? e->depth_max : 0), metres(e, e ? e->normal_max : 0),
         metres(a, a ? a->max_penetration : 0),
         metres(a && a->top_displacement, a && a->top_displacement ? *a->top_displacement : 0),
         Value::number(slide ? 100 * a->slide->min_travel : missing_figure, "%.1f"),
         Value::number(slide ? a->slide->max_vertical_speed : missing_figure, "%.4f")});
  }
  return out;
}

class RecyclingSection : public CompareSection {
 public:
  const char* section_name() const override { return "recycling"; }
  bool in_quick_run() const override { return false; }
  void run(const SectionContext& c) override {
    experiments::RecyclingSweepOptions o;
    for (const std::string& name : c.options.quick ? kQuickScenes : kScenes) {
      if (c.selected(name)) o.scenes.push_back(name);
    }
    if (o.scenes.empty()) return;
    if (c.options.quick) o.distances = kQuickDistances;
    o.steps = [&c](const std::string& name) { return c.steps(*scenes::find_scene(name)); };
    o.repetitions = experiments::in_world_repetitions(c.options.quick);
    o.seed = c.options.seed;
    o.config = c.options.skips;
    quick_ = c.options.quick;
    rows_ = experiments::run_recycling_sweep(o, c.progress);
  }

  bool measured() const override { return !rows_.empty(); }

  void write_tables(std::ostream& out) const override {
    out << "\nManifold recycling: run time against error (dyop against Box2D's own contact):\n\n";
    sweep_records(rows_).write_table(out);
  }

  // Narrow phase × own against the distance, one line per scene, the floor as a point at the
  // right edge of each scene's line; and the kept manifolds' error against the distance.
  void write_files(ReportDirectory& dir, Charts& charts) const override {
    dir.write("recycling.csv", [&](std::ostream& o) { sweep_records(rows_).write_csv(o); });
    std::vector<std::string> scenes;
    for (const RecyclingRecord& r : rows_) {
      if (scenes.empty() || scenes.back() != r.scene) scenes.push_back(r.scene);
    }
    dir.write("recycling.dat", [&](std::ostream& o) {
      for (const std::string& s : scenes) {
        // A header line per block: the plots take each block's first line as its title
        // (`columnheader`), and would take the first distance's figures for it otherwise.
        o << s << " distance_mm narrowphase_x_own step_x_own kept_error_mm\n";
        for (const RecyclingRecord& r : rows_) {
          if (r.scene != s || r.row != SweepRow::Plugin) continue;
          const double kept = r.accuracy && r.accuracy->manifold_errors
                                  ? r.accuracy->manifold_errors->kept_max
                                  : missing_figure;
          write_data_line(o, s,
                          {1000.0 * r.distance, r.timing->narrowphase_ratio(),
                           r.timing->step_ratio(), 1000.0 * kept});
        }
        o << "\n\n";
      }
    });
    std::ostringstream plot;
    plot << "set multiplot layout 1,2 title 'Manifold recycling: run time against error (dyop, "
            "each scene against Box2D''s own contact)'\n"
         << "set grid\nset key top right font ',9'\nset xlabel 'recycle distance [mm]'\n"
         << "set title 'narrow phase × own (solid) and step × own (dashed)'\nset yrange [0:*]\n"
         << "plot for [i=0:" << scenes.size() - 1 << "] " << dir.quoted("recycling.dat")
         << " index i using 2:3 with linespoints lc i+1 title columnheader(1), \\\n"
         << "     for [i=0:" << scenes.size() - 1 << "] " << dir.quoted("recycling.dat")
         << " index i using 2:4 with lines dt 2 lc i+1 notitle\n"
         << "set title 'kept manifold vs fresh, largest separation error [mm]'\n"
         << "plot for [i=0:" << scenes.size() - 1 << "] " << dir.quoted("recycling.dat")
         << " index i using 2:5 with linespoints lc i+1 title columnheader(1)\n"
         << "unset multiplot\n";
    charts.draw(dir, "recycling", "svg size 1100,480 dynamic font 'sans,11' background '#ffffff'",
                plot.str());
  }

  void write_markdown(std::ostream& o, const Charts& charts) const override {
    o << "## Manifold recycling: run time against error\n\n"
      << "`Config::recycle_distance` keeps a contact's manifold while the pair's relative pose "
         "moved less than the distance since it was computed. Per scene: `box2d-own` is Box2D's "
         "own contact (its accuracy: the yardstick); each `dyop` row runs the plug-in at one "
         "distance against Box2D's own contact, alternating ("
      << experiments::in_world_repetitions(quick_)
      << " runs each; **× own** below 1: faster), then once more with every manifold the solver "
         "got checked: **kept vs fresh** is how far the deepest separation the solver used was "
         "from the manifold the contact would compute afresh at that pose, **stale** the kept "
         "manifolds with points where the fresh one has none, **depth** and **normal error** "
         "against the exact answer on pairs whose cores penetrate. `floor` is `dyop` never "
         "recomputing after its first answer: what Box2D 2.4's own contact walk costs, the "
         "limit of any narrow phase plugged into it (its world is wrong; only its times "
         "count).\n\n";
    sweep_records(rows_).write_markdown(o);
    o << '\n';
    charts.image(o, "recycling", "recycling: narrow phase and step against distance, and error");
  }

  std::string files() const override {
    return "`recycling.csv` (the recycling sweep: times against Box2D's own contact and errors "
           "per distance, with the floor)";
  }

 private:
  std::vector<RecyclingRecord> rows_;
  bool quick_ = false;
};

}  // namespace

std::unique_ptr<CompareSection> make_recycling_section() {
  return std::make_unique<RecyclingSection>();
}

}  // namespace dyop::report
