#pragma once
/// \file
/// The main run behind `dyop compare [--quick] [--out DIR] [--skip all|none|LIST]`
/// (`program/compare_command.hpp`): every scene under every backend, for one table with the scene
/// figures and each backend's narrow-phase time as a ratio to `box2d`'s in the same run, and the
/// experiments of its sections: what skipping saves (`skip_scenes` with every skip off and on),
/// in-world timing, the paper's Figure-7 experiment, the `slide` scene side by side and levels
/// built as Box2D's chains and by the plug-in's builders
/// (`report/compare_section.hpp` runs and writes each section; `report/compare_report.hpp`
/// writes the report directory).

#include <array>
#include <functional>
#include <cstdint>
#include <iosfwd>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "experiments/in_world.hpp"
#include "scenes/drawing.hpp"
#include "scenes/metrics.hpp"
#include "scenes/scene.hpp"

namespace dyop::experiments {

struct CompareOptions {
  bool quick = false;                       ///< the catalogue's `compare_quick_steps`
  std::string out_dir = "reports/compare";  ///< where the report goes
  std::optional<int> steps;                 ///< every scene's step count (overrides the catalogue)
  std::uint64_t seed = 0;                   ///< every scene's seed
  std::vector<std::string> scenes;          ///< a subset, in catalogue order; empty: all
  /// The sections to run after the main table (`CompareSection::section_name`); empty: all.
  std::vector<std::string> sections;
  /// What the Box2D scenes may skip (`--skip`): the main table's runs, and the "on" side of the
  /// skip section.
  box2d::Config skips;
  /// The backends of the main table and the in-world section (`--backend`), run in
  /// `box2d::all_backends`' order; empty: `compare_backends`' and `in_world_backends`' defaults.
  std::vector<box2d::Backend> backends;
};

/// Scene `s`'s step count in a comparison: `--steps`, or the catalogue's full count, or with
/// `--quick` its `compare_quick_steps`. The main table and every section run these.
int compare_steps(const CompareOptions& options, const scenes::SceneInfo& s);

/// The backends of the main table: those `options.backends` names; else every backend in a full
/// run, and with `--quick` (the main command's overview, kept to seconds) `dyop`, what a user
/// installs, and `box2d` (Box2D's own `b2CollidePolygons` through the plug-in: the yardstick of
/// the summary's depth error).
std::vector<box2d::Backend> compare_backends(const CompareOptions& options);

/// The backends of the in-world section: those `options.backends` names; else every backend in
/// a full run, and with `--quick` `dyop` (what the summary's wall times are).
std::vector<box2d::Backend> in_world_backends(const CompareOptions& options);

/// True when `--quick`'s in-world and viewer sections leave scene `name` out: the two longest
/// (`rain-tall`, `tumbler`), whose figures the main table has; the full run has every scene.
bool left_out_of_quick_sections(const std::string& name);

/// Timed repetitions of the Figure-7 experiment (each figure is their median).
int paper_repetitions(bool quick);

/// Threshold on `SceneMetrics::top_displacement` under which a pyramid or stack "stands" (m):
/// settling moves a top body by a few centimetres, a toppled one moves metres.
inline constexpr double standing_displacement = 0.1;

/// The skip section's scenes (catalogue order), each run under every `skip_backends` with every
/// skip off and with `CompareOptions::skips`, back to back, same seed and steps.
inline constexpr std::array<const char*, 4> skip_scenes = {"pyramid", "rain", "tumbler", "mixed"};
inline constexpr std::array<box2d::Backend, 3> skip_backends = {
    box2d::Backend::Dyop, box2d::Backend::Sat, box2d::Backend::LinCanny};
/// The target: in these scenes with this backend, narrow-phase time with every skip on
/// at most `skip_target_ratio` × the time with every skip off. There each switch is also measured
/// alone against none.
inline constexpr std::array<const char*, 2> skip_target_scenes = {"rain", "tumbler"};
inline constexpr box2d::Backend skip_target_backend = box2d::Backend::Dyop;
inline constexpr double skip_target_ratio = 0.6;

/// Repetitions of each run of the skip section: 1 quick, 3 full. Each figure is that of the
/// repetition with the least narrow-phase time (other work on a shared machine only adds time).
int skip_repetitions(bool quick);

/// One scene and backend run with every skip off, then with skips on, then (target) each skip
/// alone; the repetitions interleaved so that what is compared is measured close in time.
struct SkipMeasurement;

/// Scene `s` under backend `b` for `steps`, with every skip off, with `options.skips`, and (target)
/// each skip alone, `skip_repetitions` times interleaved; each figure from the repetition with the
/// least narrow-phase time.
SkipMeasurement measure_skips(const scenes::SceneInfo& s, box2d::Backend b, int steps,
                              const CompareOptions& options);

struct SkipMeasurement {
  scenes::SceneMetrics off;  ///< `box2d::Config::no_skips()`
  scenes::SceneMetrics on;   ///< `CompareOptions::skips`
  /// `skip_target_scenes` with `skip_target_backend`: each switch alone, in `skip_switches` order,
  /// except `lin-canny-cache` (it changes nothing but `lin-canny`); empty otherwise.
  std::vector<scenes::SceneMetrics> alone;
};

/// True for a scene and backend of the target.
bool is_skip_target(const std::string& scene, const scenes::Runner& runner);

/// `on`'s narrow-phase time per contact update over `off`'s. When the two worlds evolve
/// identically (equal hashes) they have the same contact updates, so this is also the ratio of
/// their total narrow-phase times.
double narrowphase_ratio(const scenes::SceneMetrics& on, const scenes::SceneMetrics& off);

/// True for the backends whose answer no skip changes (bit-identical worlds): every one but
/// `lin-canny` (warm-started) and `dyop-fast` (approximate), as `box2d::Config` says.
bool skips_keep_the_answer(const scenes::Runner& runner);

/// What the main run produced.
struct CompareRun {
  CompareOptions options;
  std::vector<scenes::SceneMetrics>
      rows;  ///< scene by scene, backends in `box2d::all_backends` order
  std::vector<std::pair<std::string, scenes::Drawing>>
      snapshots;  ///< per scene: `dyop`'s final state
};

/// The scenes `options` selects, in catalogue order.
std::vector<const scenes::SceneInfo*> selected_scenes(const CompareOptions& options);

/// Runs every scene selected under every backend, one progress line per scene and backend on
/// `progress` (`elapsed`: seconds since the whole run started, for the lines' totals). Throws
/// what the scenes throw (a refused installation).
CompareRun run_compare(const CompareOptions& options, std::ostream& progress,
                       const std::function<double()>& elapsed);

/// `m`'s narrow-phase time per pair over `box2d`'s for the same scene in `run` (none if absent).
std::optional<double> ratio_to_box2d(const CompareRun& run, const scenes::SceneMetrics& m);

}  // namespace dyop::experiments
