#pragma once
/// \file
/// The main table of `dyop compare` (Markdown), printed by the command and written in its
/// `report.md`; each section's tables are its own (`report/compare_section.hpp`).

#include <ostream>

#include "experiments/compare.hpp"

namespace dyop::report {

/// The main table (Markdown).
void write_compare_table(const experiments::CompareRun& run, std::ostream& out);

}  // namespace dyop::report
