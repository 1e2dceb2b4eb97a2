#pragma once
/// \file
/// Box2D's own narrow phase as a reference the testbed compares the library's methods with (the
/// plug-in itself does not use it): `dyop pairs --method box2d`, `dyop bench`, `dyop stress`, the
/// scenes' depth checks and the tests.

#include "dyop/result.hpp"
#include "dyop/triangle.hpp"

namespace dyop::box2d {

/// Box2D's own answer for two triangles, under the library's conventions (`dyop/result.hpp`),
/// in float: `dyop pairs --method box2d`. Each triangle becomes a `b2PolygonShape` about its own
/// centroid, placed by a translation (a body whose origin is its centre of mass), with skin radius
/// 0 (`m_radius = 0`: pure geometry, no speculative margin). Then `b2CollidePolygons`:
/// - points: Penetrating or Touching; `separation` is the deepest point's, `normal` the manifold's
///   world normal (A to B), witnesses the deepest point and its projection on the reference face;
/// - no points: the distance from `b2Distance` (Box2D's GJK), its closest points and iterations;
///   Separated beyond `touching_tolerance`, else Touching (with a zero normal at distance 0).
/// Valid fields: those of `Level::Contact` except the features; `manifold` is left empty.
/// Invalid (a default `Result`: no answer, reason `None`) only if Box2D's float arithmetic gives a
/// non-finite value.
Result<float> collide_triangles(const Triangle<float>& a, const Triangle<float>& b);

}  // namespace dyop::box2d
