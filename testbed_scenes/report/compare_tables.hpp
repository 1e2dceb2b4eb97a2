#pragma once
/// \file
/// The tables of `dyop compare` (Markdown), printed by the command and written in its
/// `report.md`, and the in-world runs' CSV.

#include <ostream>
#include <vector>

#include "scenes/compare.hpp"

namespace dyop::report {

/// The main table (Markdown).
void write_compare_table(const scenes::CompareRun& run, std::ostream& out);

/// The skip section's tables (Markdown): skips on against off per scene and backend, each switch
/// alone in the breakdown scenes, and what skipping changes in `lin-canny`'s answers.
void write_skip_tables(const scenes::CompareRun& run, std::ostream& out);

/// The Figure-7 table and the per-method summary of the paper experiment (Markdown).
void write_paper_tables(const scenes::paper::Experiment& e, std::ostream& out);

/// The in-world table (Markdown): one row per scene and backend.
void write_in_world_table(const std::vector<scenes::InWorldRatio>& rows, std::ostream& out);

/// The slide section's tables (Markdown): per runner, the sliding bodies' largest speeds, their
/// smallest travel and the resting box's jitter; then per slider, each runner's figures.
void write_slide_tables(const std::vector<scenes::SlideRun>& runs, std::ostream& out);

/// The in-world CSV (header and one line per scene and backend).
void write_in_world_csv(const std::vector<scenes::InWorldRatio>& rows, std::ostream& out);

}  // namespace dyop::report
