#include <cmath>

#include "dyop/box2d_outline.hpp"
#include "outline_triangulation.hpp"

namespace dyop::box2d {
namespace {

OutlineResult refused(OutlineError e, int ring = -1) {
  OutlineResult r;
  r.error = e;
  r.ring = ring;
  r.message = describe(e);
  return r;
}

}  // namespace

const char* describe(OutlineError e) {
  switch (e) {
    case OutlineError::None:
      return "outline added";
    case OutlineError::NoRings:
      return "no ring given";
    case OutlineError::NotFinite:
      return "a coordinate is NaN or infinite";
    case OutlineError::TooFewPoints:
      return "a ring has fewer than 3 distinct points";
    case OutlineError::ZeroArea:
      return "a ring encloses no area";
    case OutlineError::SelfIntersection:
      return "a ring crosses itself or another ring";
    case OutlineError::HoleOutside:
      return "a hole lies outside the outline";
    case OutlineError::NestedHoles:
      return "a hole lies inside another hole";
    case OutlineError::SplitInterior:
      return "holes touching each other or the outline cut the ground in pieces";
    case OutlineError::Invalid:
      return "GEOS finds the polygon invalid";
    case OutlineError::Triangles:
      return "add_triangles refused the triangulation";
  }
  return "unknown outline error";
}

OutlineResult add_outline(b2Body& body, const std::vector<std::vector<b2Vec2>>& rings,
                          const OutlineOptions& options) {
  const detail::Geos geos;
  GEOSContextHandle_t ctx = geos.get();
  const detail::CheckedPolygon checked = detail::checked_polygon(ctx, rings);
  if (checked.error != OutlineError::None) return refused(checked.error, checked.ring);
  const detail::Geometry simple = detail::simplified(ctx, *checked.polygon, options.simplify);
  if (!simple) return refused(OutlineError::Invalid);

  // The triangulation of each cell's piece (or of the whole polygon): pieces share the points
  // where the outline crosses a cell's side and the cells' corners, computed the same way on both
  // sides, so the triangles meet vertex to vertex.
  detail::Triangulation t;
  if (options.cell > 0) {
    double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    if (!GEOSGeom_getExtent_r(ctx, simple.get(), &x0, &y0, &x1, &y1)) {
      return refused(OutlineError::Invalid);
    }
    const double side = options.cell;
    std::vector<detail::Point> on_sides;
    detail::add_points_on_cell_sides(ctx, *simple, side, on_sides);
    for (double x = std::floor(x0 / side) * side; x < x1; x += side) {
      for (double y = std::floor(y0 / side) * side; y < y1; y += side) {
        if (!detail::triangulate_cell(ctx, *simple, on_sides, x, y, side, t)) {
          return refused(OutlineError::Invalid);
        }
      }
    }
  } else if (!detail::triangulate(ctx, *simple, t)) {
    return refused(OutlineError::Invalid);
  }
  OutlineResult r;
  r.vertices = static_cast<int>(t.vertices.size());
  r.mesh = add_triangles(body, t.vertices.data(), static_cast<int>(t.vertices.size()),
                         t.indices.data(), static_cast<int>(t.indices.size()), options.fixture);
  if (!r.mesh.ok()) {
    r.error = OutlineError::Triangles;
    r.message = describe(r.error);
    return r;
  }
  r.message = describe(OutlineError::None);
  return r;
}

}  // namespace dyop::box2d
