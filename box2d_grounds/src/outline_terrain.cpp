#include <box2d/b2_world_callbacks.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <utility>

#include "dyop/box2d.hpp"
#include "dyop/box2d_internal_edges.hpp"
#include "dyop/box2d_mesh.hpp"
#include "dyop/box2d_terrain.hpp"
#include "outline_triangulation.hpp"

// The terrain's own types, named for `OutlineTerrain::State` (a class of the public header).
namespace dyop::box2d::detail::terrain {

// A triangle by its three points in ascending (x, y) order: one key whatever its winding and
// first vertex, so that a cell triangulated again is compared with what it was.
using TriangleKey = std::array<float, 6>;

TriangleKey key_of(const b2Vec2& a, const b2Vec2& b, const b2Vec2& c) {
  std::array<b2Vec2, 3> p = {a, b, c};
  std::sort(p.begin(), p.end(), [](const b2Vec2& u, const b2Vec2& v) {
    return u.x < v.x || (u.x == v.x && u.y < v.y);
  });
  return {p[0].x, p[0].y, p[1].x, p[1].y, p[2].x, p[2].y};
}

b2Vec2 point(const TriangleKey& k, int i) { return b2Vec2(k[2 * i], k[2 * i + 1]); }

// One cell's triangles in ascending key order and, in a loaded chunk, their fixtures in the same
// order.
struct Cell {
  std::vector<TriangleKey> triangles;
  std::vector<b2Fixture*> fixtures;
};

using ChunkIndex = std::pair<int, int>;

// A chunk holding ground: its piece of the ground (within its square, on `terrain_grid`), its
// cells' triangles, and its body while loaded.
struct Chunk {
  Geometry piece;
  std::vector<Cell> cells;
  b2Body* body = nullptr;
};

// What a call changes in one chunk, computed before anything changes: its new piece (null: its
// ground is gone) and the new triangles of the cells triangulated again.
struct Change {
  Geometry piece;
  std::vector<int> cells;
  std::vector<std::vector<TriangleKey>> triangles;  // per entry of `cells`
};

// A box in the terrain's frame, accumulated.
struct Box {
  double x0 = HUGE_VAL, y0 = HUGE_VAL, x1 = -HUGE_VAL, y1 = -HUGE_VAL;
  bool empty() const { return x0 > x1; }
  void add(double x, double y) {
    x0 = std::min(x0, x);
    y0 = std::min(y0, y);
    x1 = std::max(x1, x);
    y1 = std::max(y1, y);
  }
  void add(const Box& b) {
    if (b.empty()) return;
    add(b.x0, b.y0);
    add(b.x1, b.y1);
  }
};

Box box_of(const TriangleKey& k) {
  Box b;
  for (int i = 0; i < 3; ++i) b.add(k[2 * i], k[2 * i + 1]);
  return b;
}

}  // namespace dyop::box2d::detail::terrain

namespace dyop::box2d {
namespace {

using detail::Geometry;
using detail::GeometryDeleter;
using detail::terrain::Box;
using detail::terrain::box_of;
using detail::terrain::Cell;
using detail::terrain::Change;
using detail::terrain::Chunk;
using detail::terrain::ChunkIndex;
using detail::terrain::key_of;
using detail::terrain::point;
using detail::terrain::TriangleKey;

// Most cells a chunk's side may hold: a chunk holds their triangle lists even when empty.
constexpr int max_cells_per_side = 256;

// Most chunks one call may span (the outline's or an edit's extent): what a coordinate within
// `max_terrain_coordinate` and a sensible chunk make; beyond it, the call is refused as too large
// rather than let a tiny chunk side allocate millions of them.
constexpr double max_chunks_spanned = 1 << 20;

// Wakes the non-static bodies whose fixtures' broad-phase boxes overlap a region: a sleeping body
// is not collided, so one that new triangles overlap (a wall built over it) would sleep on inside
// them. (Those touching a destroyed triangle are woken by Box2D, as any touching contact that
// ends.)
class Waker : public b2QueryCallback {
 public:
  bool ReportFixture(b2Fixture* f) override {
    if (f->GetBody()->GetType() != b2_staticBody) f->GetBody()->SetAwake(true);
    return true;
  }
};

TerrainResult result(TerrainError e) {
  TerrainResult r;
  r.error = e;
  r.message = describe(e);
  return r;
}

bool finite(const b2Vec2& p) { return std::isfinite(p.x) && std::isfinite(p.y); }

bool within_limits(const b2Vec2& p) {
  return std::abs(p.x) <= max_terrain_coordinate && std::abs(p.y) <= max_terrain_coordinate;
}

// A multiple of `terrain_grid` (exact: the grid is a power of two).
bool on_grid(float v) { return std::isfinite(v) && v > 0 && std::fmod(double(v) * 256, 1.0) == 0; }

}  // namespace

const char* describe(TerrainError e) {
  switch (e) {
    case TerrainError::None:
      return "done";
    case TerrainError::WorldLocked:
      return "the world is stepping: change the terrain between steps";
    case TerrainError::Layout:
      return "chunk or cell not a positive multiple of terrain_grid, chunk not a multiple of cell, "
             "or circle_error not positive";
    case TerrainError::Rings:
      return "the rings were refused (see outline)";
    case TerrainError::Circle:
      return "a circle's centre is not finite or its radius not finite or below terrain_grid";
    case TerrainError::TooLarge:
      return "a coordinate beyond max_terrain_coordinate, or too many chunks spanned";
    case TerrainError::Region:
      return "a region bound is not finite or its lower bound is above its upper one";
    case TerrainError::Triangles:
      return "Box2D would refuse a triangle of the result (see triangle)";
  }
  return "unknown terrain error";
}

struct OutlineTerrain::State {
  State(b2World& w, const TerrainOptions& o) : world(&w), options(o) {
    options.body.type = b2_staticBody;
    const bool sizes = on_grid(o.chunk) && on_grid(o.cell) && std::fmod(o.chunk, o.cell) == 0 &&
                       o.chunk / o.cell <= max_cells_per_side;
    const bool others = std::isfinite(o.circle_error) && o.circle_error > 0 &&
                        std::isfinite(o.simplify) && o.simplify >= 0;
    layout = sizes && others ? TerrainError::None : TerrainError::Layout;
    per_side = sizes ? static_cast<int>(o.chunk / o.cell) : 0;
  }

  enum class Loaded { All, Region, None };

  b2World* world;
  TerrainOptions options;
  TerrainError layout;
  int per_side;  // cells along a chunk's side
  detail::Geos geos;
  std::map<ChunkIndex, Chunk> chunks;
  Loaded loaded = Loaded::All;
  b2AABB region{};

  GEOSContextHandle_t ctx() const { return geos.get(); }
  Geometry own(GEOSGeometry* g) const { return Geometry(g, GeometryDeleter{ctx()}); }

  // The lower left corner of chunk `c`, or of its cell `k`.
  double x_of(const ChunkIndex& c, int k = 0) const {
    return c.first * double(options.chunk) + (k % per_side) * double(options.cell);
  }
  double y_of(const ChunkIndex& c, int k = 0) const {
    return c.second * double(options.chunk) + (k / per_side) * double(options.cell);
  }

  bool wanted(const ChunkIndex& c) const {
    if (loaded != Loaded::Region) return loaded == Loaded::All;
    const double x = x_of(c), y = y_of(c), side = options.chunk;
    return x <= region.upperBound.x && x + side >= region.lowerBound.x &&
           y <= region.upperBound.y && y + side >= region.lowerBound.y;
  }

  // The chunks whose squares overlap `b`, or false when they would be too many.
  bool chunk_range(const Box& b, int& i0, int& j0, int& i1, int& j1) const {
    const double side = options.chunk;
    const double span = (std::floor(b.x1 / side) - std::floor(b.x0 / side) + 1) *
                        (std::floor(b.y1 / side) - std::floor(b.y0 / side) + 1);
    if (!(span <= max_chunks_spanned)) return false;
    i0 = static_cast<int>(std::floor(b.x0 / side));
    j0 = static_cast<int>(std::floor(b.y0 / side));
    i1 = static_cast<int>(std::floor(b.x1 / side));
    j1 = static_cast<int>(std::floor(b.y1 / side));
    return true;
  }

  // The cells of chunk `c` overlapping `b` grown by two grid steps (snap rounding moves nothing
  // farther than a grid step).
  std::vector<int> cells_overlapping(const ChunkIndex& c, const Box& b) const {
    const double cell = options.cell, margin = 2.0 * terrain_grid;
    const auto clamp = [&](double v) {
      return std::clamp(static_cast<int>(std::floor(v / cell)), 0, per_side - 1);
    };
    const int cx0 = clamp(b.x0 - margin - x_of(c)), cx1 = clamp(b.x1 + margin - x_of(c));
    const int cy0 = clamp(b.y0 - margin - y_of(c)), cy1 = clamp(b.y1 + margin - y_of(c));
    std::vector<int> out;
    for (int cy = cy0; cy <= cy1; ++cy) {
      for (int cx = cx0; cx <= cx1; ++cx) out.push_back(cy * per_side + cx);
    }
    return out;
  }

  std::vector<int> all_cells() const {
    std::vector<int> out(static_cast<std::size_t>(per_side * per_side));
    for (int k = 0; k < per_side * per_side; ++k) out[static_cast<std::size_t>(k)] = k;
    return out;
  }

  // The polygons of `g` alone (a clip or an intersection may add lines and points where areas only
  // touch), rounded to the grid; an empty geometry when none.
  Geometry polygonal_on_grid(const GEOSGeometry& g) const {
    std::vector<GEOSGeometry*> parts;
    const std::function<void(const GEOSGeometry&)> collect = [&](const GEOSGeometry& x) {
      const int type = GEOSGeomTypeId_r(ctx(), &x);
      if (type == GEOS_POLYGON && !GEOSisEmpty_r(ctx(), &x)) {
        parts.push_back(GEOSGeom_clone_r(ctx(), &x));
      } else if (type == GEOS_MULTIPOLYGON || type == GEOS_GEOMETRYCOLLECTION) {
        for (int i = 0; i < GEOSGetNumGeometries_r(ctx(), &x); ++i) {
          collect(*GEOSGetGeometryN_r(ctx(), &x, i));
        }
      }
    };
    collect(g);
    const Geometry all = own(GEOSGeom_createCollection_r(ctx(), GEOS_MULTIPOLYGON, parts.data(),
                                                         static_cast<unsigned>(parts.size())));
    if (!all) return nullptr;
    return own(GEOSGeom_setPrecision_r(ctx(), all.get(), detail::cell_grid, 0));
  }

  // GEOS failed on the polygon given (an overlay it could not compute).
  static TerrainResult geos_failed() {
    TerrainResult r = result(TerrainError::Rings);
    r.outline = OutlineError::Invalid;
    return r;
  }

  // The piece of chunk `c` after the call: its change's, else its own (nullptr: no ground).
  const GEOSGeometry* piece_after(const std::map<ChunkIndex, Change>& changes,
                                  const ChunkIndex& c) const {
    if (const auto it = changes.find(c); it != changes.end()) return it->second.piece.get();
    const auto it = chunks.find(c);
    return it == chunks.end() ? nullptr : it->second.piece.get();
  }

  // Triangulates the cells of every change (the pieces around each already final); a triangle
  // Box2D would refuse refuses the call.
  TerrainResult triangulate(std::map<ChunkIndex, Change>& changes) const {
    for (auto& [c, change] : changes) {
      if (!change.piece) continue;
      std::vector<detail::Point> on_sides;
      for (int di = -1; di <= 1; ++di) {
        for (int dj = -1; dj <= 1; ++dj) {
          const GEOSGeometry* g = piece_after(changes, {c.first + di, c.second + dj});
          if (g) detail::add_points_on_cell_sides(ctx(), *g, options.cell, on_sides);
        }
      }
      change.triangles.clear();
      for (const int k : change.cells) {
        detail::Triangulation t;
        if (!detail::triangulate_cell(ctx(), *change.piece, on_sides, x_of(c, k), y_of(c, k),
                                      options.cell, t)) {
          return geos_failed();
        }
        std::vector<TriangleKey> keys;
        for (std::size_t i = 0; i + 2 < t.indices.size(); i += 3) {
          const b2Vec2& a = t.vertices[static_cast<std::size_t>(t.indices[i])];
          const b2Vec2& b = t.vertices[static_cast<std::size_t>(t.indices[i + 1])];
          const b2Vec2& d = t.vertices[static_cast<std::size_t>(t.indices[i + 2])];
          const TriangleShape shape = make_triangle(a, b, d);
          if (!shape.ok()) {
            TerrainResult r = result(TerrainError::Triangles);
            r.triangle = shape.error;
            return r;
          }
          keys.push_back(key_of(a, b, d));
        }
        std::sort(keys.begin(), keys.end());
        keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
        change.triangles.push_back(std::move(keys));
      }
    }
    return result(TerrainError::None);
  }

  b2Transform frame() const {
    return b2Transform(options.body.position, b2Rot(options.body.angle));
  }

  // `b` (terrain frame) grown by `b2_linearSlop`, placed in the world.
  b2AABB world_box(const Box& b) const {
    const double m = b2_linearSlop;
    const b2Transform xf = frame();
    b2AABB out;
    out.lowerBound = out.upperBound =
        b2Mul(xf, b2Vec2(static_cast<float>(b.x0 - m), static_cast<float>(b.y0 - m)));
    for (const b2Vec2 corner :
         {b2Vec2(static_cast<float>(b.x1 + m), static_cast<float>(b.y0 - m)),
          b2Vec2(static_cast<float>(b.x1 + m), static_cast<float>(b.y1 + m)),
          b2Vec2(static_cast<float>(b.x0 - m), static_cast<float>(b.y1 + m))}) {
      const b2Vec2 p = b2Mul(xf, corner);
      out.lowerBound = b2Min(out.lowerBound, p);
      out.upperBound = b2Max(out.upperBound, p);
    }
    return out;
  }

  // Creates `triangles` on `chunk`'s body (edge data fixed there and next to them) and returns
  // their fixtures, in order.
  std::vector<b2Fixture*> create(Chunk& chunk, const std::vector<TriangleKey>& triangles) const {
    if (triangles.empty()) return {};
    std::vector<b2Vec2> vertices;
    std::vector<int> indices;
    for (const TriangleKey& k : triangles) {
      for (int i = 0; i < 3; ++i) {
        indices.push_back(static_cast<int>(vertices.size()));
        vertices.push_back(point(k, i));
      }
    }
    return add_triangles(*chunk.body, vertices.data(), static_cast<int>(vertices.size()),
                         indices.data(), static_cast<int>(indices.size()), options.fixture)
        .fixtures;
  }

  void load_chunk(Chunk& chunk, TerrainResult& r) {
    chunk.body = world->CreateBody(&options.body);
    std::vector<TriangleKey> all;
    for (const Cell& cell : chunk.cells)
      all.insert(all.end(), cell.triangles.begin(), cell.triangles.end());
    const std::vector<b2Fixture*> made = create(chunk, all);
    std::size_t at = 0;
    for (Cell& cell : chunk.cells) {
      cell.fixtures.assign(made.begin() + static_cast<std::ptrdiff_t>(at),
                           made.begin() + static_cast<std::ptrdiff_t>(at + cell.triangles.size()));
      at += cell.triangles.size();
    }
    r.created += static_cast<int>(made.size());
  }

  // Chunk `c`'s square.
  Box square(const ChunkIndex& c) const {
    Box b;
    b.add(x_of(c), y_of(c));
    b.add(x_of(c) + options.chunk, y_of(c) + options.chunk);
    return b;
  }

  // Destroys `chunk`'s body; returns the box its ground spanned.
  Box unload_chunk(const ChunkIndex& c, Chunk& chunk, TerrainResult& r) {
    const Box b = square(c);
    for (Cell& cell : chunk.cells) {
      r.destroyed += static_cast<int>(cell.fixtures.size());
      cell.fixtures.clear();
    }
    world->DestroyBody(chunk.body);
    chunk.body = nullptr;
    return b;
  }

  // After fixtures were destroyed over `gone` and created over `made`: the edge data of the fixed
  // polygons around `gone` found again (edges along it may have become outline; around `made`,
  // `add_triangles` found it), and the bodies over `made` woken.
  void settle(const Box& gone, const Box& made) const {
    if (!gone.empty()) refresh_internal_edges(*world, world_box(gone));
    if (made.empty()) return;
    Waker waker;
    world->QueryAABB(&waker, world_box(made));
  }

  // Applies `changes` (triangulated): pieces replaced, changed triangles destroyed and created in
  // loaded chunks (those that came out the same kept), chunks left without ground erased and new
  // ones loaded when wanted.
  TerrainResult commit(std::map<ChunkIndex, Change>& changes) {
    TerrainResult r = result(TerrainError::None);
    Box gone, made;
    std::vector<std::pair<Chunk*, std::vector<std::pair<int, TriangleKey>>>> to_create;
    std::vector<std::pair<ChunkIndex, Chunk*>> to_load;
    for (auto& [c, change] : changes) {
      auto it = chunks.find(c);
      if (change.piece || it != chunks.end()) ++r.chunks;
      if (!change.piece) {
        if (it == chunks.end()) continue;
        if (it->second.body) gone.add(unload_chunk(c, it->second, r));
        chunks.erase(it);
        continue;
      }
      if (it == chunks.end()) {
        it = chunks.emplace(c, Chunk{}).first;
        it->second.cells.resize(static_cast<std::size_t>(per_side * per_side));
        if (wanted(c)) to_load.emplace_back(c, &it->second);
      }
      Chunk& chunk = it->second;
      chunk.piece = std::move(change.piece);
      std::vector<std::pair<int, TriangleKey>> created;
      for (std::size_t n = 0; n < change.cells.size(); ++n) {
        Cell& cell = chunk.cells[static_cast<std::size_t>(change.cells[n])];
        std::vector<TriangleKey>& now = change.triangles[n];
        if (!chunk.body) {
          cell.triangles = std::move(now);
          continue;
        }
        // A merge of the two sorted lists: the same triangle keeps its fixture.
        std::vector<b2Fixture*> fixtures;
        std::size_t i = 0;
        for (const TriangleKey& k : now) {
          while (i < cell.triangles.size() && cell.triangles[i] < k) {
            gone.add(box_of(cell.triangles[i]));
            chunk.body->DestroyFixture(cell.fixtures[i++]);
            ++r.destroyed;
          }
          if (i < cell.triangles.size() && cell.triangles[i] == k) {
            fixtures.push_back(cell.fixtures[i++]);
            ++r.kept;
          } else {
            fixtures.push_back(nullptr);
            created.emplace_back(change.cells[n], k);
            made.add(box_of(k));
          }
        }
        for (; i < cell.triangles.size(); ++i) {
          gone.add(box_of(cell.triangles[i]));
          chunk.body->DestroyFixture(cell.fixtures[i]);
          ++r.destroyed;
        }
        cell.triangles = std::move(now);
        cell.fixtures = std::move(fixtures);
      }
      if (!created.empty()) to_create.emplace_back(&chunk, std::move(created));
    }
    // Created once every destroyed triangle is gone, so that their edge data is found against the
    // ground as it now is.
    for (auto& [chunk, created] : to_create) {
      std::vector<TriangleKey> keys;
      for (const auto& entry : created) keys.push_back(entry.second);
      const std::vector<b2Fixture*> made = create(*chunk, keys);
      r.created += static_cast<int>(made.size());
      for (std::size_t n = 0; n < created.size(); ++n) {
        Cell& cell = chunk->cells[static_cast<std::size_t>(created[n].first)];
        const auto at =
            std::lower_bound(cell.triangles.begin(), cell.triangles.end(), created[n].second);
        cell.fixtures[static_cast<std::size_t>(at - cell.triangles.begin())] = made[n];
      }
    }
    for (auto& [c, chunk] : to_load) {
      load_chunk(*chunk, r);
      made.add(square(c));
    }
    settle(gone, made);
    return r;
  }

  // Loads the chunks `mode` (and `r`) say, and unloads the others.
  TerrainResult load(Loaded mode, const b2AABB& r = b2AABB()) {
    if (layout != TerrainError::None) return result(layout);
    if (world->IsLocked()) return result(TerrainError::WorldLocked);
    loaded = mode;
    region = r;
    return sync();
  }

  // The loaded chunks made those `wanted`.
  TerrainResult sync() {
    TerrainResult r = result(TerrainError::None);
    Box gone, made;
    for (auto& [c, chunk] : chunks) {
      if (chunk.body && !wanted(c)) gone.add(unload_chunk(c, chunk, r));
    }
    for (auto& [c, chunk] : chunks) {
      if (!chunk.body && wanted(c)) {
        load_chunk(chunk, r);
        made.add(square(c));
      }
    }
    settle(gone, made);
    return r;
  }

  // The checks every edit and `set_outline` make of their rings; the polygon when accepted.
  TerrainResult checked(const std::vector<std::vector<b2Vec2>>& rings, Geometry& polygon) const {
    if (layout != TerrainError::None) return result(layout);
    if (world->IsLocked()) return result(TerrainError::WorldLocked);
    detail::CheckedPolygon p = detail::checked_polygon(ctx(), rings);
    if (p.error != OutlineError::None) {
      TerrainResult r = result(TerrainError::Rings);
      r.outline = p.error;
      r.ring = p.ring;
      return r;
    }
    for (const auto& ring : rings) {
      for (const b2Vec2& v : ring) {
        if (!within_limits(v)) return result(TerrainError::TooLarge);
      }
    }
    polygon = std::move(p.polygon);
    return result(TerrainError::None);
  }

  // The extent of `g`.
  Box extent(const GEOSGeometry& g) const {
    Box b;
    if (!GEOSisEmpty_r(ctx(), &g)) GEOSGeom_getExtent_r(ctx(), &g, &b.x0, &b.y0, &b.x1, &b.y1);
    return b;
  }

  // Triangulates and applies `changes`, or refuses them with nothing changed.
  TerrainResult apply(std::map<ChunkIndex, Change>& changes) {
    const TerrainResult t = triangulate(changes);
    if (!t.ok()) return t;
    return commit(changes);
  }

  // Removes (`add` false) or adds `polygon` (checked).
  TerrainResult edit(const GEOSGeometry& polygon, bool add) {
    const Box b = extent(polygon);
    int i0 = 0, j0 = 0, i1 = 0, j1 = 0;
    if (!chunk_range(b, i0, j0, i1, j1)) return result(TerrainError::TooLarge);
    std::map<ChunkIndex, Change> changes;
    for (int i = i0; i <= i1; ++i) {
      for (int j = j0; j <= j1; ++j) {
        const ChunkIndex c{i, j};
        const auto it = chunks.find(c);
        const GEOSGeometry* piece = it == chunks.end() ? nullptr : it->second.piece.get();
        Geometry after;
        if (!add) {
          if (!piece || !GEOSIntersects_r(ctx(), piece, &polygon)) continue;
          after = own(GEOSDifferencePrec_r(ctx(), piece, &polygon, detail::cell_grid));
        } else {
          const Geometry clipped = own(GEOSClipByRect_r(
              ctx(), &polygon, x_of(c), y_of(c), x_of(c) + options.chunk, y_of(c) + options.chunk));
          if (!clipped) return geos_failed();
          Geometry part = polygonal_on_grid(*clipped);
          if (!part) return geos_failed();
          if (GEOSisEmpty_r(ctx(), part.get())) continue;
          after = piece ? own(GEOSUnionPrec_r(ctx(), piece, part.get(), detail::cell_grid))
                        : std::move(part);
        }
        if (!after) return geos_failed();
        Change change;
        const bool existed = piece != nullptr;
        if (!GEOSisEmpty_r(ctx(), after.get())) change.piece = std::move(after);
        change.cells = existed ? cells_overlapping(c, b) : all_cells();
        changes.emplace(c, std::move(change));
      }
    }
    return apply(changes);
  }

  // A polygon within `circle_error` of the circle, inside it.
  std::vector<b2Vec2> circle(const b2Vec2& centre, float radius) const {
    const double e = std::min(double(options.circle_error), 0.5 * radius);
    const double half_angle = std::acos(1 - e / radius);
    const int n = std::clamp(static_cast<int>(std::ceil(b2_pi / half_angle)), 8, 1024);
    std::vector<b2Vec2> ring;
    for (int i = 0; i < n; ++i) {
      const double a = 2 * b2_pi * i / n;
      ring.emplace_back(static_cast<float>(centre.x + radius * std::cos(a)),
                        static_cast<float>(centre.y + radius * std::sin(a)));
    }
    return ring;
  }

  TerrainResult circle_edit(const b2Vec2& centre, float radius, bool add) {
    if (layout != TerrainError::None) return result(layout);
    if (!finite(centre) || !std::isfinite(radius) || !(radius >= terrain_grid)) {
      return result(TerrainError::Circle);
    }
    if (!within_limits(centre + b2Vec2(radius, radius)) ||
        !within_limits(centre - b2Vec2(radius, radius))) {
      return result(TerrainError::TooLarge);
    }
    Geometry polygon;
    const TerrainResult r = checked({circle(centre, radius)}, polygon);
    return r.ok() ? edit(*polygon, add) : r;
  }
};

OutlineTerrain::OutlineTerrain(b2World& world, const TerrainOptions& options)
    : state_(std::make_unique<State>(world, options)) {}

OutlineTerrain::~OutlineTerrain() {
  if (state_->world->IsLocked()) return;
  for (auto& entry : state_->chunks) {
    if (entry.second.body) state_->world->DestroyBody(entry.second.body);
  }
}

TerrainResult OutlineTerrain::set_outline(const std::vector<std::vector<b2Vec2>>& rings) {
  State& s = *state_;
  Geometry polygon;
  if (const TerrainResult r = s.checked(rings, polygon); !r.ok()) return r;
  const Geometry simple = detail::simplified(s.ctx(), *polygon, s.options.simplify);
  int i0 = 0, j0 = 0, i1 = 0, j1 = 0;
  if (!simple || !s.chunk_range(s.extent(*simple), i0, j0, i1, j1)) {
    return result(TerrainError::TooLarge);
  }
  // Every chunk starts afresh: the old ones are gone unless the outline has ground there.
  std::map<ChunkIndex, Change> changes;
  for (const auto& entry : s.chunks) changes.emplace(entry.first, Change{});
  for (int i = i0; i <= i1; ++i) {
    for (int j = j0; j <= j1; ++j) {
      const ChunkIndex c{i, j};
      const Geometry clipped =
          s.own(GEOSClipByRect_r(s.ctx(), simple.get(), s.x_of(c), s.y_of(c),
                                 s.x_of(c) + s.options.chunk, s.y_of(c) + s.options.chunk));
      Geometry piece = clipped ? s.polygonal_on_grid(*clipped) : nullptr;
      if (!piece) return s.geos_failed();
      if (!GEOSisEmpty_r(s.ctx(), piece.get())) changes[c].piece = std::move(piece);
    }
  }
  for (auto& entry : changes) entry.second.cells = s.all_cells();
  const TerrainResult t = s.triangulate(changes);
  if (!t.ok()) return t;
  TerrainResult gone = result(TerrainError::None);
  Box box;
  for (auto& [c, chunk] : s.chunks) {
    if (chunk.body) box.add(s.unload_chunk(c, chunk, gone));
  }
  s.chunks.clear();
  TerrainResult r = s.commit(changes);
  r.destroyed += gone.destroyed;
  s.settle(box, Box());
  return r;
}

TerrainResult OutlineTerrain::remove(const std::vector<b2Vec2>& polygon) {
  Geometry g;
  const TerrainResult r = state_->checked({polygon}, g);
  return r.ok() ? state_->edit(*g, false) : r;
}

TerrainResult OutlineTerrain::remove(const b2Vec2& centre, float radius) {
  return state_->circle_edit(centre, radius, false);
}

TerrainResult OutlineTerrain::add(const std::vector<b2Vec2>& polygon) {
  Geometry g;
  const TerrainResult r = state_->checked({polygon}, g);
  return r.ok() ? state_->edit(*g, true) : r;
}

TerrainResult OutlineTerrain::add(const b2Vec2& centre, float radius) {
  return state_->circle_edit(centre, radius, true);
}

TerrainResult OutlineTerrain::load(const b2AABB& region) {
  if (!finite(region.lowerBound) || !finite(region.upperBound) ||
      region.lowerBound.x > region.upperBound.x || region.lowerBound.y > region.upperBound.y) {
    return state_->layout != TerrainError::None ? result(state_->layout)
                                                : result(TerrainError::Region);
  }
  return state_->load(State::Loaded::Region, region);
}

TerrainResult OutlineTerrain::load_all() { return state_->load(State::Loaded::All); }

TerrainResult OutlineTerrain::unload() { return state_->load(State::Loaded::None); }

bool OutlineTerrain::solid(const b2Vec2& p) const {
  const State& s = *state_;
  if (!finite(p) || s.layout != TerrainError::None) return false;
  Box b;
  b.add(p.x, p.y);
  int i0 = 0, j0 = 0, i1 = 0, j1 = 0;
  if (!s.chunk_range(b, i0, j0, i1, j1)) return false;
  const Geometry at = s.own(GEOSGeom_createPointFromXY_r(s.ctx(), p.x, p.y));
  // A point on a chunk's side lies in the chunks on both sides.
  for (int i = i0 - 1; i <= i1; ++i) {
    for (int j = j0 - 1; j <= j1; ++j) {
      const auto it = s.chunks.find({i, j});
      if (it != s.chunks.end() &&
          GEOSIntersects_r(s.ctx(), it->second.piece.get(), at.get()) == 1) {
        return true;
      }
    }
  }
  return false;
}

double OutlineTerrain::area() const {
  double sum = 0;
  for (const auto& entry : state_->chunks) {
    double a = 0;
    if (GEOSArea_r(state_->ctx(), entry.second.piece.get(), &a)) sum += a;
  }
  return sum;
}

int OutlineTerrain::chunk_count() const { return static_cast<int>(state_->chunks.size()); }

int OutlineTerrain::loaded_chunks() const {
  int n = 0;
  for (const auto& entry : state_->chunks) n += entry.second.body != nullptr;
  return n;
}

int OutlineTerrain::triangle_count() const {
  std::size_t n = 0;
  for (const auto& entry : state_->chunks) {
    for (const Cell& cell : entry.second.cells) n += cell.triangles.size();
  }
  return static_cast<int>(n);
}

std::size_t OutlineTerrain::bytes() const {
  // An estimate of what GEOS 3.11 allocates: a coordinate holds x, y and z in double; a polygon,
  // its rings and their sequences are objects of about 100 bytes each.
  constexpr std::size_t per_coordinate = 24;
  constexpr std::size_t per_geometry = 100;
  std::size_t n = 0;
  for (const auto& entry : state_->chunks) {
    const Chunk& chunk = entry.second;
    const int coordinates = GEOSGetNumCoordinates_r(state_->ctx(), chunk.piece.get());
    const int parts = GEOSGetNumGeometries_r(state_->ctx(), chunk.piece.get());
    n += sizeof(Chunk) + per_coordinate * static_cast<std::size_t>(std::max(coordinates, 0)) +
         per_geometry * static_cast<std::size_t>(std::max(parts, 0) + 1);
    for (const Cell& cell : chunk.cells) {
      n += sizeof(Cell) + cell.triangles.capacity() * sizeof(TriangleKey) +
           cell.fixtures.capacity() * sizeof(b2Fixture*);
    }
  }
  return n;
}

std::vector<b2Body*> OutlineTerrain::bodies() const {
  std::vector<b2Body*> out;
  for (const auto& entry : state_->chunks) {
    if (entry.second.body) out.push_back(entry.second.body);
  }
  return out;
}

std::vector<b2Fixture*> OutlineTerrain::fixtures() const {
  std::vector<b2Fixture*> out;
  for (const auto& entry : state_->chunks) {
    for (const Cell& cell : entry.second.cells) {
      out.insert(out.end(), cell.fixtures.begin(), cell.fixtures.end());
    }
  }
  return out;
}

const TerrainOptions& OutlineTerrain::options() const { return state_->options; }

}  // namespace dyop::box2d
