#include "outline_triangulation.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>

namespace dyop::box2d::detail {
namespace {

// `ring` without consecutive repeats and without a closing repeat of its first point.
std::vector<b2Vec2> distinct_points(const std::vector<b2Vec2>& ring) {
  std::vector<b2Vec2> out;
  for (const b2Vec2& p : ring) {
    if (out.empty() || !(p.x == out.back().x && p.y == out.back().y)) out.push_back(p);
  }
  while (out.size() > 1 && out.front().x == out.back().x && out.front().y == out.back().y) {
    out.pop_back();
  }
  return out;
}

// Twice the signed area of `ring` (shoelace, in double).
double twice_area(const std::vector<b2Vec2>& ring) {
  double sum = 0;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const b2Vec2& p = ring[i];
    const b2Vec2& q = ring[(i + 1) % ring.size()];
    sum += static_cast<double>(p.x) * q.y - static_cast<double>(q.x) * p.y;
  }
  return sum;
}

// The ring's own defect, before GEOS sees it.
OutlineError ring_error(const std::vector<b2Vec2>& ring) {
  for (const b2Vec2& p : ring) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) return OutlineError::NotFinite;
  }
  if (ring.size() < 3) return OutlineError::TooFewPoints;
  if (twice_area(ring) == 0) return OutlineError::ZeroArea;
  return OutlineError::None;
}

// A closed GEOS ring of `points`, or nullptr.
GEOSGeometry* make_ring(GEOSContextHandle_t ctx, const std::vector<b2Vec2>& points) {
  const auto n = static_cast<unsigned>(points.size());
  GEOSCoordSequence* seq = GEOSCoordSeq_create_r(ctx, n + 1, 2);
  if (!seq) return nullptr;
  for (unsigned i = 0; i <= n; ++i) {
    const b2Vec2& p = points[i % n];
    GEOSCoordSeq_setXY_r(ctx, seq, i, p.x, p.y);
  }
  return GEOSGeom_createLinearRing_r(ctx, seq);  // takes the sequence
}

// GEOS's reason for an invalid polygon (GEOS 3.11's TopologyValidationError messages), as ours.
OutlineError invalid_reason(const char* reason) {
  const auto starts = [&](const char* prefix) {
    return std::strncmp(reason, prefix, std::strlen(prefix)) == 0;
  };
  if (starts("Self-intersection") || starts("Ring Self-intersection") ||
      starts("Duplicate Rings")) {
    return OutlineError::SelfIntersection;
  }
  if (starts("Hole lies outside shell")) return OutlineError::HoleOutside;
  if (starts("Holes are nested")) return OutlineError::NestedHoles;
  if (starts("Interior is disconnected")) return OutlineError::SplitInterior;
  if (starts("Too few points")) return OutlineError::TooFewPoints;
  if (starts("Invalid Coordinate")) return OutlineError::NotFinite;
  return OutlineError::Invalid;
}

CheckedPolygon refused(OutlineError e, int ring = -1) {
  CheckedPolygon out;
  out.error = e;
  out.ring = ring;
  return out;
}

// Calls `visit(ring)` for every ring of the polygons within `geometry`.
void for_each_ring(GEOSContextHandle_t ctx, const GEOSGeometry& geometry,
                   const std::function<void(const GEOSGeometry&)>& visit) {
  const int type = GEOSGeomTypeId_r(ctx, &geometry);
  if (type == GEOS_POLYGON) {
    if (GEOSisEmpty_r(ctx, &geometry)) return;
    visit(*GEOSGetExteriorRing_r(ctx, &geometry));
    for (int i = 0; i < GEOSGetNumInteriorRings_r(ctx, &geometry); ++i) {
      visit(*GEOSGetInteriorRingN_r(ctx, &geometry, i));
    }
    return;
  }
  if (type == GEOS_MULTIPOLYGON || type == GEOS_GEOMETRYCOLLECTION) {
    for (int i = 0; i < GEOSGetNumGeometries_r(ctx, &geometry); ++i) {
      for_each_ring(ctx, *GEOSGetGeometryN_r(ctx, &geometry, i), visit);
    }
  }
}

// The triangles of `collection` (GEOS polygons of 3 distinct points each) appended to `out`.
void read_triangles(GEOSContextHandle_t ctx, const GEOSGeometry& collection, Triangulation& out) {
  const int count = GEOSGetNumGeometries_r(ctx, &collection);
  for (int t = 0; t < count; ++t) {
    const GEOSGeometry* triangle = GEOSGetGeometryN_r(ctx, &collection, t);
    const GEOSCoordSequence* seq =
        GEOSGeom_getCoordSeq_r(ctx, GEOSGetExteriorRing_r(ctx, triangle));
    for (unsigned i = 0; i < 3; ++i) {
      double x = 0;
      double y = 0;
      GEOSCoordSeq_getXY_r(ctx, seq, i, &x, &y);
      const b2Vec2 p(static_cast<float>(x), static_cast<float>(y));
      const auto [at, added] =
          out.index_of.emplace(std::make_pair(p.x, p.y), static_cast<int>(out.vertices.size()));
      if (added) out.vertices.push_back(p);
      out.indices.push_back(at->second);
    }
  }
}

}  // namespace

Geos::Geos() : ctx_(GEOS_init_r()) {
  GEOSContext_setErrorMessageHandler_r(
      ctx_, [](const char*, void*) {}, nullptr);
}

Geos::~Geos() { GEOS_finish_r(ctx_); }

CheckedPolygon checked_polygon(GEOSContextHandle_t ctx,
                               const std::vector<std::vector<b2Vec2>>& rings) {
  if (rings.empty()) return refused(OutlineError::NoRings);
  std::vector<std::vector<b2Vec2>> clean;
  for (std::size_t i = 0; i < rings.size(); ++i) {
    clean.push_back(distinct_points(rings[i]));
    const OutlineError e = ring_error(clean.back());
    if (e != OutlineError::None) return refused(e, static_cast<int>(i));
  }
  GEOSGeometry* shell = make_ring(ctx, clean[0]);
  std::vector<GEOSGeometry*> holes;
  for (std::size_t i = 1; i < clean.size(); ++i) holes.push_back(make_ring(ctx, clean[i]));
  const bool made =
      shell && std::all_of(holes.begin(), holes.end(), [](GEOSGeometry* g) { return g; });
  if (!made) {
    if (shell) GEOSGeom_destroy_r(ctx, shell);
    for (GEOSGeometry* g : holes) {
      if (g) GEOSGeom_destroy_r(ctx, g);
    }
    return refused(OutlineError::Invalid);
  }
  CheckedPolygon out;
  out.polygon = Geometry(
      GEOSGeom_createPolygon_r(ctx, shell, holes.data(), static_cast<unsigned>(holes.size())),
      GeometryDeleter{ctx});
  if (!out.polygon) return refused(OutlineError::Invalid);
  char* reason = nullptr;
  const char valid = GEOSisValidDetail_r(ctx, out.polygon.get(), 0, &reason, nullptr);
  if (valid != 1) {
    const OutlineError e = reason ? invalid_reason(reason) : OutlineError::Invalid;
    if (reason) GEOSFree_r(ctx, reason);
    return refused(e);
  }
  return out;
}

Geometry simplified(GEOSContextHandle_t ctx, const GEOSGeometry& polygon, double tolerance) {
  return Geometry(tolerance > 0 ? GEOSTopologyPreserveSimplify_r(ctx, &polygon, tolerance)
                                : GEOSGeom_clone_r(ctx, &polygon),
                  GeometryDeleter{ctx});
}

void add_points_on_cell_sides(GEOSContextHandle_t ctx, const GEOSGeometry& geometry, double side,
                              std::vector<Point>& out) {
  for_each_ring(ctx, geometry, [&](const GEOSGeometry& ring) {
    const GEOSCoordSequence* seq = GEOSGeom_getCoordSeq_r(ctx, &ring);
    unsigned size = 0;
    GEOSCoordSeq_getSize_r(ctx, seq, &size);
    for (unsigned i = 0; i + 1 < size; ++i) {  // a ring repeats its first point last
      double x = 0;
      double y = 0;
      GEOSCoordSeq_getXY_r(ctx, seq, i, &x, &y);
      if (std::fmod(x, side) == 0 || std::fmod(y, side) == 0) out.push_back({x, y});
    }
  });
}

bool triangulate(GEOSContextHandle_t ctx, const GEOSGeometry& piece, Triangulation& out) {
  const int type = GEOSGeomTypeId_r(ctx, &piece);
  if (type == GEOS_GEOMETRYCOLLECTION) {
    for (int i = 0; i < GEOSGetNumGeometries_r(ctx, &piece); ++i) {
      if (!triangulate(ctx, *GEOSGetGeometryN_r(ctx, &piece, i), out)) return false;
    }
    return true;
  }
  if ((type != GEOS_POLYGON && type != GEOS_MULTIPOLYGON) || GEOSisEmpty_r(ctx, &piece)) {
    return true;
  }
  const Geometry triangles(GEOSConstrainedDelaunayTriangulation_r(ctx, &piece),
                           GeometryDeleter{ctx});
  if (!triangles) return false;
  read_triangles(ctx, *triangles, out);
  return true;
}

bool triangulate_cell(GEOSContextHandle_t ctx, const GEOSGeometry& polygon,
                      const std::vector<Point>& on_sides, double x, double y, double side,
                      Triangulation& out) {
  const GeometryDeleter destroy{ctx};
  Geometry piece(GEOSClipByRect_r(ctx, &polygon, x, y, x + side, y + side), destroy);
  if (!piece) return false;
  if (GEOSisEmpty_r(ctx, piece.get())) return true;
  std::vector<GEOSGeometry*> points;
  for (const Point& p : on_sides) {
    if (p.x >= x && p.x <= x + side && p.y >= y && p.y <= y + side) {
      points.push_back(GEOSGeom_createPointFromXY_r(ctx, p.x, p.y));
    }
  }
  if (!points.empty()) {
    const Geometry snap_to(GEOSGeom_createCollection_r(ctx, GEOS_MULTIPOINT, points.data(),
                                                       static_cast<unsigned>(points.size())),
                           destroy);
    // Within this of a piece's edge (metres), a point on a cell's side is put into that edge: far
    // below any coordinate's rounding that matters (`cell_grid`).
    const double snap = 1e-9 * side;
    piece.reset(GEOSSnap_r(ctx, piece.get(), snap_to.get(), snap));
  }
  // A piece touching itself at such a vertex is made valid (GEOS moves no point).
  if (piece && GEOSisValid_r(ctx, piece.get()) != 1) piece.reset(GEOSMakeValid_r(ctx, piece.get()));
  // Where the outline passes within millimetres of a cell's side or corner, the piece has slivers
  // Box2D refuses: its points are rounded to `cell_grid`, and what collapses goes. A piece cut from
  // a polygon already rounded keeps its grid as precision model, and GEOS rounds nothing to the
  // grid a geometry claims to be on: it is given a floating one first (a copy).
  if (piece && GEOSGeom_getPrecision_r(ctx, piece.get()) != 0) {
    piece.reset(GEOSGeom_setPrecision_r(ctx, piece.get(), 0, 0));
  }
  if (piece) piece.reset(GEOSGeom_setPrecision_r(ctx, piece.get(), cell_grid, 0));
  return piece && triangulate(ctx, *piece, out);
}

}  // namespace dyop::box2d::detail
