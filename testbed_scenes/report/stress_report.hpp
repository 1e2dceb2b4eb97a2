#pragma once
/// \file
/// `dyop stress`'s report: the records of `experiments/stress.hpp` as the aligned table, JSON and
/// the Markdown tables of docs/measurements.md.

#include <iosfwd>
#include <vector>

#include "experiments/stress.hpp"
#include "experiments/stress_convex.hpp"
#include "report/records.hpp"

namespace dyop::report {

/// The records, column by column: the aligned table printed by `dyop stress` and the JSON list
/// (every field of `StressRecord` but `runner`, whose name is `method`; one column per
/// invariance check, `invariance_translation`, ...; the worst pair, a `dyop pairs` CSV line, in
/// the JSON only).
Records stress_records(const std::vector<experiments::StressRecord>& records);

/// The convex part's records (`experiments/stress_convex.hpp`), one row per precision, class and
/// family: the aligned table printed after the triangles' and its JSON.
Records convex_stress_records(const std::vector<experiments::ConvexStressRecord>& records);

/// The stress tables of docs/measurements.md (Markdown): max error per runner and category, and the
/// counts per runner and precision.
void write_markdown(const std::vector<experiments::StressRecord>& records, std::ostream& out);

}  // namespace dyop::report
