// `dyop compare`'s report directory: report.md, the CSVs behind it, the charts and snapshots.
#include "report/compare_report.hpp"

#include "report/compare_report_files.hpp"
#include "report/compare_tables.hpp"
#include "scenes/svg.hpp"

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
                        const std::string& backend) {
  for (const SceneMetrics& m : run.rows) {
    if (m.scene == scene && m.backend == backend) return &m;
  }
  return nullptr;
}

}  // namespace detail

std::vector<Problem> write_report(const scenes::CompareRun& run) {
  detail::ReportFiles files{run, ReportDirectory(run.options.out_dir), {}};
  ReportDirectory& dir = files.dir;
  if (!dir.created()) return dir.problems();
  dir.write("compare.csv", [&](std::ostream& o) { detail::write_compare_csv(run, o); });
  if (!run.skips.empty()) {
    dir.write("skips.csv", [&](std::ostream& o) { detail::write_skips_csv(run, o); });
  }
  if (!run.in_world.empty()) {
    dir.write("inworld.csv", [&](std::ostream& o) { write_in_world_csv(run.in_world, o); });
  }
  if (run.paper) {
    dir.write("paper_figure7.csv", [&](std::ostream& o) { detail::write_figure7_data(run, o, ','); });
    dir.write("paper_methods.csv",
              [&](std::ostream& o) { detail::write_paper_methods_csv(run, o); });
  }
  for (const auto& snapshot : run.snapshots) {  // not a structured binding: C++17 lambdas
    dir.write("scene_" + snapshot.first + ".svg",  // cannot capture those (clang refuses)
              [&](std::ostream& o) { scenes::write_svg(snapshot.second, o); });
  }
  if (!run.slide.empty()) {
    dir.write("slide.csv", [&](std::ostream& o) { detail::write_slide_csv(run, o); });
  }
  for (const scenes::SlideRun& r : run.slide) {
    dir.write("slide_" + r.metrics.backend + ".svg",
              [&](std::ostream& o) { scenes::write_svg(r.final_state, o); });
  }
  detail::draw_charts(files);
  dir.write("report.md", [&](std::ostream& o) { detail::write_markdown(files, o); });
  return dir.problems();
}

}  // namespace dyop::report
