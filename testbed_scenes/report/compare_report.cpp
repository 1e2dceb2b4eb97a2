// `dyop compare`'s report directory: report.md, compare.csv, the charts, the snapshots, and each
// section's files.
#include "report/compare_report.hpp"

#include <optional>

#include "report/compare_report_files.hpp"
#include "report/format.hpp"
#include "report/metrics_io.hpp"
#include "report/svg.hpp"

namespace dyop::report {
namespace detail {

std::vector<std::string> scene_names(const CompareRun& run) {
  std::vector<std::string> names;
  for (const SceneMetrics& m : run.rows) {
    if (names.empty() || names.back() != m.scene) names.push_back(m.scene);
  }
  return names;
}

const SceneMetrics* row(const CompareRun& run, const std::string& scene,
                        const scenes::Runner& runner) {
  for (const SceneMetrics& m : run.rows) {
    if (m.scene == scene && m.runner == runner) return &m;
  }
  return nullptr;
}

}  // namespace detail

std::vector<Problem> write_report(const Comparison& comparison) {
  const experiments::CompareRun& run = comparison.main;
  detail::ReportFiles files{comparison, ReportDirectory(run.options.out_dir), {}};
  ReportDirectory& dir = files.dir;
  if (!dir.created()) return dir.problems();
  dir.write("compare.csv", [&](std::ostream& o) {
    o << report::csv_header() << ",ratio_to_box2d\n";
    for (const scenes::SceneMetrics& m : run.rows) {
      const std::optional<double> r = experiments::ratio_to_box2d(run, m);
      o << report::csv_row(m) << ',' << (r ? fmt("%.6g", *r) : "") << '\n';
    }
  });
  for (const auto& snapshot : run.snapshots) {     // not a structured binding: C++17 lambdas
    dir.write("scene_" + snapshot.first + ".svg",  // cannot capture those (clang refuses)
              [&](std::ostream& o) { report::write_svg(snapshot.second, o); });
  }
  detail::draw_charts(files);
  for (const auto& s : comparison.sections) {
    if (s->measured()) s->write_files(dir, files.charts);
  }
  dir.write("report.md", [&](std::ostream& o) { detail::write_markdown(files, o); });
  return dir.problems();
}

}  // namespace dyop::report
