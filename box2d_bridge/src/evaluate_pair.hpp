#pragma once
// Internal: one evaluation of a polygon pair by the plug-in, with the pair's memory of its last
// evaluation and the skips it allows.

#include <box2d/b2_collision.h>
#include <box2d/b2_polygon_shape.h>

#include "dyop/box2d.hpp"

namespace dyop::box2d::detail {

// The plug-in's answer for one polygon pair with `config`'s skips, counted in `stats`.
void evaluate_pair(b2Manifold* manifold, Backend backend, const Config& config,
                   const b2PolygonShape& a, const b2Transform& xf_a, const b2PolygonShape& b,
                   const b2Transform& xf_b, ContactMemory& memory);

}  // namespace dyop::box2d::detail
