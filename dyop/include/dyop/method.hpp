#pragma once
/// \file
/// The registry of the library's narrow phases: one row per method, and every tool that lists
/// methods draws from it (the `dyop` command line, `dyop bench`, `dyop stress`, the scenes and
/// the paper experiment, the engine plug-in's backends, the Google Benchmark suite, the fuzzers).
/// Adding a method means one `Method` value, one row of `method_table` and its implementation.
///
/// Each row says how the method is called (`Entry`), in which precisions and at which query
/// levels, whether it keeps state between queries of the same pair (warm start), whether it is
/// fit to answer a physics engine's contacts, and how exact it is. Its `name` is its one spelling
/// in every table, CSV, chart and command line. Only the library's own methods are here: the
/// references the testbed compares them with (a physics engine's own narrow phase) and the
/// spellings of its comparisons are the testbed's.

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>
#include <type_traits>
#include <vector>

#include "dyop/dyop.hpp"
#include "dyop/dyop_paper.hpp"
#include "dyop/epa.hpp"
#include "dyop/lin_canny.hpp"
#include "dyop/pair_state.hpp"
#include "dyop/result.hpp"
#include "dyop/sat.hpp"
#include "dyop/triangle.hpp"

namespace dyop {

/// Every narrow phase, in registry order (`method_table`).
enum class Method : std::uint8_t {
  Dyop,       ///< `dyop`: DyOP-PD with certification, exact
  DyopFast,   ///< `dyop-fast`: the pivot heuristic alone, approximate
  DyopPaper,  ///< `dyop-paper`: the paper's equations literally, for reproduction
  LinCanny,   ///< `lin-canny`: closest-feature tracking, local-minimum depth
  Sat,        ///< `sat`: the exact reference
  Epa,        ///< `epa`: GJK + EPA
  Batch,      ///< `batch`: `sat`'s answer for many pairs at once (`penetrate_batch`)
};

/// Number of methods: the size of arrays indexed by `static_cast<int>(Method)`.
inline constexpr int method_count = 7;

/// How a method is called.
enum class Entry : std::uint8_t {
  /// One pair per call, through `penetrate` (or the row's `run<T>()`).
  PerPair,
  /// Many pairs per call over structure-of-arrays input: `penetrate_batch` (`dyop/batch.hpp`).
  Batch,
};

/// How close to the exact answer a method's depth and status are, by design.
enum class Accuracy : std::uint8_t {
  Exact,        ///< the exact answer up to rounding, invariant under rigid motions
  ToTolerance,  ///< converges to a stated tolerance, invariant under rigid motions (EPA)
  LocalDepth,   ///< exact distance; depth a local minimum that depends on the start (Lin–Canny)
  Approximate,  ///< a heuristic: can misclassify pairs and misjudge depths (`dyop-fast`, paper)
};

/// A per-pair entry point: `state` is the pair's warm-start state (`dyop/pair_state.hpp`;
/// nullptr: cold start), used by the methods that keep one and ignored by the others.
template <class T>
using PairFunction = Result<T> (*)(const Triangle<T>&, const Triangle<T>&, const Query<T>&,
                                   PairState* state);

/// The bit of `level` in `MethodInfo::levels`.
constexpr std::uint8_t level_bit(Level level) {
  return static_cast<std::uint8_t>(1u << static_cast<unsigned>(level));
}

/// Every query level.
inline constexpr std::uint8_t all_level_bits = level_bit(Level::Overlap) | level_bit(Level::Depth) |
                                               level_bit(Level::Contact) |
                                               level_bit(Level::Manifold);

/// What a row can do beyond its entry and levels, as bits of `MethodInfo::traits`: named where
/// the table is written, read through `MethodInfo`'s accessors.
namespace trait {
inline constexpr std::uint8_t runs_double = 1u << 0;  ///< has a double-precision version
inline constexpr std::uint8_t warm_start = 1u << 1;   ///< keeps state between queries of a pair
/// fit to answer a physics engine's contacts: one pair per call, robust, not the paper's literal
/// equations (the engine plug-in offers these as its backends)
inline constexpr std::uint8_t simulation = 1u << 2;
inline constexpr std::uint8_t internal_edges = 1u << 3;  ///< honours `Query::internal_edges`
/// honours `Query::witnesses` (false: a manifold without the Contact level's fields)
inline constexpr std::uint8_t manifold_only = 1u << 4;
}  // namespace trait

/// One row of the registry.
struct MethodInfo {
  Method method;  ///< the row's method
  /// Its one spelling: command line, tables, CSV columns, chart legends.
  const char* name;
  Entry entry;  ///< how it is called
  /// The query levels it answers, as `level_bit`s. Batch: Overlap and Depth.
  std::uint8_t levels;
  std::uint8_t traits;              ///< `trait` bits; read them through the accessors below
  Accuracy accuracy;                ///< how exact it is by design
  PairFunction<float> run_float;    ///< `Entry::PerPair` only (else nullptr)
  PairFunction<double> run_double;  ///< `Entry::PerPair` only (else nullptr)

  /// Has a double-precision version.
  constexpr bool runs_double() const { return (traits & trait::runs_double) != 0; }
  /// Keeps state between queries of the same pair (in its `PairState`).
  constexpr bool warm_start() const { return (traits & trait::warm_start) != 0; }
  /// Fit to answer a physics engine's contacts (`trait::simulation`).
  constexpr bool simulation() const { return (traits & trait::simulation) != 0; }
  /// Honours `Query::internal_edges` (the exact `dyop` and `sat`); the others answer as if every
  /// axis were allowed.
  constexpr bool internal_edges() const { return (traits & trait::internal_edges) != 0; }
  /// Honours `Query::witnesses` (the exact `dyop` and `sat`): a manifold asked for without
  /// witnesses costs less. The others fill the Contact level's fields anyway.
  constexpr bool manifold_only() const { return (traits & trait::manifold_only) != 0; }

  /// True when it answers queries at `level`.
  constexpr bool has(Level level) const { return (levels & level_bit(level)) != 0; }
  /// True when its answers are exact or within a tolerance that does not depend on where the
  /// pair is: the same answer, moved, for a moved pair.
  constexpr bool invariant() const {
    return accuracy == Accuracy::Exact || accuracy == Accuracy::ToTolerance;
  }
  /// The per-pair entry point in precision T (nullptr for `Entry::Batch`).
  template <class T>
  constexpr PairFunction<T> run() const {
    if constexpr (std::is_same_v<T, float>) {
      return run_float;
    } else {
      return run_double;
    }
  }
};

namespace detail {

// The per-pair entry point of a method that keeps no state between queries.
template <class T, Result<T> (*F)(const Triangle<T>&, const Triangle<T>&, const Query<T>&)>
Result<T> stateless(const Triangle<T>& a, const Triangle<T>& b, const Query<T>& query, PairState*) {
  return F(a, b, query);
}

// Lin–Canny's entry point: its part of the pair's state.
template <class T>
Result<T> lin_canny_warm(const Triangle<T>& a, const Triangle<T>& b, const Query<T>& query,
                         PairState* state) {
  return lin_canny(a, b, query, state != nullptr ? &state->lin_canny : nullptr);
}

}  // namespace detail

/// The registry, in `Method` order.
inline constexpr MethodInfo method_table[method_count] = {
    {Method::Dyop, "dyop", Entry::PerPair, all_level_bits,
     trait::runs_double | trait::simulation | trait::internal_edges | trait::manifold_only,
     Accuracy::Exact, &detail::stateless<float, &dyop<float>>,
     &detail::stateless<double, &dyop<double>>},
    {Method::DyopFast, "dyop-fast", Entry::PerPair, all_level_bits,
     trait::runs_double | trait::simulation, Accuracy::Approximate,
     &detail::stateless<float, &dyop_fast<float>>, &detail::stateless<double, &dyop_fast<double>>},
    {Method::DyopPaper, "dyop-paper", Entry::PerPair, all_level_bits, trait::runs_double,
     Accuracy::Approximate, &detail::stateless<float, &dyop_paper<float>>,
     &detail::stateless<double, &dyop_paper<double>>},
    {Method::LinCanny, "lin-canny", Entry::PerPair, all_level_bits,
     trait::runs_double | trait::warm_start | trait::simulation, Accuracy::LocalDepth,
     &detail::lin_canny_warm<float>, &detail::lin_canny_warm<double>},
    {Method::Sat, "sat", Entry::PerPair, all_level_bits,
     trait::runs_double | trait::simulation | trait::internal_edges | trait::manifold_only,
     Accuracy::Exact, &detail::stateless<float, &sat<float>>,
     &detail::stateless<double, &sat<double>>},
    {Method::Epa, "epa", Entry::PerPair, all_level_bits, trait::runs_double | trait::simulation,
     Accuracy::ToTolerance, &detail::stateless<float, &epa<float>>,
     &detail::stateless<double, &epa<double>>},
    {Method::Batch, "batch", Entry::Batch,
     static_cast<std::uint8_t>(level_bit(Level::Overlap) | level_bit(Level::Depth)),
     trait::runs_double, Accuracy::Exact, nullptr, nullptr},
};

namespace detail {

constexpr bool rows_in_method_order() {
  for (int i = 0; i < method_count; ++i) {
    if (static_cast<int>(method_table[i].method) != i) return false;
  }
  return true;
}
static_assert(rows_in_method_order(), "method_table must list the methods in `Method` order");

}  // namespace detail

/// The row of `m`.
constexpr const MethodInfo& info(Method m) { return method_table[static_cast<int>(m)]; }

/// The one spelling of `m` (`info(m).name`): "dyop", "dyop-fast", "dyop-paper", "lin-canny",
/// "sat", "epa", "batch".
constexpr const char* name(Method m) { return info(m).name; }

/// A choice of the registry's rows (the methods fit for simulation, those that answer single
/// pairs, ...): true for the rows it keeps.
using RowFilter = bool (*)(const MethodInfo& row);

/// The method spelt `s` (its `name`) among the rows `keep` keeps (every row when nullptr), or
/// nothing: the one parser of method names (the engine plug-in's backends are parsed through it).
std::optional<Method> parse_method(std::string_view s, RowFilter keep = nullptr);

namespace detail {

template <class Keep>
constexpr std::size_t count_methods(Keep keep) {
  std::size_t n = 0;
  for (const MethodInfo& row : method_table) n += keep(row) ? 1 : 0;
  return n;
}

template <std::size_t N, class Keep>
constexpr std::array<Method, N> select_methods(Keep keep) {
  std::array<Method, N> out{};
  std::size_t k = 0;
  for (const MethodInfo& row : method_table) {
    if (keep(row)) out[k++] = row.method;
  }
  return out;
}

inline constexpr auto is_per_pair = [](const MethodInfo& row) {
  return row.entry == Entry::PerPair;
};

}  // namespace detail

/// The methods `penetrate` runs (`Entry::PerPair`), in registry order: dyop, dyop-fast,
/// dyop-paper, lin-canny, sat, epa.
inline constexpr auto pair_methods =
    detail::select_methods<detail::count_methods(detail::is_per_pair)>(detail::is_per_pair);

/// Runs method `m` on one pair. `state` is the pair's warm-start state, used by the methods that
/// keep one (`info(m).warm_start()`; nullptr: cold start). `m` must be one of `pair_methods`;
/// `Batch` answers `Invalid` here.
template <class T>
Result<T> penetrate(Method m, const Triangle<T>& a, const Triangle<T>& b,
                    const Query<T>& query = {}, PairState* state = nullptr);

/// \cond EXPLICIT_INSTANTIATIONS
extern template Result<float> penetrate(Method, const Triangle<float>&, const Triangle<float>&,
                                        const Query<float>&, PairState*);
extern template Result<double> penetrate(Method, const Triangle<double>&, const Triangle<double>&,
                                         const Query<double>&, PairState*);
/// \endcond

}  // namespace dyop
