// `dyop compare`'s report.md: the tables of the run, the charts drawn and the problems found.
#include <algorithm>
#include <thread>

#include "report/compare_report_files.hpp"
#include "report/compare_summary.hpp"
#include "report/compare_tables.hpp"
#include "report/format.hpp"
#include "report/metrics_io.hpp"
#include "scenes/scene.hpp"

namespace dyop::report::detail {
namespace {

using namespace dyop::scenes;
using namespace dyop::experiments;

class Markdown {
 public:
  explicit Markdown(const ReportFiles& files)
      : files_(files), comparison_(files.comparison), run_(files.comparison.main) {}

  void report(std::ostream& o) const {
    const CompareOptions& opt = run_.options;
    for (const std::string& line : summary_lines(comparison_)) o << line << '\n';
    o << "\n# DyOP-PD: every scene under every narrow phase\n\n"
      << "`dyop compare" << (opt.quick ? " --quick" : "") << "`, seed " << opt.seed << ": "
      << run_.rows.size() << " runs in the main table, " << fmt("%.1f", comparison_.seconds)
      << " s with its sections, on " << std::thread::hardware_concurrency()
      << " hardware threads. Box2D 2.4.1, 60 Hz, 8 "
      << "velocity and 3 position iterations, sleeping off.\n\n"
      << "## What is measured\n\n"
      << "- **Backends**: `dyop`, `dyop-fast`, `lin-canny` (warm-started, a cache per contact), "
         "`sat`, `epa` answer every triangle–triangle contact through the Box2D plug-in "
         "(`dyop::box2d::install`); `box2d` is Box2D's own `b2CollidePolygons` routed through the "
         "same plug-in (bit-identical to Box2D's polygon contact). Under every backend but "
         "`box2d`, polygon pairs of more vertices and polygon–circle pairs are answered by the "
         "exact `dyop::collide` (docs/box2d-plugin.md, \"Which pairs go where\"). `fallbacks` "
         "counts pairs a backend could not answer (answered by Box2D).\n"
      << "- **Narrow-phase time**: Box2D's `GetProfile().collide` (time in "
         "`b2ContactManager::Collide`, where every contact is updated) summed over steps 2..N, "
         "per contact update. It includes Box2D's own per-contact work around the call (the "
         "broad-phase overlap test, bookkeeping, warm-start matching), identical for all "
         "backends, so the ratios to `box2d` understate the differences between methods. In "
         "`paper` it is the method's calls alone, timed once per step (the paper's section below "
         "has the medians of repeated whole runs, which are steadier).\n"
      << "- **× box2d**: that time per pair over `box2d`'s for the same scene in this run.\n"
      << "- **Penetration**: after each step, the exact depth (`sat` in double) of every touching "
         "triangle pair's triangles themselves (not Box2D's 1 cm skins): max and mean over all "
         "(pair, step) samples.\n"
      << "- **pd error**: before each step, every triangle pair the step's `Collide` will update "
         "is re-evaluated untimed on the plug-in's own float inputs (B moved into A's body "
         "frame), by the backend at depth level (`box2d`: the deepest point of "
         "`b2CollidePolygons`) and by the exact reference (`sat` in double on the same float "
         "vertices); max of |difference|, mean over the pairs that penetrate by either account. "
         "**misclassified**: penetrating by one account and apart by the other beyond the "
         "touching band (32 float epsilons of the triangles' size).\n"
      << "- **top displacement**: largest distance of a top body from where it was after the "
         "first second of settling (pyramids, stacks); it stands below "
      << standing_displacement << " m.\n"
      << "- **hash**: FNV-1a of every body's position, angle and velocities after the last step, "
         "in creation order (in `compare.csv`): equal seeds give equal hashes.\n\n"
      << "## Results\n\n";
    write_compare_table(run_, o);
    o << '\n';
    files_.charts.image(o, "time_per_method", "narrow-phase time per pair, by scene and backend");
    files_.charts.image(o, "time_vs_error", "time against largest depth error");

    o << "## Scenes\n\n| scene | what | steps | bodies | triangle fixtures | final state (dyop) |\n"
      << "|---|---|--:|--:|--:|---|\n";
    for (const std::string& s : scene_names(run_)) {
      const SceneMetrics* m = row(run_, s, box2d::Backend::Dyop);
      const SceneInfo* info = find_scene(s);
      o << "| " << s << " | " << (info ? info->description : "") << " | " << (m ? m->steps : 0)
        << " | " << (m ? m->bodies : 0) << " | " << (m ? m->triangles : 0) << " | [scene_" << s
        << ".svg](scene_" << s << ".svg) |\n";
    }
    o << '\n';
    for (const auto& [scene, drawing] : run_.snapshots) {
      o << "![" << scene << "](scene_" << scene << ".svg)\n\n";
    }

    for (const auto& s : comparison_.sections) {
      if (s->measured()) s->write_markdown(o, files_.charts);
    }
    problems(o);
    o << "## Files\n\n`compare.csv` (every figure of the table, and the hash), ";
    for (const auto& s : comparison_.sections) {
      if (s->measured()) o << s->files() << ", ";
    }
    o << "the charts' gnuplot scripts (`*.gp`) and data (`*.dat`), `scene_*.svg` (final "
         "states).\n";
  }

  void problems(std::ostream& o) const {
    std::vector<std::string> lines;
    for (const SceneMetrics& m : run_.rows) {
      const std::string who = "`" + m.scene + "` / `" + name(m.runner) + "`: ";
      if (m.nan_detected) lines.push_back(who + "non-finite state or figure");
      if (m.fallbacks && *m.fallbacks > 0) {
        lines.push_back(who + std::to_string(*m.fallbacks) + " pairs answered by Box2D instead");
      }
      if (m.top_displacement && *m.top_displacement > standing_displacement) {
        const SceneMetrics* ref = row(run_, m.scene, box2d::Backend::Box2D);
        lines.push_back(who + "top moved " + fmt("%.3f", *m.top_displacement) + " m (box2d: " +
                        (ref && ref->top_displacement ? fmt("%.3f", *ref->top_displacement)
                                                      : std::string("n/a")) +
                        " m)");
      }
    }
    for (const auto& s : comparison_.sections) s->problems(lines);
    for (const Problem& p : files_.dir.problems()) {
      if (p.kind == ProblemKind::ChartNotDrawn) lines.push_back(p.message);
    }
    o << "## Problems\n\n";
    if (lines.empty()) o << "None: no NaN, no fallback, every pyramid and stack stands.\n";
    for (const std::string& l : lines) o << "- " << l << '\n';
    o << '\n';
  }

 private:
  const ReportFiles& files_;
  const Comparison& comparison_;
  const CompareRun& run_;
};

}  // namespace

void write_markdown(const ReportFiles& files, std::ostream& o) { Markdown(files).report(o); }

}  // namespace dyop::report::detail
