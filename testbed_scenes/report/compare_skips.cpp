// `dyop compare`'s skip section: what skipping saves (`experiments/compare.hpp`'s skip scenes under
// its skip backends, every skip off against `--skip`, each skip alone in the target scenes),
// with its tables, CSV, Markdown and problems.
#include <cstdint>
#include <string>
#include <vector>

#include "report/compare_section.hpp"
#include "report/format.hpp"
#include "report/records.hpp"
#include "report/metrics_io.hpp"
#include "experiments/progress.hpp"
#include "scenes/skips.hpp"

namespace dyop::report {
namespace {

using namespace dyop::scenes;
using namespace dyop::experiments;

// Only the exact backends promise equal hashes: a difference there is flagged.
std::string hashes_equal(const SceneMetrics& on, const SceneMetrics& off) {
  if (on.hash == off.hash) return "yes";
  return skips_keep_the_answer(on.runner) ? "NO" : "no";
}

// "n (p %)" skipped of the evaluations.
std::string skipped_share(std::uint64_t n, std::uint64_t of) {
  return std::to_string(n) + (of > 0 ? " (" + fmt("%.0f", 100.0 * n / of) + " %)" : "");
}

std::uint64_t skipped(const SceneMetrics& m, box2d::Skip why) {
  return m.skips ? (*m.skips)[static_cast<int>(why)] : 0;
}

class SkipSection : public CompareSection {
 public:
  const char* section_name() const override { return "skips"; }
  bool in_quick_run() const override { return false; }
  void run(const SectionContext& c) override {
    using experiments::detail::fixed;
    quick_ = c.options.quick;
    skips_ = c.options.skips;
    const int reps = skip_repetitions(c.options.quick);
    std::vector<const SceneInfo*> skip_runs;
    for (const SceneInfo* s : c.scenes) {
      for (const char* name : skip_scenes) {
        if (std::string(s->name) == name) skip_runs.push_back(s);
      }
    }
    const int total = static_cast<int>(skip_runs.size() * skip_backends.size());
    int done = 0;
    for (const SceneInfo* s : skip_runs) {
      const int steps = c.steps(*s);
      for (box2d::Backend b : skip_backends) {
        const double start = c.elapsed();
        measurements_.push_back(measure_skips(*s, b, steps, c.options));
        ++done;
        c.progress << "[skips " << done << '/' << total << "] " << s->name << " / "
                   << box2d::name(b) << ", " << steps << " steps, none then "
                   << skip_argument(c.options.skips)
                   << (measurements_.back().alone.empty() ? "" : " then each skip alone")
                   << (reps > 1 ? ", " + std::to_string(reps) + " times" : "") << ": "
                   << fixed(c.elapsed() - start, 2) << " s (total " << fixed(c.elapsed(), 1)
                   << " s)\n"
                   << std::flush;
      }
    }
  }

  bool measured() const override { return !measurements_.empty(); }

  void write_tables(std::ostream& out) const override {
    out << "\nSkipping what a scene doesn't need:\n\n";
    tables(out);
  }

  void write_files(ReportDirectory& dir, Charts&) const override {
    dir.write("skips.csv", [&](std::ostream& o) { skip_records(true).write_csv(o); });
  }

  void write_markdown(std::ostream& o, const Charts&) const override {
    const std::string on = skip_argument(skips_);
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
      << (skip_repetitions(quick_) > 1
              ? ", " + std::to_string(skip_repetitions(quick_)) +
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
    tables(o);
    o << '\n';

    std::string target;
    for (const SkipMeasurement& m : measurements_) {
      if (!is_skip_target(m.on.scene, m.on.runner)) continue;
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
    for (const SkipMeasurement& m : measurements_) {
      if (m.on.runner != box2d::Backend::LinCanny) continue;
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
         "is bit-identical to `none` (checked in `tests/testbed/scene_skips_test.cpp`). In this "
         "run, hashes differ in "
      << join(differ) << " and are equal in " << join(same)
      << ": a different local minimum gives a slightly different contact, and the scene then "
         "evolves differently (compare the penetration, error and energy columns above).\n\n";
  }

  std::string files() const override {
    return "`skips.csv` (every run of the skip section against its `none` run)";
  }

  void problems(std::vector<std::string>& lines) const override {
    for (const SkipMeasurement& m : measurements_) {
      const std::string who = "`" + m.on.scene + "` / `" + name(m.on.runner) + "`: ";
      if (m.on.hash != m.off.hash && skips_keep_the_answer(m.on.runner)) {
        lines.push_back(who + "skips `" + skip_argument(skips_) +
                        "` changed the final state (hash " + hash_hex(m.on.hash) +
                        ", none: " + hash_hex(m.off.hash) + ")");
      }
      const bool all = skip_argument(skips_) == "all";  // what the target is about
      if (all && is_skip_target(m.on.scene, m.on.runner) &&
          narrowphase_ratio(m.on, m.off) > skip_target_ratio) {
        lines.push_back(who + "narrow-phase time with skips on " +
                        fmt("%.2f", narrowphase_ratio(m.on, m.off)) + " × off, above the target " +
                        fmt("%.1f", skip_target_ratio));
      }
    }
  }

 private:
  // Skips on against off per scene and backend, each switch alone in the breakdown scenes, and
  // what skipping changes in `lin-canny`'s answers.
  void tables(std::ostream& out) const {
    const std::string on = skip_argument(skips_);
    out << "Skips `" << on << "` against `none`, run back to back (narrow phase: ns per contact "
        << "update; step: median wall time):\n\n"
        << "\n";
    skip_records(false).write_markdown(out);

    bool breakdown = false;
    for (const SkipMeasurement& m : measurements_) breakdown = breakdown || !m.alone.empty();
    if (breakdown) {
      out << "\nEach skip alone against `none` (`" << box2d::name(skip_target_backend)
          << "`; `lin-canny-cache` changes nothing but `lin-canny`):\n\n"
          << "| scene | skips | ns/pair | × none | step ms | × none | hashes equal | skipped "
             "bounds "
             "| skipped warm-axis |\n"
          << "|---|---|--:|--:|--:|--:|---|--:|--:|\n";
      for (const SkipMeasurement& m : measurements_) {
        if (m.alone.empty()) continue;
        std::vector<const SceneMetrics*> rows = {&m.off};
        for (const SceneMetrics& a : m.alone) rows.push_back(&a);
        rows.push_back(&m.on);
        for (const SceneMetrics* r : rows) {
          out << "| " << r->scene << " | " << (r->skip_config ? skip_argument(*r->skip_config) : "")
              << " | " << fmt("%.1f", r->narrowphase_ns_per_pair) << " | "
              << fmt("%.2f", narrowphase_ratio(*r, m.off)) << " | "
              << fmt("%.3g", r->step_ms_median) << " | "
              << fmt("%.2f", r->step_ms_median / m.off.step_ms_median) << " | "
              << hashes_equal(*r, m.off) << " | " << skipped(*r, box2d::Skip::Bounds) << " | "
              << skipped(*r, box2d::Skip::WarmAxis) << " |\n";
        }
      }
    }

    bool lin_canny = false;
    for (const SkipMeasurement& m : measurements_) {
      lin_canny = lin_canny || m.on.runner == box2d::Backend::LinCanny;
    }
    if (!lin_canny) return;
    out << "\n`lin-canny` with skips `" << on << "` against `none` (its answer may change: see "
        << "the text):\n\n"
        << "| scene | hashes equal | contact updates on / off | max penetration m on / off "
           "| pd error max m on / off | misclassified on / off | KE final J on / off |\n"
        << "|---|---|--:|--:|--:|--:|--:|\n";
    for (const SkipMeasurement& m : measurements_) {
      if (m.on.runner != box2d::Backend::LinCanny) continue;
      out << "| " << m.on.scene << " | " << (m.on.hash == m.off.hash ? "yes" : "no") << " | "
          << m.on.contact_updates << " / " << m.off.contact_updates << " | "
          << metres(m.on.max_penetration) << " / " << metres(m.off.max_penetration) << " | "
          << metres(m.on.pd_error_max) << " / " << metres(m.off.pd_error_max) << " | "
          << m.on.misclassified << " / " << m.off.misclassified << " | "
          << fmt("%.3g", m.on.kinetic_energy_final) << " / "
          << fmt("%.3g", m.off.kinetic_energy_final) << " |\n";
    }
  }

  // One row per run with skips on (the `--skip` one, then each skip alone when `alone`) against
  // its `none` run: the report's table (the `--skip` runs) and `skips.csv` (all).
  Records skip_records(bool alone) const {
    const unsigned files = where::files;
    const unsigned shown = where::table | where::markdown;
    std::vector<Column> columns = {{"scene", "scene", "", -14},
                                   {"runner", "runner", "", -10},
                                   {"steps", "steps", "", 6},
                                   {"skips", "skips", "", -20, files},
                                   {"contact_updates_on", "", "", 9, files},
                                   {"contact_updates_off", "", "", 9, files},
                                   {"narrowphase_ns_per_pair_on", "ns/pair on", "", 9},
                                   {"narrowphase_ns_per_pair_off", "ns/pair off", "", 9},
                                   {"narrowphase_ratio", "on/off", "", 7},
                                   {"narrowphase_ms_on", "", "", 9, files},
                                   {"narrowphase_ms_off", "", "", 9, files},
                                   {"step_ms_median_on", "step ms on", "", 9},
                                   {"step_ms_median_off", "step ms off", "", 9},
                                   {"step_ratio", "on/off", "", 7},
                                   {"hash_on", "", "", 16, files},
                                   {"hash_off", "", "", 16, files},
                                   {"hashes_equal", "", "", 5, files},
                                   {"hashes_equal_flagged", "hashes equal", "", 5, shown},
                                   {"plugin_evaluations", "evaluations", "", 10}};
    for (int k = 0; k < box2d::skip_count; ++k) {
      const std::string why = box2d::name(static_cast<box2d::Skip>(k));
      columns.push_back({"skipped_" + why, "", "", 9, files});
      columns.push_back({"skipped_share_" + why, "skipped " + why, "", 12, shown});
    }
    Records out(std::move(columns));
    for (const SkipMeasurement& m : measurements_) {
      std::vector<const SceneMetrics*> on = {&m.on};
      if (alone) {
        for (const SceneMetrics& a : m.alone) on.push_back(&a);
      }
      for (const SceneMetrics* r : on) {
        const std::uint64_t of = r->plugin_evaluations.value_or(0);
        std::vector<Value> row = {Value::text(r->scene),
                                  Value::text(name(r->runner)),
                                  Value::count(r->steps),
                                  Value::text(r->skip_config ? skip_argument(*r->skip_config) : ""),
                                  Value::count(static_cast<std::int64_t>(r->contact_updates)),
                                  Value::count(static_cast<std::int64_t>(m.off.contact_updates)),
                                  Value::number(r->narrowphase_ns_per_pair, "%.1f"),
                                  Value::number(m.off.narrowphase_ns_per_pair, "%.1f"),
                                  Value::number(narrowphase_ratio(*r, m.off), "%.2f"),
                                  Value::number(r->narrowphase_ms_total, "%.3g"),
                                  Value::number(m.off.narrowphase_ms_total, "%.3g"),
                                  Value::number(r->step_ms_median, "%.3g"),
                                  Value::number(m.off.step_ms_median, "%.3g"),
                                  Value::number(r->step_ms_median / m.off.step_ms_median, "%.2f"),
                                  Value::text(hash_hex(r->hash)),
                                  Value::text(hash_hex(m.off.hash)),
                                  Value::text(r->hash == m.off.hash ? "true" : "false"),
                                  Value::text(hashes_equal(*r, m.off)),
                                  Value::count(static_cast<std::int64_t>(of))};
        for (int k = 0; k < box2d::skip_count; ++k) {
          const std::uint64_t n = skipped(*r, static_cast<box2d::Skip>(k));
          row.push_back(Value::count(static_cast<std::int64_t>(n)));
          row.push_back(Value::text(skipped_share(n, of)));
        }
        out.add(std::move(row));
      }
    }
    return out;
  }

  bool quick_ = false;
  box2d::Config skips_;
  std::vector<SkipMeasurement> measurements_;
};

}  // namespace

std::unique_ptr<CompareSection> make_skip_section() { return std::make_unique<SkipSection>(); }

}  // namespace dyop::report
