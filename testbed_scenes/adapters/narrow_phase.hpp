#pragma once
/// \file
/// What the testbed compares on pairs: a narrow phase is a method of the library run one way
/// (a `Variant` of a registry row: `adapters/variant.hpp`), or Box2D's own `b2CollidePolygons` —
/// the production reference of every comparison, which the library does not link (in builds with
/// Box2D, through `box2d_reference/`; float only, its whole manifold at every level). Every tool
/// that lists what it compares (`dyop bench`, `dyop stress`, `dyop pairs`, the paper experiment)
/// lists narrow phases from here, so the registry stays the library's and Box2D is named only here.

#include <optional>
#include <string_view>
#include <vector>

#include "adapters/variant.hpp"
#include "dyop/method.hpp"

namespace dyop::adapters {

/// How a narrow phase is called: one adapter each (`pair_function`, the batch kernel's arrays,
/// Box2D's shapes).
enum class Call : std::uint8_t {
  PerPair,  ///< the library's per-pair entry (`Entry::PerPair`)
  Batch,    ///< the library's batch kernel over structure-of-arrays input (`Entry::Batch`)
  Box2D,    ///< Box2D's `b2CollidePolygons` on `b2PolygonShape`s
};

/// A narrow phase the testbed runs on pairs.
struct NarrowPhase {
  /// The library's method and whether it runs warm-started; nothing: Box2D's `b2CollidePolygons`.
  std::optional<Variant> method;

  /// Box2D's `b2CollidePolygons`.
  static NarrowPhase box2d() { return {}; }
  /// Method `m`, from no state (cold).
  static NarrowPhase of(Method m) { return {Variant{m, false}}; }
};

/// True when `x` and `y` are the same narrow phase run the same way.
bool operator==(const NarrowPhase& x, const NarrowPhase& y);
inline bool operator!=(const NarrowPhase& x, const NarrowPhase& y) { return !(x == y); }

/// Its spelling in every table and on the command line: the variant's (`name(Variant)`:
/// "dyop", "lin-canny-warm", ...) or "box2d".
const char* name(const NarrowPhase& p);

/// How it is called.
Call call_of(const NarrowPhase& p);

/// True when it answers at `level` (Box2D: its manifold is always whole, so it is asked, and
/// timed, at `Level::Manifold` only).
bool has(const NarrowPhase& p, Level level);

/// True when it has a double-precision version (Box2D runs in float only).
bool runs_double(const NarrowPhase& p);

/// True when this build can run it (Box2D's only in builds with Box2D).
bool built(const NarrowPhase& p);

/// Every narrow phase of this build: the variants of the registry rows `keep` keeps (every row
/// when nullptr; registry order, cold before warm), then Box2D's `b2CollidePolygons` when
/// `with_box2d` and built.
std::vector<NarrowPhase> narrow_phases(RowFilter keep, bool with_box2d);

/// The narrow phase spelt `s` (a method's `name`, run cold, or "box2d" when built), or nothing.
std::optional<NarrowPhase> parse_narrow_phase(std::string_view s);

}  // namespace dyop::adapters
