#pragma once
/// \file
/// `dyop compare [--quick] [--out DIR]`: every scene under every backend, one table with the
/// scene figures and each backend's narrow-phase time as a ratio to `box2d`'s in the same run,
/// the paper's Figure-7 experiment, and a report directory: `report.md`, the CSVs behind it,
/// gnuplot charts (time per method, time against error, Figure 7) and a snapshot of each scene.

#include <cstdint>
#include <iosfwd>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "scenes/metrics.hpp"
#include "scenes/paper.hpp"
#include "scenes/svg.hpp"

namespace dyop::scenes {

struct CompareOptions {
  bool quick = false;                       ///< the catalogue's quick step counts
  std::string out_dir = "reports/compare";  ///< where the report goes
  std::optional<int> steps;                 ///< every scene's step count (overrides the catalogue)
  std::uint64_t seed = 0;                   ///< every scene's seed
  std::vector<std::string> scenes;          ///< a subset, in catalogue order; empty: all
};

/// Timed repetitions of the Figure-7 experiment (each figure is their median).
int paper_repetitions(bool quick);

/// Threshold on `SceneMetrics::top_displacement` under which a pyramid or stack "stands" (m):
/// settling moves a top body by a few centimetres, a toppled one moves metres.
inline constexpr double standing_displacement = 0.1;

/// What a comparative run produced.
struct CompareRun {
  CompareOptions options;
  std::vector<SceneMetrics> rows;  ///< scene by scene, backends in `box2d::all_backends` order
  std::optional<paper::Experiment> paper;                  ///< when the paper scene was run
  std::vector<std::pair<std::string, Drawing>> snapshots;  ///< per scene: `dyop`'s final state
  double seconds = 0;                                      ///< wall time of the whole run
};

/// Runs it all, one progress line per scene and backend on `progress`. Throws what the scenes
/// throw (a refused installation).
CompareRun run_compare(const CompareOptions& options, std::ostream& progress);

/// `m`'s narrow-phase time per pair over `box2d`'s for the same scene in `run` (none if absent).
std::optional<double> ratio_to_box2d(const CompareRun& run, const SceneMetrics& m);

/// The main table (Markdown).
void write_compare_table(const CompareRun& run, std::ostream& out);

/// The Figure-7 table and the per-method summary of the paper experiment (Markdown).
void write_paper_tables(const paper::Experiment& e, std::ostream& out);

/// What became of the report.
struct ReportOutcome {
  std::vector<std::string> errors;    ///< files that could not be written (report.md, CSVs, SVGs)
  std::vector<std::string> warnings;  ///< charts not drawn (gnuplot missing or failing)
};

/// Writes the report directory (created if needed): the tables, CSVs and snapshots whatever
/// happens to the charts.
ReportOutcome write_report(const CompareRun& run);

/// The whole command: checks that the directory is writable first (exit 2 if not), runs, prints
/// the tables to `out` and progress and problems to `err`, writes the report and says where.
int run_compare_command(const CompareOptions& options, std::ostream& out, std::ostream& err);

}  // namespace dyop::scenes
