#include <geos_c.h>

#include <algorithm>
#include <cmath>
#include <cstring>
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

// The triangles of `collection` (GEOS polygons of 3 distinct points each) as a vertex list, each
// point once (the triangulation makes no point of its own: every vertex is an input point), and
// indices.
void read_triangles(GEOSContextHandle_t ctx, const GEOSGeometry& collection,
                    std::vector<b2Vec2>& vertices, std::vector<int>& indices) {
  std::map<std::pair<float, float>, int> index_of;
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
  const Geometry triangles(GEOSConstrainedDelaunayTriangulation_r(ctx, simple.get()), destroy);
  if (!triangles) return refused(OutlineError::Invalid);

  std::vector<b2Vec2> vertices;
  std::vector<int> indices;
  read_triangles(ctx, *triangles, vertices, indices);
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
