#pragma once
/// \file
/// What `dyop compare` opens with, on standard output and at the top of `report.md`: the plug-in
/// against Box2D's own contact on this machine in at most `summary_max_lines` lines, every
/// figure taken from the records the run's main table and sections produced.

#include <optional>
#include <string>
#include <vector>

#include "report/compare_section.hpp"

namespace dyop::report {

/// The most lines the summary takes: what a newcomer reads in a minute.
inline constexpr int summary_max_lines = 20;

/// One sliding scene's bodies under Box2D's own contact and under the plug-in (`dyop`).
struct GlideFigures {
  std::string scene;  ///< "slide" (triangulated grounds) or "tiles" (tiled grounds)
  /// Largest |v_y| (m/s) and smallest travel (1: a glide) of the sliding bodies, each side.
  double own_vertical_speed = 0, own_travel = 0, plugin_vertical_speed = 0, plugin_travel = 0;
};

/// One scene's wall time with the plug-in (`dyop`) over Box2D's own contact (below 1: faster).
struct WallTimeFigures {
  std::string scene;
  double narrowphase_ratio = 0;  ///< `b2Profile::collide`
  double step_ratio = 0;         ///< `b2World::Step`
};

/// One level built as Box2D's chain loops (Box2D's own contact) and by the plug-in's builders (the
/// plug-in), from the grounds section.
struct GroundFigures {
  std::string level;  ///< e.g. "tile grid, 256 × 64 cells of 0.5 m"
  /// Largest |v_y| (m/s) of the everyday bodies pushed along the top: the chain under Box2D's
  /// own contact, the same chain under the plug-in, the builders' ground.
  double chain_vertical_speed = 0, chain_plugin_vertical_speed = 0, builders_vertical_speed = 0;
  /// Boxes started 0.4 m inside the ground that ended on top, the chain's and the builders', of
  /// `boxes`.
  int chain_on_top = 0, builders_on_top = 0, boxes = 0;
  /// A crowd's `b2Profile::collide` and `b2World::Step` under the plug-in over Box2D's own on the
  /// same chain, and on the same two-sided edges.
  double chain_narrowphase_ratio = 0, chain_step_ratio = 0;
  double edges_narrowphase_ratio = 0, edges_step_ratio = 0;
  /// The same for the builders' ground over the chain under Box2D's own contact.
  double narrowphase_ratio = 0, step_ratio = 0;
};

/// The largest depth error of one runner over the main table's scenes, and where.
struct DepthErrorFigures {
  double max_m = 0;   ///< largest `pd_error_max` (m)
  std::string scene;  ///< the scene of that error
};

/// Everything the summary says, in figures; a part the run did not measure is absent.
struct SummaryFigures {
  std::string machine;                          ///< the CPU and its hardware threads
  int scenes = 0;                               ///< scenes of the main table
  std::optional<DepthErrorFigures> depth_own;   ///< Box2D's `b2CollidePolygons` (`box2d`)
  std::optional<DepthErrorFigures> depth_dyop;  ///< the plug-in (`dyop`)
  std::vector<GlideFigures> glides;             ///< from the slide section
  std::vector<WallTimeFigures> wall_times;      ///< from the in-world section
  std::vector<GroundFigures> grounds;           ///< from the grounds section
  bool viewer_pages = false;                    ///< the viewer section wrote its pages
};

/// The figures of `comparison`: the main table's, then each measured section's
/// (`CompareSection::summarize`).
SummaryFigures summary_figures(const Comparison& comparison);

/// The summary's lines (Markdown that reads as plain text), at most `summary_max_lines`.
std::vector<std::string> summary_lines(const Comparison& comparison);

}  // namespace dyop::report
