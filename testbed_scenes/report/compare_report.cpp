// `dyop compare`'s report directory: report.md, the CSVs behind it, the charts and snapshots.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "report/gnuplot.hpp"
#include "scenes/compare.hpp"
#include "scenes/format.hpp"
#include "scenes/metrics_io.hpp"
#include "scenes/scene.hpp"

namespace dyop::scenes {
namespace {

using detail::fmt;
using detail::metres;

// A path inside a gnuplot single-quoted string ('' stands for one quote).
std::string gp_quote(const std::string& path) {
  std::string out = "'";
  for (char c : path) out += c == '\'' ? std::string("''") : std::string(1, c);
  return out + "'";
}

// The errors below this are drawn at this value on the log axis (exact methods have zeros).
constexpr double kErrorFloor = 1e-9;

class Writer {
 public:
  explicit Writer(const CompareRun& run) : run_(run), dir_(run.options.out_dir) {}

  ReportOutcome write() {
    write_file("compare.csv", [&](std::ostream& o) { compare_csv(o); });
    if (!run_.skips.empty()) write_file("skips.csv", [&](std::ostream& o) { skips_csv(o); });
    if (!run_.in_world.empty()) {
      write_file("inworld.csv", [&](std::ostream& o) { write_in_world_csv(run_.in_world, o); });
    }
    if (run_.paper) {
      write_file("paper_figure7.csv", [&](std::ostream& o) { figure7_data(o, ','); });
      write_file("paper_methods.csv", [&](std::ostream& o) { paper_methods_csv(o); });
    }
    for (const auto& snapshot : run_.snapshots) {  // not a structured binding: C++17 lambdas
      write_file("scene_" + snapshot.first + ".svg",  // cannot capture those (clang refuses)
                 [&](std::ostream& o) { write_svg(snapshot.second, o); });
    }
    charts();
    write_file("report.md", [&](std::ostream& o) { report(o); });
    return outcome_;
  }

 private:
  std::string path(const std::string& file) const { return dir_ + "/" + file; }

  template <class F>
  bool write_file(const std::string& file, F&& body) {
    std::ofstream out(path(file));
    body(out);
    out.close();
    if (!out) {
      outcome_.errors.push_back("cannot write " + path(file));
      return false;
    }
    return true;
  }

  void compare_csv(std::ostream& o) const {
    o << csv_header() << ",ratio_to_box2d\n";
    for (const SceneMetrics& m : run_.rows) {
      const std::optional<double> r = ratio_to_box2d(run_, m);
      o << csv_row(m) << ',' << (r ? fmt("%.6g", *r) : "") << '\n';
    }
  }

  // One row per run with skips on (the `--skip` one, then each skip alone) against its `none` run.
  void skips_csv(std::ostream& o) const {
    o << "scene,backend,steps,skips,contact_updates_on,contact_updates_off,"
         "narrowphase_ns_per_pair_on,narrowphase_ns_per_pair_off,narrowphase_ratio,"
         "narrowphase_ms_on,narrowphase_ms_off,step_ms_median_on,step_ms_median_off,step_ratio,"
         "hash_on,hash_off,hashes_equal,plugin_evaluations";
    for (int s = 0; s < box2d::skip_count; ++s) {
      o << ",skipped_" << box2d::name(static_cast<box2d::Skip>(s));
    }
    o << '\n';
    for (const SkipMeasurement& m : run_.skips) {
      std::vector<const SceneMetrics*> on = {&m.on};
      for (const SceneMetrics& a : m.alone) on.push_back(&a);
      for (const SceneMetrics* r : on) {
        // A skip list has commas: quoted, as CSV does.
        o << r->scene << ',' << r->backend << ',' << r->steps << ",\""
          << (r->skip_config ? skip_argument(*r->skip_config) : "") << "\"," << r->contact_updates
          << ',' << m.off.contact_updates << ',' << fmt("%.6g", r->narrowphase_ns_per_pair) << ','
          << fmt("%.6g", m.off.narrowphase_ns_per_pair) << ','
          << fmt("%.6g", narrowphase_ratio(*r, m.off)) << ','
          << fmt("%.6g", r->narrowphase_ms_total) << ',' << fmt("%.6g", m.off.narrowphase_ms_total)
          << ',' << fmt("%.6g", r->step_ms_median) << ',' << fmt("%.6g", m.off.step_ms_median)
          << ',' << fmt("%.6g", r->step_ms_median / m.off.step_ms_median) << ','
          << hash_hex(r->hash) << ',' << hash_hex(m.off.hash) << ','
          << (r->hash == m.off.hash ? "true" : "false") << ',' << r->plugin_evaluations.value_or(0);
        for (int s = 0; s < box2d::skip_count; ++s) o << ',' << (r->skips ? (*r->skips)[s] : 0);
        o << '\n';
      }
    }
  }

  // type, size, then one column per method (µs); `sep` ',' for CSV, ' ' for gnuplot.
  void figure7_data(std::ostream& o, char sep) const {
    const paper::Experiment& e = *run_.paper;
    o << "type" << sep << "size" << sep << "pairs";
    for (const auto& m : e.methods) o << sep << paper::name(m.method);
    o << '\n';
    for (int k = 0; k < paper::type_count; ++k) {
      const auto& t = paper::triangle_types()[k];
      const double size =
          std::max({(t[1] - t[0]).norm(), (t[2] - t[1]).norm(), (t[0] - t[2]).norm()});
      o << k + 1 << sep << fmt("%.4g", size) << sep << e.pairs_per_type[k];
      for (const auto& m : e.methods) o << sep << fmt("%.6g", m.us_per_type[k]);
      o << '\n';
    }
  }

  void paper_methods_csv(std::ostream& o) const {
    const paper::Experiment& e = *run_.paper;
    o << "method,us_overlapping_pairs,ns_per_pair,us_all_pairs,error_max,error_mean,"
         "misclassified,invalid,pairs_tested,pairs_penetrating,steps,repetitions\n";
    for (const auto& m : e.methods) {
      o << paper::name(m.method) << ',' << fmt("%.6g", m.us_total) << ','
        << fmt("%.6g", m.ns_per_pair) << ',' << fmt("%.6g", m.us_all_pairs) << ','
        << fmt("%.6g", m.error_max) << ',' << fmt("%.6g", m.error_mean) << ',' << m.misclassified
        << ',' << m.invalid << ',' << e.pairs_tested << ',' << e.pairs_penetrating << ',' << e.steps
        << ',' << e.repetitions << '\n';
    }
  }

  std::vector<std::string> scene_names() const {
    std::vector<std::string> names;
    for (const SceneMetrics& m : run_.rows) {
      if (names.empty() || names.back() != m.scene) names.push_back(m.scene);
    }
    return names;
  }

  const SceneMetrics* row(const std::string& scene, const std::string& backend) const {
    for (const SceneMetrics& m : run_.rows) {
      if (m.scene == scene && m.backend == backend) return &m;
    }
    return nullptr;
  }

  void chart(const std::string& name, const std::string& script) {
    const report::ChartResult r = report::run_gnuplot(script, path(name + ".gp"));
    if (r.ok) {
      charts_.push_back(name + ".svg");
    } else {
      outcome_.warnings.push_back(name + ".svg: " + r.message);
    }
  }

  void charts() {
    const std::string terminal =
        "set terminal svg size 1000,520 dynamic font 'sans,11' background '#ffffff'\n";
    // Time per method: clustered bars, scenes along x, one bar per backend.
    write_file("time_per_method.dat", [&](std::ostream& o) {
      o << "scene";
      for (box2d::Backend b : box2d::all_backends) o << ' ' << box2d::name(b);
      o << '\n';
      for (const std::string& s : scene_names()) {
        o << s;
        for (box2d::Backend b : box2d::all_backends) {
          const SceneMetrics* m = row(s, box2d::name(b));
          o << ' ' << (m ? fmt("%.6g", m->narrowphase_ns_per_pair) : "NaN");
        }
        o << '\n';
      }
    });
    std::ostringstream bars;
    bars << terminal << "set output " << gp_quote(path("time_per_method.svg")) << "\n"
         << "set title 'Narrow-phase time per contact update (Box2D scenes: "
            "b2ContactManager::Collide; paper: the method alone)'\n"
         << "set style data histograms\nset style histogram clustered gap 1\n"
         << "set style fill solid 0.85 border -1\nset logscale y\nset grid ytics\n"
         << "set ylabel 'ns per pair (log scale)'\nset xtics rotate by -25\n"
         << "set key outside right top\nset yrange [1:*]\n"
         << "plot for [i=2:" << box2d::backend_count + 1 << "] "
         << gp_quote(path("time_per_method.dat")) << " using i:xtic(1) title columnheader(i)\n";
    chart("time_per_method", bars.str());

    // Time against error: one point per scene and backend, one colour per backend.
    write_file("time_vs_error.dat", [&](std::ostream& o) {
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
    scatter << terminal << "set output " << gp_quote(path("time_vs_error.svg")) << "\n"
            << "set title 'Narrow-phase time against largest depth error vs exact, per scene "
               "(errors below "
            << fmt("%g", kErrorFloor) << " m drawn at " << fmt("%g", kErrorFloor) << ")'\n"
            << "set logscale xy\nset grid\nset xlabel 'ns per pair'\n"
            << "set ylabel 'largest |depth - exact depth| (m)'\nset key outside right top\n"
            << "plot ";
    for (int i = 0; i < box2d::backend_count; ++i) {
      scatter << (i ? ", " : "") << gp_quote(path("time_vs_error.dat")) << " index " << i
              << " using 1:2 with points pt " << 5 + 2 * (i % 3) << " ps 1.3 title '"
              << box2d::name(box2d::all_backends[i]) << "'";
    }
    scatter << '\n';
    chart("time_vs_error", scatter.str());

    if (!run_.in_world.empty()) in_world_chart();
    if (!run_.paper) return;
    write_file("paper_figure7.dat", [&](std::ostream& o) { figure7_data(o, ' '); });
    std::ostringstream fig;
    fig << terminal << "set output " << gp_quote(path("paper_figure7.svg")) << "\n"
        << "set title 'The paper''s Figure 7 rebuilt: time to find the penetration depths of "
           "each triangle type over "
        << run_.paper->steps << " steps'\n"
        << "set xlabel 'triangle type'\nset ylabel 'µs for all steps (median of "
        << run_.paper->repetitions << " runs)'\nset xtics 1\nset xrange [0.5:10.5]\n"
        << "set yrange [0:*]\nset grid ytics\nset key outside right top\n"
        << "plot for [i=4:" << 3 + run_.paper->methods.size() << "] "
        << gp_quote(path("paper_figure7.dat"))
        << " using 1:i with linespoints lw 2 pt 7 title columnheader(i)\n";
    chart("paper_figure7", fig.str());
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
          return fmt("%.6g", step ? r.step_ratio() : r.narrowphase_ratio());
        }
      }
      return std::string("NaN");
    };
    for (const bool step : {false, true}) {
      write_file(step ? "inworld_step.dat" : "inworld_collide.dat", [&](std::ostream& o) {
        o << "scene";
        for (const std::string& b : backends) o << ' ' << b;
        o << '\n';
        for (const std::string& s : scene_names()) {
          if (s == "paper") continue;
          o << s;
          for (const std::string& b : backends) o << ' ' << ratio(s, b, step);
          o << '\n';
        }
      });
    }
    std::ostringstream bars;
    bars << "set terminal svg size 1000,760 dynamic font 'sans,11' background '#ffffff'\n"
         << "set output " << gp_quote(path("inworld.svg")) << "\n"
         << "set multiplot layout 2,1 title 'In the world: time with the plug-in over time with "
            "Box2D''s own contact (below 1: the plug-in is faster)'\n"
         << "set style data histograms\nset style histogram clustered gap 1\n"
         << "set style fill solid 0.85 border -1\nset grid ytics\nset yrange [0:*]\n"
         << "set xtics nomirror font ',9'\nset key outside right top\n"
         << "set arrow 1 from graph 0, first 1 to graph 1, first 1 nohead dt 2\n";
    for (const bool step : {false, true}) {
      bars << "set title '" << (step ? "whole step (b2World::Step)" : "narrow phase (b2Profile::collide)")
           << "'\nset ylabel '× " << box2d_own << "'\n"
           << "plot for [i=2:" << backends.size() + 1 << "] "
           << gp_quote(path(step ? "inworld_step.dat" : "inworld_collide.dat"))
           << " using i:xtic(1) title columnheader(i)\n";
    }
    bars << "unset multiplot\n";
    chart("inworld", bars.str());
  }

  bool has_chart(const std::string& file) const {
    return std::find(charts_.begin(), charts_.end(), file) != charts_.end();
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
    if (!run_.skips.empty()) skips_section(o);

    o << "## Scenes\n\n| scene | what | steps | bodies | triangle fixtures | final state (dyop) |\n"
      << "|---|---|--:|--:|--:|---|\n";
    for (const std::string& s : scene_names()) {
      const SceneMetrics* m = row(s, "dyop");
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
      << (run_.paper ? "`paper_figure7.csv`, `paper_methods.csv`, " : "")
      << "the charts' gnuplot scripts (`*.gp`) and data (`*.dat`), `scene_*.svg`.\n";
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
      if (m.on.backend != "lin-canny") continue;
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
        const SceneMetrics* ref = row(m.scene, "box2d");
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
    for (const std::string& w : outcome_.warnings) lines.push_back(w);
    o << "## Problems\n\n";
    if (lines.empty()) o << "None: no NaN, no fallback, every pyramid and stack stands.\n";
    for (const std::string& l : lines) o << "- " << l << '\n';
    o << '\n';
  }

  const CompareRun& run_;
  std::string dir_;
  ReportOutcome outcome_;
  std::vector<std::string> charts_;
};

}  // namespace

ReportOutcome write_report(const CompareRun& run) {
  std::error_code ec;
  std::filesystem::create_directories(run.options.out_dir, ec);
  if (ec) return {{"cannot create " + run.options.out_dir + ": " + ec.message()}, {}};
  return Writer(run).write();
}

}  // namespace dyop::scenes
