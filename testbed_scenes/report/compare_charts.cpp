// `dyop compare`'s charts: gnuplot scripts and their data files, drawn as SVG.
#include <algorithm>
#include <limits>
#include <sstream>

#include "report/compare_report_files.hpp"
#include "report/format.hpp"
#include "report/gnuplot.hpp"

namespace dyop::report::detail {
namespace {

using namespace dyop::scenes;

// The errors below this are drawn at this value on the log axis (exact methods have zeros).
constexpr double kErrorFloor = 1e-9;
// A missing figure in a chart's data file (gnuplot's missing value).
constexpr double kMissing = std::numeric_limits<double>::quiet_NaN();

const char* const kTerminal = "svg size 1000,520 dynamic font 'sans,11' background '#ffffff'";

class Charts {
 public:
  explicit Charts(ReportFiles& files) : files_(files), dir_(files.dir), run_(files.run) {}

  void chart(const std::string& name, const std::string& terminal, const std::string& body) {
    if (dir_.chart(name, terminal, body)) files_.charts.push_back(name + ".svg");
  }

  void charts() {
    // Time per method: clustered bars, scenes along x, one bar per backend.
    dir_.write("time_per_method.dat", [&](std::ostream& o) {
      o << "scene";
      for (box2d::Backend b : box2d::all_backends) o << ' ' << box2d::name(b);
      o << '\n';
      for (const std::string& s : scene_names(run_)) {
        std::vector<double> times;
        for (box2d::Backend b : box2d::all_backends) {
          const SceneMetrics* m = row(run_, s, box2d::name(b));
          times.push_back(m ? m->narrowphase_ns_per_pair : kMissing);
        }
        write_data_line(o, s, times);
      }
    });
    std::ostringstream bars;
    bars << "set title 'Narrow-phase time per contact update (Box2D scenes: "
            "b2ContactManager::Collide; paper: the method alone)'\n"
         << "set style data histograms\nset style histogram clustered gap 1\n"
         << "set style fill solid 0.85 border -1\nset logscale y\nset grid ytics\n"
         << "set ylabel 'ns per pair (log scale)'\nset xtics rotate by -25\n"
         << "set key outside right top\nset yrange [1:*]\n"
         << "plot for [i=2:" << box2d::backend_count + 1 << "] "
         << dir_.quoted("time_per_method.dat") << " using i:xtic(1) title columnheader(i)\n";
    chart("time_per_method", kTerminal, bars.str());

    // Time against error: one point per scene and backend, one colour per backend.
    dir_.write("time_vs_error.dat", [&](std::ostream& o) {
      for (box2d::Backend b : box2d::all_backends) {
        o << "# " << box2d::name(b) << ": ns_per_pair pd_error_max scene\n";
        for (const SceneMetrics& m : run_.rows) {
          if (m.backend != box2d::name(b)) continue;
          o << fmt("%.6g", m.narrowphase_ns_per_pair) << ' '
            << fmt("%.6g", std::max(m.pd_error_max, kErrorFloor)) << ' ' << m.scene << '\n';
        }
        o << "\n\n";
      }
    });
    std::ostringstream scatter;
    scatter << "set title 'Narrow-phase time against largest depth error vs exact, per scene "
               "(errors below "
            << fmt("%g", kErrorFloor) << " m drawn at " << fmt("%g", kErrorFloor) << ")'\n"
            << "set logscale xy\nset grid\nset xlabel 'ns per pair'\n"
            << "set ylabel 'largest |depth - exact depth| (m)'\nset key outside right top\n"
            << "plot ";
    for (int i = 0; i < box2d::backend_count; ++i) {
      scatter << (i ? ", " : "") << dir_.quoted("time_vs_error.dat") << " index " << i
              << " using 1:2 with points pt " << 5 + 2 * (i % 3) << " ps 1.3 title '"
              << box2d::name(box2d::all_backends[i]) << "'";
    }
    scatter << '\n';
    chart("time_vs_error", kTerminal, scatter.str());

    if (!run_.in_world.empty()) in_world_chart();
    if (!run_.slide.empty()) slide_chart();
    if (!run_.paper) return;
    dir_.write("paper_figure7.dat", [&](std::ostream& o) { write_figure7_data(run_, o, ' '); });
    std::ostringstream fig;
    fig << "set title 'The paper''s Figure 7 rebuilt: time to find the penetration depths of "
           "each triangle type over "
        << run_.paper->steps << " steps'\n"
        << "set xlabel 'triangle type'\nset ylabel 'µs for all steps (median of "
        << run_.paper->repetitions << " runs)'\nset xtics 1\nset xrange [0.5:10.5]\n"
        << "set yrange [0:*]\nset grid ytics\nset key outside right top\n"
        << "plot for [i=4:" << 3 + run_.paper->methods.size() << "] "
        << dir_.quoted("paper_figure7.dat")
        << " using 1:i with linespoints lw 2 pt 7 title columnheader(i)\n";
    chart("paper_figure7", kTerminal, fig.str());
  }

  // Narrow-phase and step ratios to Box2D's own contact: clustered bars, one group per scene, one
  // bar per backend, narrow phase above and step below.
  void in_world_chart() {
    std::vector<std::string> backends;
    for (const InWorldRatio& r : run_.in_world) {
      if (std::find(backends.begin(), backends.end(), r.backend) == backends.end()) {
        backends.push_back(r.backend);
      }
    }
    auto ratio = [&](const std::string& scene, const std::string& backend, bool step) {
      for (const InWorldRatio& r : run_.in_world) {
        if (r.scene == scene && r.backend == backend) {
          return step ? r.step_ratio() : r.narrowphase_ratio();
        }
      }
      return kMissing;
    };
    for (const bool step : {false, true}) {
      dir_.write(step ? "inworld_step.dat" : "inworld_collide.dat", [&](std::ostream& o) {
        o << "scene";
        for (const std::string& b : backends) o << ' ' << b;
        o << '\n';
        for (const std::string& s : scene_names(run_)) {
          if (s == "paper") continue;
          std::vector<double> ratios;
          for (const std::string& b : backends) ratios.push_back(ratio(s, b, step));
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
      bars << "set title '" << (step ? "whole step (b2World::Step)" : "narrow phase (b2Profile::collide)")
           << "'\nset ylabel '× " << box2d_own << "'\n"
           << "plot for [i=2:" << backends.size() + 1 << "] "
           << dir_.quoted(step ? "inworld_step.dat" : "inworld_collide.dat")
           << " using i:xtic(1) title columnheader(i)\n";
    }
    bars << "unset multiplot\n";
    chart("inworld", "svg size 1000,760 dynamic font 'sans,11' background '#ffffff'", bars.str());
  }

  // The sliders' paths (height above their start against distance along x), one panel per
  // runner on one height scale: a ghost collision is a hop and a path cut short.
  void slide_chart() {
    double low = 0, high = 0;
    dir_.write("slide_paths.dat", [&](std::ostream& o) {
      for (const SlideRun& r : run_.slide) {
        for (const SliderPath& p : r.paths) {
          o << "# " << r.metrics.backend << ": " << p.body << " on " << p.ground
            << ": x height\n";
          for (std::size_t i = 0; i < p.x.size(); ++i) {
            o << fmt("%.6g", p.x[i]) << ' ' << fmt("%.6g", p.height[i]) << '\n';
            low = std::min(low, p.height[i]);
            high = std::max(high, p.height[i]);
          }
          o << "\n\n";
        }
      }
    });
    const std::size_t panels = run_.slide.size();
    std::ostringstream plot;
    plot << "set multiplot layout " << panels << ",1 title 'Scene slide: each slider''s height "
            "above its start against the distance it travelled (one panel per runner)'\n"
         << "set grid\nset key outside right top font ',9'\nset ylabel 'height (m)'\n"
         << "set yrange [" << fmt("%.4g", low - 0.01) << ':' << fmt("%.4g", high + 0.01) << "]\n"
         << "set xrange [-1:*]\n";
    int index = 0;
    for (const SlideRun& r : run_.slide) {
      plot << "set title '" << r.metrics.backend << "'\n"
           << (&r == &run_.slide.back() ? "set xlabel 'distance along x (m)'\n" : "") << "plot ";
      for (std::size_t k = 0; k < r.paths.size(); ++k, ++index) {
        plot << (k ? ", " : "") << dir_.quoted("slide_paths.dat") << " index " << index
             << " using 1:2 with lines lw 1.5 title '" << r.paths[k].body << " on "
             << r.paths[k].ground << "'";
      }
      plot << '\n';
    }
    plot << "unset multiplot\n";
    chart("slide_paths",
          "svg size 1000," + std::to_string(120 + 230 * panels) +
              " dynamic font 'sans,11' background '#ffffff'",
          plot.str());
  }

 private:
  ReportFiles& files_;
  ReportDirectory& dir_;
  const CompareRun& run_;
};

}  // namespace

void draw_charts(ReportFiles& files) { Charts(files).charts(); }

}  // namespace dyop::report::detail
