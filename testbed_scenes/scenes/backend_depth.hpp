#pragma once
/// \file
/// One triangle pair's depth as a backend sees it, in float at `Level::Depth`: the library's
/// method behind the backend, or for `box2d` the deepest point of `b2CollidePolygons`' manifold
/// (`dyop::box2d::collide_triangles`). Used by every scene to check the backend against the exact
/// reference.

#include "dyop/box2d.hpp"

namespace dyop::scenes {

/// The backend's answer for `a`, `b`; `cache` warm-starts Lin–Canny (nullptr: cold), and is
/// ignored by the others.
Result<float> backend_depth(box2d::Backend backend, const Triangle<float>& a,
                            const Triangle<float>& b, LinCannyCache* cache);

}  // namespace dyop::scenes
