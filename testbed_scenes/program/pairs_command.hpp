#pragma once
/// \file
/// `dyop pairs`: runs methods over the pair CSV (contract in `program/pair_csv.hpp`). The
/// subcommand itself (arguments, files) is registered by `add_pairs_command` (`commands.hpp`).

#include <iosfwd>
#include <vector>

#include "dyop/batch.hpp"
#include "program/pair_method.hpp"

namespace dyop::cli {

struct PairsOptions {
  std::vector<PairMethod> methods;  ///< one: the CSV contract; several: a `method` column first
  bool use_float = false;           ///< convert input to float and run the float instantiation
  bool table = false;               ///< aligned human-readable table instead of CSV
  /// The kernel the batch method runs (`--batch-kernel`): the fastest here by default; one that
  /// cannot run here answers every row with an error line.
  BatchKernel batch_kernel = BatchKernel::Auto;
};

/// Output lines written, and how many of them are errors.
struct PairsSummary {
  int rows = 0;
  int ok = 0;
  int errors = 0;
};

/// Reads every line of `in`, writes one output line per data line and method; never stops on a
/// bad line.
PairsSummary run_pairs(const PairsOptions& options, std::istream& in, std::ostream& out);

}  // namespace dyop::cli
