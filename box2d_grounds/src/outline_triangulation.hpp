#pragma once
// What the outline builder (`add_outline`) and the chunked terrain (`OutlineTerrain`) share: a GEOS
// context and geometries owned by their holder, the checks of a polygon given as rings, and the
// triangulation of a polygon cell by cell, so that both make the same triangles the same way.

#include <geos_c.h>

#include <box2d/b2_math.h>

#include <map>
#include <memory>
#include <utility>
#include <vector>

#include "dyop/box2d_outline.hpp"

namespace dyop::box2d::detail {

// One GEOS context (GEOS's reentrant API: nothing shared between threads); its error messages are
// dropped, as every failure is read from a call's return value.
class Geos {
 public:
  Geos();
  ~Geos();
  Geos(const Geos&) = delete;
  Geos& operator=(const Geos&) = delete;
  GEOSContextHandle_t get() const { return ctx_; }

 private:
  GEOSContextHandle_t ctx_;
};

// A geometry owned by its holder.
struct GeometryDeleter {
  GEOSContextHandle_t ctx;
  void operator()(GEOSGeometry* g) const { GEOSGeom_destroy_r(ctx, g); }
};
using Geometry = std::unique_ptr<GEOSGeometry, GeometryDeleter>;

// The grid every point of a triangulated piece is rounded to (metres). Why this: Box2D welds
// vertices closer than 0.5·b2_linearSlop (2.5 mm), so distinct points of this 3.9 mm grid make
// triangles it takes; a power of two keeps the cells' sides (multiples of a side that is itself a
// multiple of the grid) exactly on it, and every point of the grid within 32 km exact in float.
constexpr double cell_grid = 1.0 / 256;

// `rings` (`rings[0]` the outline, the others its holes, either winding, a closing repeat of the
// first point allowed) as a valid GEOS polygon, or why not: each ring's own defect first (`ring`
// the ring at fault), then GEOS's verdict on the polygon (`ring` -1).
struct CheckedPolygon {
  Geometry polygon;
  OutlineError error = OutlineError::None;
  int ring = -1;
};
CheckedPolygon checked_polygon(GEOSContextHandle_t ctx,
                               const std::vector<std::vector<b2Vec2>>& rings);

// `polygon` with the vertices within `tolerance` (metres) of the line through their neighbours
// dropped, its topology kept (GEOS's topology-preserving simplification); a copy when `tolerance`
// is 0; nullptr when GEOS fails.
Geometry simplified(GEOSContextHandle_t ctx, const GEOSGeometry& polygon, double tolerance);

// A point in double, as GEOS gives it.
struct Point {
  double x, y;
};

// Appends the vertices of `geometry`'s rings (any polygonal geometry) that lie on a side of the
// cells of side `side` (a coordinate a multiple of it). Why: where the outline touches a cell's
// side at a vertex from one side only, that vertex is a vertex of the piece on that side alone (a
// T-junction the rule cannot close) and can leave that piece touching itself: `triangulate_cell`
// puts it into the other piece too.
void add_points_on_cell_sides(GEOSContextHandle_t ctx, const GEOSGeometry& geometry, double side,
                              std::vector<Point>& out);

// Triangles: each point once (`index_of`: a point's index; the triangulation makes no point of its
// own), and three indices per triangle.
struct Triangulation {
  std::map<std::pair<float, float>, int> index_of;
  std::vector<b2Vec2> vertices;
  std::vector<int> indices;
};

// Appends the constrained Delaunay triangulation of the polygons of `piece` (its lines and points,
// where an outline only touches a cell's side, are passed by); false when GEOS fails.
bool triangulate(GEOSContextHandle_t ctx, const GEOSGeometry& piece, Triangulation& out);

// Appends the triangles of the piece of `polygon` in the cell [x, x + side] × [y, y + side]:
// clipped, the points of `on_sides` within the cell put into it, made valid where it touches
// itself there, and rounded to `cell_grid` (the same points the same way in every piece, so
// neighbouring cells meet vertex to vertex and no sliver Box2D would refuse is left); false when
// GEOS fails.
bool triangulate_cell(GEOSContextHandle_t ctx, const GEOSGeometry& polygon,
                      const std::vector<Point>& on_sides, double x, double y, double side,
                      Triangulation& out);

}  // namespace dyop::box2d::detail
