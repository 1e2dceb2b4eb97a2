// `dyop compare`'s slide section: the sliding scenes (`slide`, `tiles`) under Box2D's own contact
// and the plug-in's backends (`experiments/slide_run.hpp`), side by side: tables, CSV, the
// sliders' paths, final states; one part per scene, its files named after it.
#include <sstream>

#include "report/compare_section.hpp"
#include "report/compare_summary.hpp"
#include "report/format.hpp"
#include "report/records.hpp"
#include "report/svg.hpp"
#include "experiments/progress.hpp"
#include "scenes/scene.hpp"
#include "experiments/slide_run.hpp"

namespace dyop::report {
namespace {

using experiments::SlideRun;

std::string percent(double fraction) { return fmt("%.1f", 100 * fraction) + " %"; }

class SlideSection : public CompareSection {
 public:
  const char* section_name() const override { return "slide"; }
  void run(const SectionContext& c) override {
    using experiments::detail::fixed;
    internal_edges_ = c.options.skips.internal_edges;
    for (const scenes::SceneInfo* s : c.scenes) {
      const std::string scene = s->name;
      if (scene != "slide" && scene != "tiles") continue;
      const int steps = c.steps(*s);
      parts_.push_back({scene, {}});
      for (const scenes::Runner& r : experiments::slide_runners(c.options.quick)) {
        const double start = c.elapsed();
        parts_.back().runs.push_back(
            experiments::run_slide(r, steps, c.options.seed, c.options.skips, scene));
        c.progress << "[" << scene << "] " << scenes::name(r) << ", " << steps
                   << " steps, paths recorded: " << fixed(c.elapsed() - start, 2) << " s (total "
                   << fixed(c.elapsed(), 1) << " s)\n"
                   << std::flush;
      }
    }
  }

  bool measured() const override { return !parts_.empty(); }

  void write_tables(std::ostream& out) const override {
    for (const Part& p : parts_) {
      out << "\nSliding over triangulated grounds (scene `" << p.scene
          << "`), Box2D's own contact against the plug-in:\n\n";
      tables(p, out);
    }
  }

  void write_files(ReportDirectory& dir, Charts& charts) const override {
    for (const Part& p : parts_) {
      dir.write(p.scene + ".csv", [&](std::ostream& o) { slider_records(p).write_csv(o); });
      for (const SlideRun& r : p.runs) {
        dir.write(p.scene + "_" + std::string(scenes::name(r.metrics.runner)) + ".svg",
                  [&](std::ostream& o) { report::write_svg(r.final_state, o); });
      }
      paths_chart(p, dir, charts);
    }
  }

  void write_markdown(std::ostream& o, const Charts& charts) const override {
    for (const Part& p : parts_) {
      if (p.scene == "slide") {
        slide_intro(o);
      } else {
        tiles_intro(o);
      }
      tables(p, o);
      o << '\n';
      charts.image(o, p.scene + "_paths",
                   "each slider's height against distance travelled, per runner");
      o << "Final states side by side (lanes top to bottom in the order of the table above):\n\n|";
      for (const SlideRun& r : p.runs)
        o << ' ' << std::string(scenes::name(r.metrics.runner)) << " |";
      o << "\n|";
      for (std::size_t i = 0; i < p.runs.size(); ++i) o << "---|";
      o << "\n|";
      for (const SlideRun& r : p.runs) {
        const std::string runner(scenes::name(r.metrics.runner));
        o << " ![" << p.scene << ", " << runner << "](" << p.scene << "_" << runner << ".svg) |";
      }
      o << "\n\n";
    }
  }

  // Each part's sliding bodies under Box2D's own contact and under `dyop`, when both ran.
  void summarize(SummaryFigures& figures) const override {
    for (const Part& p : parts_) {
      const scenes::SlideFigures* own = nullptr;
      const scenes::SlideFigures* plugin = nullptr;
      for (const SlideRun& r : p.runs) {
        if (!r.metrics.slide) continue;
        if (!r.metrics.runner) own = &*r.metrics.slide;
        if (r.metrics.runner == box2d::Backend::Dyop) plugin = &*r.metrics.slide;
      }
      if (own && plugin) {
        figures.glides.push_back({p.scene, own->max_vertical_speed, own->min_travel,
                                  plugin->max_vertical_speed, plugin->min_travel});
      }
    }
  }

  std::string files() const override {
    std::string out;
    for (const Part& p : parts_) {
      out += std::string(out.empty() ? "" : ", ") + "`" + p.scene +
             ".csv` (every slider under every runner), `" + p.scene + "_*.svg` (final states)";
    }
    return out;
  }

 private:
  // One sliding scene's runs, one per runner.
  struct Part {
    std::string scene;
    std::vector<SlideRun> runs;
  };

  void slide_intro(std::ostream& o) const {
    o << "## Sliding over triangulated grounds (scene `slide`)\n\n"
      << "Flat grounds whose top is made of triangle fixtures of one static body have internal "
         "edges (shared by two of its triangles); Box2D collides each fixture alone and bodies "
         "sliding over them trip (ghost collisions). One lane per slider: a frictionless box of "
         "two triangles launched at 6 m/s on a one-piece ground (two large triangles: what a "
         "glide is), on 1 m and 0.25 m square cells split along a diagonal and on 0.25 m cells "
         "split in 4 around their centre (fan); a frictionless L of six triangles at 6 m/s on "
         "the 0.25 m grounds; a 16-sided wheel (friction 0.6) rolling at 1.8 m/s on the "
         "one-piece ground and on 0.25 m diagonal cells (a polygon loses speed at each vertex: "
         "its one-piece travel is its yardstick); a box (friction 0.6) resting across a junction "
         "of two 1 m cells. ";
    runners(o, "the rule that never pushes along an internal edge");
    o << "- **vertical speed**, **angular speed**: largest |v_y| and |ω| over the run of the "
         "sliding (not rolling) bodies (a glide: 0).\n"
      << "- **travel**: distance along x over launch speed × time (a frictionless glide: "
         "100 %); **smallest travel**: over the sliding bodies.\n"
      << "- **resting box jitter**: its largest displacement from where it was after the first "
         "second (m).\n\n";
  }

  void tiles_intro(std::ostream& o) const {
    o << "## Sliding over tiled grounds (scene `tiles`)\n\n"
      << "Levels are often not one body: tile maps put each tile in a static body, streamed "
         "terrain puts each chunk in one, and grounds refined in one cell and not the next have "
         "T-junctions (a vertex inside the neighbour's edge). Grounds of 0.5 m square tiles, each "
         "split in triangles: in one static body; one static body per tile, each turned by a "
         "multiple of a quarter turn (its vertices meet its neighbours' only within float "
         "rounding); chunks of 8 × 8 tiles per body; cells alternately split in two and in five "
         "with the five-triangle cell's left side split at mid height, in one body and in one "
         "body per cell; and tiles as bodies added 1.5 m ahead of the slider and removed 1.5 m "
         "behind it while it goes (disabled and enabled, or moved 1 km away and back by "
         "`SetTransform`). On each: a frictionless box and L at 6 m/s and a rubber 16-sided wheel "
         "rolling at 1.8 m/s, launched 0.2 m past a junction. ";
    runners(o, "which joins the edges static bodies share and those T-junctions cover");
    o << "Figures as in the `slide` part (no resting box: its column reads n/a).\n\n";
  }

  // Who ran: the same seed and steps for every runner, Box2D's own contact and the plug-in's
  // backends with the internal-edge rule on or off (`rule` says what it does).
  void runners(std::ostream& o, const char* rule) const {
    o << "Same seed and steps for every runner; `" << scenes::box2d_own
      << "` is Box2D's own contact (the plug-in not installed); the plug-in's backends ran with "
         "`Config::internal_edges` "
      << (internal_edges_ ? "**on**" : "**off**") << " (" << rule << ").\n\n";
  }

  // Per runner, the sliding bodies' largest speeds, their smallest travel and the resting box's
  // jitter; then per slider, each runner's figures.
  void tables(const Part& p, std::ostream& out) const {
    Records summary({{"runner", "runner", "", -10},
                     {"max_vertical_speed", "largest vertical speed (m/s)", "", 9},
                     {"max_angular_speed", "largest angular speed (rad/s)", "", 9},
                     {"min_travel", "smallest travel", "", 9},
                     {"resting_jitter", "resting box jitter (m)", "", 9}});
    for (const SlideRun& r : p.runs) {
      const scenes::SceneMetrics& m = r.metrics;
      if (!m.slide) continue;
      summary.add({Value::text(scenes::name(m.runner)),
                   Value::number(m.slide->max_vertical_speed, "%.4f"),
                   Value::number(m.slide->max_angular_speed, "%.4f"),
                   Value::text(percent(m.slide->min_travel)),
                   m.top_displacement ? Value::metres(*m.top_displacement) : Value::text("n/a")});
    }
    summary.write_markdown(out);
    if (p.runs.empty() || !p.runs.front().metrics.slide) return;
    out << "\n| slider |";
    for (const SlideRun& r : p.runs)
      out << ' ' << std::string(scenes::name(r.metrics.runner)) << " |";
    out << "\n|---|";
    for (std::size_t i = 0; i < p.runs.size(); ++i) out << "---|";
    out << '\n';
    const std::vector<scenes::SliderFigures>& sliders = p.runs.front().metrics.slide->sliders;
    for (std::size_t k = 0; k < sliders.size(); ++k) {
      out << "| " << sliders[k].body << " on " << sliders[k].ground
          << (sliders[k].rolling ? " (rolling)" : "") << " |";
      for (const SlideRun& r : p.runs) {
        const scenes::SliderFigures& f = r.metrics.slide->sliders.at(k);
        out << " vy " << fmt("%.3f", f.max_vertical_speed) << ", ω "
            << fmt("%.2f", f.max_angular_speed) << ", " << percent(f.travel) << " |";
      }
      out << '\n';
    }
  }

  // One row per runner and slider; the resting box's jitter is the runner's, repeated on its rows.
  Records slider_records(const Part& p) const {
    Records out({{"runner", "", "", -10},
                 {"body", "", "", -8},
                 {"ground", "", "", -16},
                 {"rolling", "", "", 7},
                 {"steps", "", "", 6},
                 {"internal_edges", "", "", 5},
                 {"max_vertical_speed", "", "", 9},
                 {"max_angular_speed", "", "", 9},
                 {"travel", "", "", 9},
                 {"resting_jitter", "", "", 9}});
    for (const SlideRun& r : p.runs) {
      const scenes::SceneMetrics& m = r.metrics;
      if (!m.slide) continue;
      for (const scenes::SliderFigures& f : m.slide->sliders) {
        out.add(
            {Value::text(scenes::name(m.runner)), Value::text(f.body), Value::text(f.ground),
             Value::text(f.rolling ? "true" : "false"), Value::count(m.steps),
             Value::text(!m.runner         ? ""
                         : internal_edges_ ? "true"
                                           : "false"),
             Value::number(f.max_vertical_speed, "%.3f"),
             Value::number(f.max_angular_speed, "%.2f"), Value::number(f.travel, "%.3f"),
             m.top_displacement ? Value::number(*m.top_displacement, "%.2e") : Value::text("")});
      }
    }
    return out;
  }

  // The sliders' paths (height above their start against distance along x), one panel per
  // runner on one height scale: a ghost collision is a hop and a path cut short.
  void paths_chart(const Part& p, ReportDirectory& dir, Charts& charts) const {
    double low = 0, high = 0;
    const std::string data = p.scene + "_paths.dat";
    dir.write(data, [&](std::ostream& o) {
      for (const SlideRun& r : p.runs) {
        for (const experiments::SliderPath& p : r.paths) {
          o << "# " << std::string(scenes::name(r.metrics.runner)) << ": " << p.body << " on "
            << p.ground << ": x height\n";
          for (std::size_t i = 0; i < p.x.size(); ++i) {
            o << fmt("%.6g", p.x[i]) << ' ' << fmt("%.6g", p.height[i]) << '\n';
            low = std::min(low, p.height[i]);
            high = std::max(high, p.height[i]);
          }
          o << "\n\n";
        }
      }
    });
    const std::size_t panels = p.runs.size();
    std::ostringstream plot;
    plot << "set multiplot layout " << panels << ",1 title 'Scene " << p.scene
         << ": each slider''s height "
            "above its start against the distance it travelled (one panel per runner)'\n"
         << "set grid\nset key outside right top font ',9'\nset ylabel 'height (m)'\n"
         << "set yrange [" << fmt("%.4g", low - 0.01) << ':' << fmt("%.4g", high + 0.01) << "]\n"
         << "set xrange [-1:*]\n";
    int index = 0;
    for (const SlideRun& r : p.runs) {
      plot << "set title '" << std::string(scenes::name(r.metrics.runner)) << "'\n"
           << (&r == &p.runs.back() ? "set xlabel 'distance along x (m)'\n" : "") << "plot ";
      for (std::size_t k = 0; k < r.paths.size(); ++k, ++index) {
        plot << (k ? ", " : "") << dir.quoted(data) << " index " << index
             << " using 1:2 with lines lw 1.5 title '" << r.paths[k].body << " on "
             << r.paths[k].ground << "'";
      }
      plot << '\n';
    }
    plot << "unset multiplot\n";
    charts.draw(dir, p.scene + "_paths",
                "svg size 1000," + std::to_string(120 + 230 * panels) +
                    " dynamic font 'sans,11' background '#ffffff'",
                plot.str());
  }

  bool internal_edges_ = true;
  std::vector<Part> parts_;
};

}  // namespace

std::unique_ptr<CompareSection> make_slide_section() { return std::make_unique<SlideSection>(); }

}  // namespace dyop::report
