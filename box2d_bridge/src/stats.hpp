#pragma once
// Internal: the process-wide counters behind `dyop::box2d::stats()`.

#include "dyop/box2d.hpp"

namespace dyop::box2d::detail {

// The live counters, incremented by `collide_polygons` (single-threaded, like Box2D 2.4).
Stats& counters();

}  // namespace dyop::box2d::detail
