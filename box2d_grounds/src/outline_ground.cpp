#include <geos_c.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <map>
#include <memory>
#include <utility>

#include "dyop/box2d_outline.hpp"

namespace dyop::box2d {
namespace {

// One GEOS context for one call (GEOS's reentrant API: nothing shared between threads); its
// error messages are dropped, as every failure is read from the call's return value.
class Geos {
 public:
  Geos() : ctx_(GEOS_init_r()) {
    GEOSContext_setErrorMessageHandler_r(
        ctx_, [](const char*, void*) {}, nullptr);
  }
  ~Geos() { GEOS_finish_r(ctx_); }
  Geos(const Geos&) = delete;
  Geos& operator=(const Geos&) = delete;
  GEOSContextHandle_t get() const { return ctx_; }

 private:
  GEOSContextHandle_t ctx_;
};

// A geometry owned by the call.
struct GeometryDeleter {
  GEOSContextHandle_t ctx;
  void operator()(GEOSGeometry* g) const { GEOSGeom_destroy_r(ctx, g); }
};
using Geometry = std::unique_ptr<GEOSGeometry, GeometryDeleter>;

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

OutlineResult refused(OutlineError e, int ring = -1) {
  OutlineResult r;
  r.error = e;
  r.ring = ring;
  r.message = describe(e);
  return r;
}

// The triangles of `collection` (GEOS polygons of 3 distinct points each) appended to a vertex
// list, each point once (`index_of`: a point's index; the triangulation makes no point of its
// own), and indices.
void read_triangles(GEOSContextHandle_t ctx, const GEOSGeometry& collection,
                    std::map<std::pair<float, float>, int>& index_of, std::vector<b2Vec2>& vertices,
                    std::vector<int>& indices) {
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
          index_of.emplace(std::make_pair(p.x, p.y), static_cast<int>(vertices.size()));
      if (added) vertices.push_back(p);
      indices.push_back(at->second);
    }
  }
}

// The grid the points of a cell's piece are rounded to (metres). Why this: Box2D welds vertices
// closer than `b2_linearSlop`, so distinct points on this grid make triangles it takes, and no
// point moves by more than 3.6 mm.
constexpr double cell_precision = b2_linearSlop;

// The vertices of `polygon`'s rings lying on a side of the cells of side `side` (a coordinate a
// multiple of it), as a multipoint, or nullptr for none. Why: where the outline touches a cell's
// side at a vertex from one side only, that vertex is a vertex of the piece on that side alone
// (a T-junction the rule cannot close) and can leave that piece touching itself.
GEOSGeometry* vertices_on_cell_sides(GEOSContextHandle_t ctx, const GEOSGeometry& polygon,
                                     double side) {
  std::vector<GEOSGeometry*> points;
  const auto add_ring = [&](const GEOSGeometry* ring) {
    const GEOSCoordSequence* seq = GEOSGeom_getCoordSeq_r(ctx, ring);
    unsigned size = 0;
    GEOSCoordSeq_getSize_r(ctx, seq, &size);
    for (unsigned i = 0; i + 1 < size; ++i) {  // a ring repeats its first point last
      double x = 0;
      double y = 0;
      GEOSCoordSeq_getXY_r(ctx, seq, i, &x, &y);
      if (std::fmod(x, side) == 0 || std::fmod(y, side) == 0) {
        points.push_back(GEOSGeom_createPointFromXY_r(ctx, x, y));
      }
    }
  };
  add_ring(GEOSGetExteriorRing_r(ctx, &polygon));
  for (int i = 0; i < GEOSGetNumInteriorRings_r(ctx, &polygon); ++i) {
    add_ring(GEOSGetInteriorRingN_r(ctx, &polygon, i));
  }
  if (points.empty()) return nullptr;
  return GEOSGeom_createCollection_r(ctx, GEOS_MULTIPOINT, points.data(),
                                     static_cast<unsigned>(points.size()));
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
  if (rings.empty()) return refused(OutlineError::NoRings);
  std::vector<std::vector<b2Vec2>> clean;
  for (std::size_t i = 0; i < rings.size(); ++i) {
    clean.push_back(distinct_points(rings[i]));
    const OutlineError e = ring_error(clean.back());
    if (e != OutlineError::None) return refused(e, static_cast<int>(i));
  }

  const Geos geos;
  GEOSContextHandle_t ctx = geos.get();
  const GeometryDeleter destroy{ctx};
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
  const Geometry polygon(
      GEOSGeom_createPolygon_r(ctx, shell, holes.data(), static_cast<unsigned>(holes.size())),
      destroy);
  if (!polygon) return refused(OutlineError::Invalid);

  char* reason = nullptr;
  const char valid = GEOSisValidDetail_r(ctx, polygon.get(), 0, &reason, nullptr);
  if (valid != 1) {
    const OutlineError e = reason ? invalid_reason(reason) : OutlineError::Invalid;
    if (reason) GEOSFree_r(ctx, reason);
    return refused(e);
  }

  Geometry simple(options.simplify > 0
                      ? GEOSTopologyPreserveSimplify_r(ctx, polygon.get(), options.simplify)
                      : GEOSGeom_clone_r(ctx, polygon.get()),
                  destroy);
  if (!simple) return refused(OutlineError::Invalid);

  // The triangulation of each cell's piece (or of the whole polygon): pieces share the points
  // where the outline crosses a cell's side and the cells' corners, computed the same way on both
  // sides, so the triangles meet vertex to vertex.
  std::map<std::pair<float, float>, int> index_of;
  std::vector<b2Vec2> vertices;
  std::vector<int> indices;
  // A piece clipped from a cell may hold lines and points where the outline only touches the
  // cell's side: its polygons alone are triangulated.
  const std::function<bool(const GEOSGeometry&)> triangulate = [&](const GEOSGeometry& piece) {
    const int type = GEOSGeomTypeId_r(ctx, &piece);
    if (type == GEOS_GEOMETRYCOLLECTION) {
      for (int i = 0; i < GEOSGetNumGeometries_r(ctx, &piece); ++i) {
        if (!triangulate(*GEOSGetGeometryN_r(ctx, &piece, i))) return false;
      }
      return true;
    }
    if ((type != GEOS_POLYGON && type != GEOS_MULTIPOLYGON) || GEOSisEmpty_r(ctx, &piece)) {
      return true;
    }
    const Geometry triangles(GEOSConstrainedDelaunayTriangulation_r(ctx, &piece), destroy);
    if (!triangles) return false;
    read_triangles(ctx, *triangles, index_of, vertices, indices);
    return true;
  };
  if (options.cell > 0) {
    double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    if (!GEOSGeom_getExtent_r(ctx, simple.get(), &x0, &y0, &x1, &y1)) {
      return refused(OutlineError::Invalid);
    }
    const double side = options.cell;
    const Geometry on_sides(vertices_on_cell_sides(ctx, *simple, side), destroy);
    // Within this of a piece's edge (metres), a vertex on a cell's side is put into that edge:
    // far below any coordinate's rounding that matters (`b2_linearSlop` is 5e-3 m).
    const double snap = 1e-9 * side;
    for (double x = std::floor(x0 / side) * side; x < x1; x += side) {
      for (double y = std::floor(y0 / side) * side; y < y1; y += side) {
        Geometry piece(GEOSClipByRect_r(ctx, simple.get(), x, y, x + side, y + side), destroy);
        if (piece && on_sides) piece.reset(GEOSSnap_r(ctx, piece.get(), on_sides.get(), snap));
        // A piece touching itself at such a vertex is made valid (GEOS moves no point).
        if (piece && GEOSisValid_r(ctx, piece.get()) != 1) {
          piece.reset(GEOSMakeValid_r(ctx, piece.get()));
        }
        // Where the outline passes within millimetres of a cell's side or corner, the piece has
        // slivers Box2D refuses: its points are rounded to `cell_precision`, the same points the
        // same way in every piece, and what collapses goes.
        if (piece) piece.reset(GEOSGeom_setPrecision_r(ctx, piece.get(), cell_precision, 0));
        if (!piece || !triangulate(*piece)) return refused(OutlineError::Invalid);
      }
    }
  } else if (!triangulate(*simple)) {
    return refused(OutlineError::Invalid);
  }
  OutlineResult r;
  r.vertices = static_cast<int>(vertices.size());
  r.mesh = add_triangles(body, vertices.data(), static_cast<int>(vertices.size()), indices.data(),
                         static_cast<int>(indices.size()), options.fixture);
  if (!r.mesh.ok()) {
    r.error = OutlineError::Triangles;
    r.message = describe(r.error);
    return r;
  }
  r.message = describe(OutlineError::None);
  return r;
}

}  // namespace dyop::box2d
