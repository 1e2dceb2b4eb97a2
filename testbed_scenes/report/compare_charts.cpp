// `dyop compare`'s main charts (time per method, time against error): gnuplot scripts and their
// data files, drawn as SVG. Each section draws its own.
#include <algorithm>
#include <sstream>

#include "report/compare_report_files.hpp"
#include "report/format.hpp"
#include "report/gnuplot.hpp"

namespace dyop::report::detail {
namespace {

using namespace dyop::scenes;
using namespace dyop::experiments;

// The errors below this are drawn at this value on the log axis (exact methods have zeros).
constexpr double kErrorFloor = 1e-9;

const char* const kTerminal = "svg size 1000,520 dynamic font 'sans,11' background '#ffffff'";

class MainCharts {
 public:
  explicit MainCharts(ReportFiles& files)
      : files_(files),
        dir_(files.dir),
        run_(files.comparison.main),
        backends_(experiments::compare_backends(run_.options)) {}

  void chart(const std::string& name, const std::string& terminal, const std::string& body) {
    files_.charts.draw(dir_, name, terminal, body);
  }

  void charts() {
    // Time per method: clustered bars, scenes along x, one bar per backend.
    dir_.write("time_per_method.dat", [&](std::ostream& o) {
      o << "scene";
      for (box2d::Backend b : backends_) o << ' ' << box2d::name(b);
      o << '\n';
      for (const std::string& s : scene_names(run_)) {
        std::vector<double> times;
        for (box2d::Backend b : backends_) {
          const SceneMetrics* m = row(run_, s, b);
          times.push_back(m ? m->narrowphase_ns_per_pair : missing_figure);
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
         << "plot for [i=2:" << backends_.size() + 1 << "] " << dir_.quoted("time_per_method.dat")
         << " using i:xtic(1) title columnheader(i)\n";
    chart("time_per_method", kTerminal, bars.str());

    // Time against error: one point per scene and backend, one colour per backend.
    dir_.write("time_vs_error.dat", [&](std::ostream& o) {
      for (box2d::Backend b : backends_) {
        o << "# " << box2d::name(b) << ": ns_per_pair pd_error_max scene\n";
        for (const SceneMetrics& m : run_.rows) {
          if (m.runner != b) continue;
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
    for (std::size_t i = 0; i < backends_.size(); ++i) {
      scatter << (i ? ", " : "") << dir_.quoted("time_vs_error.dat") << " index " << i
              << " using 1:2 with points pt " << 5 + 2 * (i % 3) << " ps 1.3 title '"
              << box2d::name(backends_[i]) << "'";
    }
    scatter << '\n';
    chart("time_vs_error", kTerminal, scatter.str());
  }

 private:
  ReportFiles& files_;
  ReportDirectory& dir_;
  const CompareRun& run_;
  const std::vector<box2d::Backend> backends_;  // the main table's, in its order
};

}  // namespace

void draw_charts(ReportFiles& files) { MainCharts(files).charts(); }

}  // namespace dyop::report::detail
