// `dyop compare`'s report.md: the tables of the run, the charts drawn and the problems found.
#include <algorithm>
#include <thread>

#include "report/compare_report_files.hpp"
#include "report/compare_tables.hpp"
#include "report/format.hpp"
#include "scenes/metrics_io.hpp"
#include "scenes/scene.hpp"

namespace dyop::report::detail {
namespace {

using namespace dyop::scenes;

class Markdown {
 public:
  explicit Markdown(const ReportFiles& files) : files_(files), run_(files.run) {}

  bool has_chart(const std::string& file) const {
    return std::find(files_.charts.begin(), files_.charts.end(), file) != files_.charts.end();
  }

  void image(std::ostream& o, const std::string& file, const std::string& alt) const {
    if (has_chart(file)) {
      o << "![" << alt << "](" << file << ")\n\n";
    } else {
      o << "*Chart `" << file << "` not drawn (see Problems); its data is in the CSV files.*\n\n";
    }
  }

  void report(std::ostream& o) const {
    const CompareOptions& opt = run_.options;
    o << "# DyOP-PD: every scene under every narrow phase\n\n"
      << "`dyop compare" << (opt.quick ? " --quick" : "") << "`, seed " << opt.seed << ": "
      << run_.rows.size() << " runs in " << fmt("%.1f", run_.seconds) << " s on "
      << std::thread::hardware_concurrency() << " hardware threads. Box2D 2.4.1, 60 Hz, 8 "
      << "velocity and 3 position iterations, sleeping off.\n\n"
      << "## What is measured\n\n"
      << "- **Backends**: `dyop`, `dyop-fast`, `lin-canny` (warm-started, a cache per contact), "
         "`sat`, `epa` answer every triangle–triangle contact through the Box2D plug-in "
         "(`dyop::box2d::install`); `box2d` is Box2D's own `b2CollidePolygons` routed through the "
         "same plug-in (bit-identical to Box2D's polygon contact). Non-triangle pairs keep Box2D's "
         "own code. `fallbacks` counts pairs a backend could not answer (answered by Box2D).\n"
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
    image(o, "time_per_method.svg", "narrow-phase time per pair, by scene and backend");
    image(o, "time_vs_error.svg", "time against largest depth error");
    if (!run_.in_world.empty()) in_world_section(o);
    if (!run_.slide.empty()) slide_section(o);
    if (!run_.skips.empty()) skips_section(o);

    o << "## Scenes\n\n| scene | what | steps | bodies | triangle fixtures | final state (dyop) |\n"
      << "|---|---|--:|--:|--:|---|\n";
    for (const std::string& s : scene_names(run_)) {
      const SceneMetrics* m = row(run_, s, "dyop");
      const SceneInfo* info = find_scene(s);
      o << "| " << s << " | " << (info ? info->description : "") << " | " << (m ? m->steps : 0)
        << " | " << (m ? m->bodies : 0) << " | " << (m ? m->triangles : 0) << " | [scene_" << s
        << ".svg](scene_" << s << ".svg) |\n";
    }
    o << '\n';
    for (const auto& [scene, drawing] : run_.snapshots) {
      o << "![" << scene << "](scene_" << scene << ".svg)\n\n";
    }

    if (run_.paper) paper_section(o);
    problems(o);
    o << "## Files\n\n`compare.csv` (every figure of the table, and the hash), "
      << (run_.skips.empty()
              ? ""
              : "`skips.csv` (every run of the skip section against its `none` run), ")
      << (run_.slide.empty() ? "" : "`slide.csv` (every slider under every runner), ")
      << (run_.paper ? "`paper_figure7.csv`, `paper_methods.csv`, " : "")
      << "the charts' gnuplot scripts (`*.gp`) and data (`*.dat`), `scene_*.svg`"
      << (run_.slide.empty() ? "" : ", `slide_*.svg`") << ".\n";
  }

  void in_world_section(std::ostream& o) const {
    o << "## In the world, against Box2D's own contact\n\n"
      << "What a user who installs the plug-in feels: each Box2D scene runs under Box2D's own "
         "contact with the plug-in **not installed** (`"
      << box2d_own << "`) and under the backend, alternately (own, backend, own, backend, ...; "
      << in_world_repetitions(run_.options.quick)
      << " runs of each) in this process, same seed and steps as the table above. Each side's "
         "figure is the median over its runs of the narrow phase (`b2Profile::collide`, summed "
         "over steps 2..N) and of the whole step (`b2World::Step`'s wall time, summed over the "
         "same steps: the solver and the time-of-impact pass included). **× own** is the "
         "backend's figure over Box2D's own: below 1 the plug-in is faster. The worlds evolve "
         "alike but not bit for bit (`box2d` excepted), so each side's contact updates are "
         "given. Machine: "
      << std::thread::hardware_concurrency()
      << " hardware threads; ratios move between machines of one kind, name the machine with "
         "them.\n\n";
    write_in_world_table(run_.in_world, o);
    o << '\n';
    image(o, "inworld.svg", "narrow-phase and step time against Box2D's own contact");
  }

  void slide_section(std::ostream& o) const {
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
         "of two 1 m cells. Same seed and steps for every runner; `"
      << box2d_own << "` is Box2D's own contact (the plug-in not installed); the plug-in's "
      << "backends ran with `Config::internal_edges` "
      << (run_.options.skips.internal_edges ? "**on**" : "**off**")
      << " (the rule that never pushes along an internal edge).\n\n"
      << "- **vertical speed**, **angular speed**: largest |v_y| and |ω| over the run of the "
         "sliding (not rolling) bodies (a glide: 0).\n"
      << "- **travel**: distance along x over launch speed × time (a frictionless glide: "
         "100 %); **smallest travel**: over the sliding bodies.\n"
      << "- **resting box jitter**: its largest displacement from where it was after the first "
         "second (m).\n\n";
    write_slide_tables(run_.slide, o);
    o << '\n';
    image(o, "slide_paths.svg", "each slider's height against distance travelled, per runner");
    o << "Final states side by side (lanes top to bottom in the order of the table above):\n\n|";
    for (const SlideRun& r : run_.slide) o << ' ' << r.metrics.backend << " |";
    o << "\n|";
    for (std::size_t i = 0; i < run_.slide.size(); ++i) o << "---|";
    o << "\n|";
    for (const SlideRun& r : run_.slide) {
      o << " ![slide, " << r.metrics.backend << "](slide_" << r.metrics.backend << ".svg) |";
    }
    o << "\n\n";
  }

  void skips_section(std::ostream& o) const {
    const std::string on = skip_argument(run_.options.skips);
    o << "## Skipping what a scene doesn't need\n\n"
      << "Each Box2D world is given the narrow-phase work it may skip (`dyop::box2d::Config`, "
         "`--skip all|none|LIST`, all by default; the main table ran with `"
      << on << "`):\n\n";
    for (const SkipSwitch& sw : skip_switches()) o << "- `" << sw.name << "`: " << sw.what << ".\n";
    o << "\nA skip avoids work whose result nobody uses and never changes the arithmetic of the "
         "work it keeps: with an exact backend (`dyop`, `sat`) a world with skips on is "
         "bit-identical to the same world with every skip off (**hashes equal**). Sensor fixtures "
         "need no skip of their own: Box2D 2.4 never asks a sensor's contact for a manifold "
         "(`b2Contact::Update` calls `b2TestOverlap` and leaves the manifold empty), so their "
         "pairs never reach the plug-in; no scene has sensors. The `paper` scene has no Box2D "
         "world: skips do not apply to it.\n\n"
      << "Measured: each scene and backend below runs with every skip off (`none`), then with `"
      << on << "`, back to back, same seed and steps"
      << (skip_repetitions(run_.options.quick) > 1
              ? ", " + std::to_string(skip_repetitions(run_.options.quick)) +
                    " times interleaved, each figure from the repetition with the least "
                    "narrow-phase time"
              : std::string())
      << ". Narrow-phase time is that of the main table "
         "(`GetProfile().collide` over steps 2..N, per contact update); with equal hashes both "
         "runs make the same contact updates, so on/off is also the ratio of the total "
         "narrow-phase times. It includes Box2D's own per-contact work (the broad-phase overlap "
         "test, bookkeeping, warm-start matching), which no skip avoids. **evaluations**: the "
         "plug-in's triangle-pair evaluations (step 1 and time-of-impact sub-steps included), of "
         "which the skipped ones are a part.\n\n";
    write_skip_tables(run_, o);
    o << '\n';

    std::string target;
    for (const SkipMeasurement& m : run_.skips) {
      if (!is_skip_target(m.on.scene, m.on.backend)) continue;
      const double r = narrowphase_ratio(m.on, m.off);
      const bool equal = m.on.hash == m.off.hash;
      target += std::string(target.empty() ? "" : "; ") + "`" + m.on.scene + "` " + fmt("%.2f", r) +
                (r <= skip_target_ratio && equal ? " (met" : " (MISSED") +
                (equal ? ", hashes equal)" : ", hashes DIFFER)");
    }
    if (!target.empty()) {
      o << "**Target** (`rain` and `tumbler` with `dyop`: narrow-phase time with every skip on at "
           "most "
        << skip_target_ratio << " × with every skip off, identical hashes)"
        << ": " << target << (on == "all" ? "" : " — measured with `" + on + "`, not `all`")
        << ".\n\n";
    }

    std::vector<std::string> differ, same;
    for (const SkipMeasurement& m : run_.skips) {
      if (m.on.backend != name(Method::LinCanny)) continue;
      (m.on.hash == m.off.hash ? same : differ).push_back("`" + m.on.scene + "`");
    }
    if (differ.empty() && same.empty()) return;
    auto join = [](const std::vector<std::string>& v) {
      std::string out;
      for (const std::string& x : v) out += (out.empty() ? "" : ", ") + x;
      return out.empty() ? std::string("none") : out;
    };
    o << "**`lin-canny`** is not held to bit-identity. With `lin-canny-cache` each step's walk "
         "starts from the features the pair ended on last step, and a penetrating walk stops at "
         "a local minimum of the overlap that depends on where it starts; a pair skipped by "
         "`bounds` or `warm-axis` also leaves its cache where it was, so its next walk "
         "starts from older features. Without the cache every walk starts cold and the other "
         "skips only avoid pairs beyond reach (whose manifold is empty from any start) or "
         "repeat an identical evaluation, so `lin-canny` with every skip but `lin-canny-cache` "
         "is bit-identical to `none` (checked in `tests/scenes/scene_skips_test.cpp`). In this "
         "run, hashes differ in "
      << join(differ) << " and are equal in " << join(same)
      << ": a different local minimum gives a slightly different contact, and the scene then "
         "evolves differently (compare the penetration, error and energy columns above).\n\n";
  }

  void paper_section(std::ostream& o) const {
    const paper::Experiment& e = *run_.paper;
    o << "## The paper's experiment (scene `paper`)\n\n"
      << "The paper moves 10 pre-defined irregular triangle types on pre-defined paths for 90 "
         "steps, tests them against each other and plots per type the time DyOP-PD and "
         "Lin–Canny take to find the penetration depths (its Figure 7). It publishes neither the "
         "triangles nor the paths; ours follow. Every step, each pair whose bounding boxes "
         "overlap goes to every method, in float, at depth level; errors are against the exact "
         "rational reference. Seed "
      << e.seed << ", steps of " << fmt("%.4f", paper::step_seconds)
      << " s from t = " << fmt("%.1f", paper::start_time(e.seed)) << " s.\n\n"
      << "Triangle types (vertices about the centroid):\n\n| type | v0 | v1 | v2 | longest edge |\n"
      << "|--:|---|---|---|--:|\n";
    for (int k = 0; k < paper::type_count; ++k) {
      const auto& t = paper::triangle_types()[k];
      o << "| " << k + 1 << " |";
      for (int i = 0; i < 3; ++i) {
        o << " (" << fmt("%.3f", t[i].x()) << ", " << fmt("%.3f", t[i].y()) << ") |";
      }
      o << ' '
        << fmt("%.2f", std::max({(t[1] - t[0]).norm(), (t[2] - t[1]).norm(), (t[0] - t[2]).norm()}))
        << " |\n";
    }
    o << "\nPaths: type k is at (cx + ax·sin(wx·t + phase), cy + ay·sin(wy·t)), turned by "
         "angle0 + spin·t:\n\n| type | cx | cy | ax | ay | wx | wy | phase | angle0 | spin |\n"
      << "|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|\n";
    for (int k = 0; k < paper::type_count; ++k) {
      const paper::Path& p = paper::paths()[k];
      o << "| " << k + 1;
      for (double v : {p.cx, p.cy, p.ax, p.ay, p.wx, p.wy, p.phase, p.angle0, p.spin}) {
        o << " | " << fmt("%.2f", v);
      }
      o << " |\n";
    }
    o << '\n';
    write_paper_tables(e, o);
    o << '\n';
    image(o, "paper_figure7.svg", "time per triangle type and method");
  }

  void problems(std::ostream& o) const {
    std::vector<std::string> lines;
    for (const SceneMetrics& m : run_.rows) {
      const std::string who = "`" + m.scene + "` / `" + m.backend + "`: ";
      if (m.nan_detected) lines.push_back(who + "non-finite state or figure");
      if (m.fallbacks && *m.fallbacks > 0) {
        lines.push_back(who + std::to_string(*m.fallbacks) + " pairs answered by Box2D instead");
      }
      if (m.top_displacement && *m.top_displacement > standing_displacement) {
        const SceneMetrics* ref = row(run_, m.scene, "box2d");
        lines.push_back(who + "top moved " + fmt("%.3f", *m.top_displacement) + " m (box2d: " +
                        (ref && ref->top_displacement ? fmt("%.3f", *ref->top_displacement)
                                                      : std::string("n/a")) +
                        " m)");
      }
    }
    for (const SkipMeasurement& m : run_.skips) {
      const std::string who = "`" + m.on.scene + "` / `" + m.on.backend + "`: ";
      if (m.on.hash != m.off.hash && skips_keep_the_answer(m.on.backend)) {
        lines.push_back(who + "skips `" + skip_argument(run_.options.skips) +
                        "` changed the final state (hash " + hash_hex(m.on.hash) +
                        ", none: " + hash_hex(m.off.hash) + ")");
      }
      const bool all = skip_argument(run_.options.skips) == "all";  // what the target is about
      if (all && is_skip_target(m.on.scene, m.on.backend) &&
          narrowphase_ratio(m.on, m.off) > skip_target_ratio) {
        lines.push_back(who + "narrow-phase time with skips on " +
                        fmt("%.2f", narrowphase_ratio(m.on, m.off)) + " × off, above the target " +
                        fmt("%.1f", skip_target_ratio));
      }
    }
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
  const CompareRun& run_;
};

}  // namespace

void write_markdown(const ReportFiles& files, std::ostream& o) { Markdown(files).report(o); }

}  // namespace dyop::report::detail
