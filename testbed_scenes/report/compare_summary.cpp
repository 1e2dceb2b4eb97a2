// The summary `dyop compare` opens with: the plug-in against Box2D's own contact, in the few
// figures a newcomer came for, each from the run's records.
#include "report/compare_summary.hpp"

#include <utility>

#include "report/format.hpp"
#include "report/machine.hpp"

namespace dyop::report {
namespace {

// What each summarised scene stands for, in the summary's order.
const std::vector<std::pair<std::string, std::string>> kSummaryGlideScenes = {
    {"slide", "triangulated ground"}, {"tiles", "tile grounds"}};
const std::vector<std::pair<std::string, std::string>> kSummaryWallTimeScenes = {
    {"rain", "falling pile"}, {"pyramid", "resting pile"}, {"tile-map", "tile map"}};

std::optional<DepthErrorFigures> largest_depth_error(const experiments::CompareRun& run,
                                                     box2d::Backend backend) {
  std::optional<DepthErrorFigures> out;
  for (const scenes::SceneMetrics& m : run.rows) {
    if (m.runner != backend) continue;
    if (!out || m.pd_error_max > out->max_m) out = DepthErrorFigures{m.pd_error_max, m.scene};
  }
  return out;
}

std::string glide(double vertical_speed, double travel) {
  return fmt("%.3f", vertical_speed) + " m/s, " + fmt("%.1f", 100 * travel) + " %";
}

// A block of lines: its title, then one line per summarised scene the run measured, in the
// summary's order; nothing when it measured none of them.
template <class Figures, class Line>
void add_block(std::vector<std::string>& lines, const std::string& title,
               const std::vector<std::pair<std::string, std::string>>& scenes,
               const std::vector<Figures>& figures, const Line& line) {
  std::vector<std::string> block;
  for (const auto& [scene, what] : scenes) {
    for (const Figures& f : figures) {
      if (f.scene == scene) block.push_back("  - " + what + " (" + scene + "): " + line(f));
    }
  }
  if (block.empty()) return;
  lines.push_back(title);
  lines.insert(lines.end(), block.begin(), block.end());
}

}  // namespace

SummaryFigures summary_figures(const Comparison& comparison) {
  SummaryFigures f;
  f.machine = machine_description();
  const experiments::CompareRun& run = comparison.main;
  for (const scenes::SceneMetrics& m : run.rows) {
    if (m.runner == box2d::Backend::Dyop) ++f.scenes;
  }
  f.depth_own = largest_depth_error(run, box2d::Backend::Box2D);
  f.depth_dyop = largest_depth_error(run, box2d::Backend::Dyop);
  for (const auto& s : comparison.sections) {
    if (s->measured()) s->summarize(f);
  }
  return f;
}

std::vector<std::string> summary_lines(const Comparison& comparison) {
  const SummaryFigures f = summary_figures(comparison);
  const std::string dir = comparison.main.options.out_dir;
  std::vector<std::string> lines = {"# DyOP-PD against Box2D 2.4's own contact, on " + f.machine,
                                    ""};
  if (f.depth_own && f.depth_dyop) {
    lines.push_back("- Depth error (deepest point against the exact depth, largest over " +
                    std::to_string(f.scenes) + " scenes): Box2D's own " +
                    metres(f.depth_own->max_m) + " m (" + f.depth_own->scene + "), the plug-in " +
                    metres(f.depth_dyop->max_m) + " m (" + f.depth_dyop->scene + ")");
  }
  add_block(lines,
            "- Ghost collisions, bodies sliding at 6 m/s (largest vertical speed, smallest travel; "
            "a glide: 0 m/s, 100 %):",
            kSummaryGlideScenes, f.glides, [](const GlideFigures& g) {
              return "Box2D's own " + glide(g.own_vertical_speed, g.own_travel) + "; the plug-in " +
                     glide(g.plugin_vertical_speed, g.plugin_travel);
            });
  add_block(lines,
            "- Wall time, the plug-in over Box2D's own (below 1: faster), narrow phase and whole "
            "step:",
            kSummaryWallTimeScenes, f.wall_times, [](const WallTimeFigures& w) {
              return fmt("%.2f", w.narrowphase_ratio) + "x, " + fmt("%.2f", w.step_ratio) + "x";
            });
  if (!f.grounds.empty()) {
    lines.push_back(
        "- Levels as Box2D tells users to build them, under the plug-in: the chain's everyday "
        "bodies' largest vertical speed under Box2D's own -> the plug-in; a crowd's narrow phase "
        "and step on the chain and on two-sided edges, plug-in over Box2D's own; the builders' "
        "solid ground: boxes started 0.4 m inside that end on top (chain -> builders):");
    for (const GroundFigures& g : f.grounds) {
      lines.push_back(
          "  - " + g.level + ": " + fmt("%.3f", g.chain_vertical_speed) + " -> " +
          fmt("%.3f", g.chain_plugin_vertical_speed) + " m/s; chain " +
          fmt("%.2f", g.chain_narrowphase_ratio) + "x, " + fmt("%.2f", g.chain_step_ratio) +
          "x; edges " + fmt("%.2f", g.edges_narrowphase_ratio) + "x, " +
          fmt("%.2f", g.edges_step_ratio) + "x; " + std::to_string(g.chain_on_top) + " -> " +
          std::to_string(g.builders_on_top) + " of " + std::to_string(g.boxes));
    }
  }
  lines.push_back("- The report: " + dir +
                  "/report.md (every table below, and more); charts: " + dir + "/*.svg");
  if (f.viewer_pages) {
    lines.push_back("- Box2D's own against the plug-in, step by step, in a browser: " + dir +
                    "/view_<scene>.html");
  }
  return lines;
}

}  // namespace dyop::report
