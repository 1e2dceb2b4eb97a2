#pragma once
// Internal: the process-wide counters behind `dyop::box2d::stats()`.

#include "dyop/box2d.hpp"

namespace dyop::box2d::detail {

// The live counters, incremented by every evaluation (single-threaded, like Box2D 2.4). Inline:
// an evaluation that is skipped costs a few dozen instructions, and a call would add to them.
inline Stats live_counters;
inline Stats& counters() { return live_counters; }

}  // namespace dyop::box2d::detail
