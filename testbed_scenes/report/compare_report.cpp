// `dyop compare`'s report directory: report.md, the CSVs behind it, the charts and snapshots.
#include "report/compare_report.hpp"

#include <filesystem>

#include "report/compare_report_files.hpp"
#include "scenes/scene.hpp"

namespace dyop::scenes {
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

ReportOutcome write_report(const CompareRun& run) {
  std::error_code ec;
  std::filesystem::create_directories(run.options.out_dir, ec);
  if (ec) return {{"cannot create " + run.options.out_dir + ": " + ec.message()}, {}};
  detail::ReportFiles files{run, run.options.out_dir, {}, {}};
  files.write_file("compare.csv", [&](std::ostream& o) { detail::write_compare_csv(run, o); });
  if (!run.skips.empty()) {
    files.write_file("skips.csv", [&](std::ostream& o) { detail::write_skips_csv(run, o); });
  }
  if (!run.in_world.empty()) {
    files.write_file("inworld.csv", [&](std::ostream& o) { write_in_world_csv(run.in_world, o); });
  }
  if (run.paper) {
    files.write_file("paper_figure7.csv",
                     [&](std::ostream& o) { detail::write_figure7_data(run, o, ','); });
    files.write_file("paper_methods.csv",
                     [&](std::ostream& o) { detail::write_paper_methods_csv(run, o); });
  }
  for (const auto& snapshot : run.snapshots) {  // not a structured binding: C++17 lambdas
    files.write_file("scene_" + snapshot.first + ".svg",  // cannot capture those (clang refuses)
                     [&](std::ostream& o) { write_svg(snapshot.second, o); });
  }
  detail::draw_charts(files);
  files.write_file("report.md", [&](std::ostream& o) { detail::write_markdown(files, o); });
  return files.outcome;
}

}  // namespace dyop::scenes
