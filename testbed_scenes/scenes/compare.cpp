#include "scenes/compare.hpp"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <ostream>

#include "report/format.hpp"
#include "scenes/scene.hpp"

namespace dyop::scenes {
namespace {

using detail::fmt;
using detail::metres;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

template <std::size_t N>
bool listed(const std::array<const char*, N>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

// The configurations one after the other, repetition after repetition: the machines are shared,
// so what is compared is measured as close together in time as possible.
SkipMeasurement measure_skips(const SceneInfo& s, box2d::Backend b, int steps,
                              const CompareOptions& options) {
  std::vector<box2d::Config> configs = {box2d::Config::none(), options.skips};
  if (is_skip_target(s.name, box2d::name(b))) {
    for (const SkipSwitch& sw : skip_switches()) {
      if (sw.field == &box2d::Config::lin_canny_cache) continue;
      box2d::Config alone = box2d::Config::none();
      alone.*(sw.field) = true;
      configs.push_back(alone);
    }
  }
  std::vector<std::optional<SceneMetrics>> fastest(configs.size());
  for (int r = 0; r < skip_repetitions(options.quick); ++r) {
    for (std::size_t i = 0; i < configs.size(); ++i) {
      SceneMetrics run = run_scene(s.name, b, steps, options.seed, configs[i]);
      if (!fastest[i] || run.narrowphase_ms_total < fastest[i]->narrowphase_ms_total) {
        fastest[i] = std::move(run);
      }
    }
  }
  SkipMeasurement m{*fastest[0], *fastest[1], {}};
  for (std::size_t i = 2; i < fastest.size(); ++i) m.alone.push_back(*fastest[i]);
  return m;
}

// Only the exact backends promise equal hashes: a difference there is flagged.
std::string hashes_equal(const SceneMetrics& on, const SceneMetrics& off) {
  if (on.hash == off.hash) return "yes";
  return skips_keep_the_answer(on.backend) ? "NO" : "no";
}

// "n (p %)" skipped of the evaluations.
std::string skipped_share(std::uint64_t n, std::uint64_t of) {
  return std::to_string(n) + (of > 0 ? " (" + fmt("%.0f", 100.0 * n / of) + " %)" : "");
}

std::uint64_t skipped(const SceneMetrics& m, box2d::Skip why) {
  return m.skips ? (*m.skips)[static_cast<int>(why)] : 0;
}

}  // namespace

int skip_repetitions(bool quick) { return quick ? 1 : 3; }

bool is_skip_target(const std::string& scene, const std::string& backend) {
  return backend == box2d::name(skip_target_backend) && listed(skip_target_scenes, scene);
}

bool skips_keep_the_answer(const std::string& backend) {
  return backend != box2d::name(box2d::Backend::LinCanny) &&
         backend != box2d::name(box2d::Backend::DyopFast);
}

double narrowphase_ratio(const SceneMetrics& on, const SceneMetrics& off) {
  return on.narrowphase_ns_per_pair / off.narrowphase_ns_per_pair;
}

int paper_repetitions(bool quick) { return quick ? 41 : 201; }

std::vector<box2d::Backend> in_world_backends(bool quick) {
  if (!quick) return {std::begin(box2d::all_backends), std::end(box2d::all_backends)};
  return {box2d::Backend::Dyop, box2d::Backend::Sat, box2d::Backend::LinCanny,
          box2d::Backend::Box2D};
}

CompareRun run_compare(const CompareOptions& options, std::ostream& progress) {
  CompareRun run;
  run.options = options;
  const auto start = Clock::now();
  std::vector<const SceneInfo*> scenes;
  for (const SceneInfo& s : scene_catalog()) {
    if (options.scenes.empty() ||
        std::find(options.scenes.begin(), options.scenes.end(), s.name) != options.scenes.end()) {
      scenes.push_back(&s);
    }
  }
  const int total = static_cast<int>(scenes.size()) * box2d::backend_count;
  int done = 0;
  for (const SceneInfo* s : scenes) {
    const int steps = options.steps.value_or(options.quick ? s->quick_steps : s->default_steps);
    if (std::string(s->name) == "paper") {
      const auto t = Clock::now();
      const int reps = paper_repetitions(options.quick);
      run.paper = paper::run_experiment(options.seed, steps, reps);
      progress << "[paper] Figure 7 experiment, " << steps << " steps, " << reps
               << " repetitions of 8 methods: " << fmt("%.1f", seconds_since(t)) << " s\n";
    }
    for (box2d::Backend b : box2d::all_backends) {
      const auto t = Clock::now();
      Drawing final_state;
      const bool snapshot = b == box2d::Backend::Dyop;
      run.rows.push_back(run_scene(s->name, b, steps, options.seed, options.skips,
                                   snapshot ? &final_state : nullptr));
      if (snapshot) run.snapshots.emplace_back(s->name, std::move(final_state));
      ++done;
      progress << '[' << done << '/' << total << "] " << s->name << " / " << box2d::name(b) << ", "
               << steps << " steps: " << fmt("%.2f", seconds_since(t)) << " s (total "
               << fmt("%.1f", seconds_since(start)) << " s)\n"
               << std::flush;
    }
  }

  const int reps = skip_repetitions(options.quick);
  std::vector<const SceneInfo*> skip_runs;
  for (const SceneInfo* s : scenes) {
    if (listed(skip_scenes, s->name)) skip_runs.push_back(s);
  }
  const int skip_total = static_cast<int>(skip_runs.size() * skip_backends.size());
  int skip_done = 0;
  for (const SceneInfo* s : skip_runs) {
    const int steps = options.steps.value_or(options.quick ? s->quick_steps : s->default_steps);
    for (box2d::Backend b : skip_backends) {
      const auto t = Clock::now();
      run.skips.push_back(measure_skips(*s, b, steps, options));
      ++skip_done;
      progress << "[skips " << skip_done << '/' << skip_total << "] " << s->name << " / "
               << box2d::name(b) << ", " << steps << " steps, none then "
               << skip_argument(options.skips)
               << (run.skips.back().alone.empty() ? "" : " then each skip alone")
               << (reps > 1 ? ", " + std::to_string(reps) + " times" : "") << ": "
               << fmt("%.2f", seconds_since(t)) << " s (total " << fmt("%.1f", seconds_since(start))
               << " s)\n"
               << std::flush;
    }
  }
  const int in_world_reps = in_world_repetitions(options.quick);
  for (const SceneInfo* s : scenes) {
    if (std::string(s->name) == "paper") continue;  // no Box2D world
    const int steps = options.steps.value_or(options.quick ? s->quick_steps : s->default_steps);
    for (box2d::Backend b : in_world_backends(options.quick)) {
      const auto t = Clock::now();
      run.in_world.push_back(measure_in_world(s->name, b, in_world_reps, [&](const Runner& r) {
        return run_scene(s->name, r, steps, options.seed, options.skips);
      }));
      const InWorldRatio& m = run.in_world.back();
      progress << "[in-world] " << s->name << " / " << box2d::name(b) << " against "
               << box2d_own << ", " << in_world_reps << " times each: narrow phase "
               << fmt("%.2f", m.narrowphase_ratio()) << "x, step " << fmt("%.2f", m.step_ratio())
               << "x, " << fmt("%.2f", seconds_since(t)) << " s (total "
               << fmt("%.1f", seconds_since(start)) << " s)\n"
               << std::flush;
    }
  }
  run.seconds = seconds_since(start);
  return run;
}

std::optional<double> ratio_to_box2d(const CompareRun& run, const SceneMetrics& m) {
  for (const SceneMetrics& r : run.rows) {
    if (r.scene == m.scene && r.backend == "box2d" && r.narrowphase_ns_per_pair > 0) {
      return m.narrowphase_ns_per_pair / r.narrowphase_ns_per_pair;
    }
  }
  return std::nullopt;
}

void write_compare_table(const CompareRun& run, std::ostream& out) {
  out << "| scene | backend | steps | triangle pairs | step ms (median) | narrow phase ns/pair "
         "| × box2d | max penetration m | mean penetration m | pd error max m | pd error mean m "
         "| misclassified | top displacement m | KE final J | NaN | fallbacks |\n"
      << "|---|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|---|--:|\n";
  for (const SceneMetrics& m : run.rows) {
    const std::optional<double> ratio = ratio_to_box2d(run, m);
    std::string top = "–";
    if (m.top_displacement) {
      top = fmt("%.3f", *m.top_displacement) +
            (*m.top_displacement <= standing_displacement ? " (stands)" : " (FELL)");
    }
    out << "| " << m.scene << " | " << m.backend << " | " << m.steps << " | " << m.triangle_pairs
        << " | " << fmt("%.3g", m.step_ms_median) << " | " << fmt("%.0f", m.narrowphase_ns_per_pair)
        << " | " << (ratio ? fmt("%.2f", *ratio) : "–") << " | " << metres(m.max_penetration)
        << " | " << metres(m.mean_penetration) << " | " << metres(m.pd_error_max) << " | "
        << metres(m.pd_error_mean) << " | " << m.misclassified << " | " << top << " | "
        << fmt("%.3g", m.kinetic_energy_final) << " | " << (m.nan_detected ? "YES" : "no") << " | "
        << (m.fallbacks ? std::to_string(*m.fallbacks) : "–") << " |\n";
  }
}

void write_skip_tables(const CompareRun& run, std::ostream& out) {
  const std::string on = skip_argument(run.options.skips);
  out << "Skips `" << on << "` against `none`, run back to back (narrow phase: ns per contact "
      << "update; step: median wall time):\n\n"
      << "| scene | backend | steps | ns/pair on | ns/pair off | on/off | step ms on | step ms off "
         "| on/off | hashes equal | evaluations | skipped bounds | skipped warm-axis |\n"
      << "|---|---|--:|--:|--:|--:|--:|--:|--:|---|--:|--:|--:|\n";
  for (const SkipMeasurement& m : run.skips) {
    const std::uint64_t of = m.on.plugin_evaluations.value_or(0);
    out << "| " << m.on.scene << " | " << m.on.backend << " | " << m.on.steps << " | "
        << fmt("%.1f", m.on.narrowphase_ns_per_pair) << " | "
        << fmt("%.1f", m.off.narrowphase_ns_per_pair) << " | "
        << fmt("%.2f", narrowphase_ratio(m.on, m.off)) << " | " << fmt("%.3g", m.on.step_ms_median)
        << " | " << fmt("%.3g", m.off.step_ms_median) << " | "
        << fmt("%.2f", m.on.step_ms_median / m.off.step_ms_median) << " | "
        << hashes_equal(m.on, m.off) << " | " << of << " | "
        << skipped_share(skipped(m.on, box2d::Skip::Bounds), of) << " | "
        << skipped_share(skipped(m.on, box2d::Skip::WarmAxis), of) << " |\n";
  }

  bool breakdown = false;
  for (const SkipMeasurement& m : run.skips) breakdown = breakdown || !m.alone.empty();
  if (breakdown) {
    out << "\nEach skip alone against `none` (`" << box2d::name(skip_target_backend)
        << "`; `lin-canny-cache` changes nothing but `lin-canny`):\n\n"
        << "| scene | skips | ns/pair | × none | step ms | × none | hashes equal | skipped bounds "
           "| skipped warm-axis |\n"
        << "|---|---|--:|--:|--:|--:|---|--:|--:|\n";
    for (const SkipMeasurement& m : run.skips) {
      if (m.alone.empty()) continue;
      std::vector<const SceneMetrics*> rows = {&m.off};
      for (const SceneMetrics& a : m.alone) rows.push_back(&a);
      rows.push_back(&m.on);
      for (const SceneMetrics* r : rows) {
        out << "| " << r->scene << " | " << (r->skip_config ? skip_argument(*r->skip_config) : "")
            << " | " << fmt("%.1f", r->narrowphase_ns_per_pair) << " | "
            << fmt("%.2f", narrowphase_ratio(*r, m.off)) << " | " << fmt("%.3g", r->step_ms_median)
            << " | " << fmt("%.2f", r->step_ms_median / m.off.step_ms_median) << " | "
            << hashes_equal(*r, m.off) << " | " << skipped(*r, box2d::Skip::Bounds) << " | "
            << skipped(*r, box2d::Skip::WarmAxis) << " |\n";
      }
    }
  }

  bool lin_canny = false;
  for (const SkipMeasurement& m : run.skips) {
    lin_canny = lin_canny || m.on.backend == box2d::name(box2d::Backend::LinCanny);
  }
  if (!lin_canny) return;
  out << "\n`lin-canny` with skips `" << on << "` against `none` (its answer may change: see "
      << "the text):\n\n"
      << "| scene | hashes equal | contact updates on / off | max penetration m on / off "
         "| pd error max m on / off | misclassified on / off | KE final J on / off |\n"
      << "|---|---|--:|--:|--:|--:|--:|\n";
  for (const SkipMeasurement& m : run.skips) {
    if (m.on.backend != box2d::name(box2d::Backend::LinCanny)) continue;
    out << "| " << m.on.scene << " | " << (m.on.hash == m.off.hash ? "yes" : "no") << " | "
        << m.on.contact_updates << " / " << m.off.contact_updates << " | "
        << metres(m.on.max_penetration) << " / " << metres(m.off.max_penetration) << " | "
        << metres(m.on.pd_error_max) << " / " << metres(m.off.pd_error_max) << " | "
        << m.on.misclassified << " / " << m.off.misclassified << " | "
        << fmt("%.3g", m.on.kinetic_energy_final) << " / "
        << fmt("%.3g", m.off.kinetic_energy_final) << " |\n";
  }
}

void write_paper_tables(const paper::Experiment& e, std::ostream& out) {
  const auto& types = paper::triangle_types();
  out << "Time to compute the penetration depth of every bounding-box-overlapping pair a "
         "triangle type is in, over all "
      << e.steps << " steps (µs, median of " << e.repetitions << " repetitions):\n\n"
      << "| type | size | pairs |";
  for (const auto& m : e.methods) out << ' ' << name(m.method) << " |";
  out << " lin-canny-warm / dyop | lin-canny-cold / dyop |\n|--:|--:|--:|";
  for (std::size_t i = 0; i < e.methods.size() + 2; ++i) out << "--:|";
  out << '\n';
  auto figures = [&](const Variant& which) -> const paper::MethodFigures& {
    for (const auto& m : e.methods) {
      if (m.method == which) return m;
    }
    return e.methods.front();
  };
  const auto& dyop = figures({Method::Dyop, false});
  const auto& warm = figures({Method::LinCanny, true});
  const auto& cold = figures({Method::LinCanny, false});
  for (int k = 0; k < paper::type_count; ++k) {
    const auto& t = types[k];
    const double size =
        std::max({(t[1] - t[0]).norm(), (t[2] - t[1]).norm(), (t[0] - t[2]).norm()});
    out << "| " << k + 1 << " | " << fmt("%.2f", size) << " | " << e.pairs_per_type[k] << " |";
    for (const auto& m : e.methods) out << ' ' << fmt("%.2f", m.us_per_type[k]) << " |";
    out << ' ' << fmt("%.2f", warm.us_per_type[k] / dyop.us_per_type[k]) << " | "
        << fmt("%.2f", cold.us_per_type[k] / dyop.us_per_type[k]) << " |\n";
  }
  out << "\nEvery method over the same pairs (" << e.pairs_tested
      << " bounding-box-overlapping pairs, " << e.pairs_penetrating
      << " of them penetrating; and all " << paper::pair_count << " pairs × " << e.steps
      << " steps without a broad phase), errors against the exact rational reference:\n\n"
      << "| method | µs, overlapping pairs | ns/pair | × dyop | µs, all pairs | × dyop "
         "| depth error max | depth error mean | misclassified | invalid |\n"
      << "|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|\n";
  for (const auto& m : e.methods) {
    out << "| " << name(m.method) << " | " << fmt("%.1f", m.us_total) << " | "
        << fmt("%.1f", m.ns_per_pair) << " | " << fmt("%.2f", m.us_total / dyop.us_total) << " | "
        << fmt("%.1f", m.us_all_pairs) << " | " << fmt("%.2f", m.us_all_pairs / dyop.us_all_pairs)
        << " | " << metres(m.error_max) << " | " << metres(m.error_mean) << " | " << m.misclassified
        << " | " << m.invalid << " |\n";
  }
  out << "\nThe paper (its Figure 7): DyOP-PD 10.765 ms against Lin–Canny 23.259 ms on average "
         "over its 90 steps, Lin–Canny / DyOP = 2.16. Here, on the overlapping pairs: "
         "Lin–Canny warm-started / dyop = "
      << fmt("%.2f", warm.us_total / dyop.us_total)
      << ", cold / dyop = " << fmt("%.2f", cold.us_total / dyop.us_total)
      << "; the paper's literal method (dyop-paper) against warm Lin–Canny: "
      << fmt("%.2f", warm.us_total / figures({Method::DyopPaper, false}).us_total) << ".\n";
}

}  // namespace dyop::scenes
