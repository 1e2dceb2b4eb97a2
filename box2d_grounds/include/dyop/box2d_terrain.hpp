#pragma once
/// \file
/// A level's outline held as a terrain of square chunks, each chunk a static body of triangle
/// fixtures with its edge data fixed across the seams, that edits (a crater, a tunnel, a wall) and
/// streaming (chunks near the camera only) rebuild where they change and nowhere else. Part of the
/// optional `dyop::box2d_outlines` library (GEOS; docs/box2d-plugin.md, "Terrains in chunks").
///
///     dyop::box2d::OutlineTerrain terrain(world);
///     dyop::box2d::TerrainResult r = terrain.set_outline({outline, cave});
///     if (!r.ok()) std::cerr << "ring " << r.ring << ": " << r.message << '\n';
///     terrain.remove(b2Vec2(40, -1), 1.0f);          // a crater 2 m across
///     terrain.load(camera);                           // only the chunks it overlaps have bodies
///
/// Units and frames: metres; every point, polygon and region is in the terrain's frame, the frame
/// of its chunks' bodies (`TerrainOptions::body`: the world frame by default). Chunk (i, j) spans
/// [i·chunk, (i + 1)·chunk] × [j·chunk, (j + 1)·chunk]; within it the triangles are made in cells
/// of `TerrainOptions::cell`, as `add_outline` makes them, every point rounded to `terrain_grid`.

#include <box2d/b2_body.h>
#include <box2d/b2_collision.h>
#include <box2d/b2_fixture.h>
#include <box2d/b2_world.h>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "dyop/box2d_outline.hpp"

namespace dyop::box2d {

/// Why an `OutlineTerrain` call was refused; it then changed nothing.
enum class TerrainError : std::uint8_t {
  None,         ///< done
  WorldLocked,  ///< called during a step (Box2D creates and destroys no fixture then)
  Layout,       ///< `chunk` or `cell` not a positive multiple of `terrain_grid`, `chunk` not a
                ///< multiple of `cell` or above 256 cells, `circle_error` not finite and positive,
                ///< or `simplify` not finite and non-negative
  Rings,        ///< the outline or an edit's polygon was refused: see `TerrainResult::outline`
  Circle,       ///< a circle's centre not finite, or its radius not finite or below `terrain_grid`
  TooLarge,     ///< a coordinate beyond `max_terrain_coordinate`, or over 2^20 chunks spanned
  Region,       ///< a region with a bound not finite, or its lower bound above its upper one
  Triangles,    ///< Box2D would refuse a triangle of the result (see `TerrainResult::triangle`)
};

/// A static, human-readable description of `e`.
const char* describe(TerrainError e);

/// The grid every point of the terrain is rounded to (metres; 1/256 m, 3.9 mm): distinct points
/// of it are farther apart than Box2D welds (2.5 mm), and exact in float within 32 km.
inline constexpr float terrain_grid = 1.0f / 256;

/// Largest coordinate magnitude a terrain accepts (metres, terrain frame). Why: every point of
/// `terrain_grid` up to 2^15 m is exact in float; half that keeps a margin for circles' points.
inline constexpr float max_terrain_coordinate = 16384;

/// How an `OutlineTerrain` is cut and built.
struct TerrainOptions {
  /// Side of a chunk (metres; default 16): a static body each, what loads and unloads.
  float chunk = 16;
  /// Side of the cells triangulated apart within a chunk (metres; default 2, as
  /// `OutlineOptions::cell`): an edit triangulates again the cells it touches, nothing else.
  float cell = 2;
  /// `set_outline` drops the vertices within this distance of the line through their neighbours
  /// (metres; default `b2_linearSlop`, 5 mm, as `OutlineOptions::simplify`); 0 keeps every one.
  float simplify = b2_linearSlop;
  /// Largest gap between a circle given to `remove` or `add` and the polygon cut for it (metres;
  /// default 0.01): its vertex count grows with the radius (23 for a radius of 1 m).
  float circle_error = 0.01f;
  /// The chunks' bodies are made like this (position and angle place the terrain, user data...;
  /// `type` is ignored: static).
  b2BodyDef body;
  /// The triangles' fixtures are made like this (friction, filter, user data...; `shape` is
  /// ignored).
  b2FixtureDef fixture;
};

/// The outcome of an `OutlineTerrain` call, returned by value.
struct TerrainResult {
  TerrainError error = TerrainError::None;  ///< always valid
  /// `error == Rings`: why the rings were refused (as `add_outline` says); `None` otherwise.
  OutlineError outline = OutlineError::None;
  /// `error == Rings`: the ring at fault (0: the outline or the edit's polygon, 1..: the holes);
  /// -1 when none or when the reason concerns several rings.
  int ring = -1;
  /// `error == Triangles`: why Box2D would refuse the triangle (`make_triangle`'s reason).
  ShapeError triangle = ShapeError::None;
  const char* message = "";  ///< static, human-readable: what is wrong, or "done"
  int chunks = 0;            ///< chunks whose ground changed (edits, `set_outline`)
  int created = 0;           ///< triangle fixtures created (in loaded chunks)
  int destroyed = 0;         ///< triangle fixtures destroyed
  int kept = 0;  ///< triangles of the cells triangulated again that were the same before: their
                 ///< fixtures, and the contacts on them, are kept
  bool ok() const { return error == TerrainError::None; }  ///< true when `error == None`
};

/// A level's ground held as chunks of triangles in a world. The outline, edits included, is kept
/// for every chunk; the chunks overlapping the loaded region (all, until `load` or `unload`) have a
/// static body each with their triangle fixtures, edge data fixed within and across chunks
/// (`fix_internal_edges`: static bodies share edges), so bodies glide over the seams. An edit
/// triangulates again the cells it touches; triangles that come out the same keep their fixtures,
/// the others are destroyed and created, and the edge data around them is found again. Bodies
/// touching a destroyed triangle are woken; a `b2ContactListener` sees `EndContact` for their
/// contacts with it during the call, and `BeginContact` with the new triangles in the next step;
/// contacts with kept triangles see nothing. Call between steps; not thread-safe (one GEOS
/// context per terrain). The bodies are the terrain's: move or destroy none of them. Destroy the
/// terrain before its world: its destructor destroys its bodies.
class OutlineTerrain {
 public:
  /// An empty terrain in `world`; nothing is created until `set_outline` or `add`. A layout it
  /// refuses (`TerrainError::Layout`) makes every later call refuse it too.
  explicit OutlineTerrain(b2World& world, const TerrainOptions& options = TerrainOptions());
  ~OutlineTerrain();
  OutlineTerrain(const OutlineTerrain&) = delete;
  OutlineTerrain& operator=(const OutlineTerrain&) = delete;

  /// Replaces the terrain by the polygon `rings` (`rings[0]` the outline, the others its holes;
  /// either winding; checked as `add_outline` checks them, `TerrainError::Rings` with the reason).
  TerrainResult set_outline(const std::vector<std::vector<b2Vec2>>& rings);

  /// Removes the area inside `polygon` (one ring, either winding) from the ground: a tunnel.
  TerrainResult remove(const std::vector<b2Vec2>& polygon);
  /// Removes a disc (a polygon within `TerrainOptions::circle_error` of it): a crater.
  TerrainResult remove(const b2Vec2& centre, float radius);
  /// Adds the area inside `polygon` (one ring, either winding) to the ground: a wall.
  TerrainResult add(const std::vector<b2Vec2>& polygon);
  /// Adds a disc (a polygon within `TerrainOptions::circle_error` of it).
  TerrainResult add(const b2Vec2& centre, float radius);

  /// Makes the chunks overlapping `region` (terrain frame; a camera rectangle with a margin) the
  /// loaded ones: those missing are created, the others' bodies destroyed (their edge data, and
  /// their neighbours', found again). Edits go on at any chunk, loaded or not.
  TerrainResult load(const b2AABB& region);
  /// Loads every chunk (the state after construction).
  TerrainResult load_all();
  /// Unloads every chunk: no body, fixture or proxy is left; the ground is kept.
  TerrainResult unload();

  /// True when `p` (terrain frame) lies in the ground, on its outline included.
  bool solid(const b2Vec2& p) const;
  /// The ground's area (m²), loaded or not.
  double area() const;
  /// Chunks holding ground, loaded or not.
  int chunk_count() const;
  /// Chunks holding ground that have a body now.
  int loaded_chunks() const;
  /// Triangles of the ground, loaded or not.
  int triangle_count() const;
  /// Bytes the terrain holds beside Box2D's bodies and fixtures, estimated: the chunks' pieces of
  /// ground (GEOS: 24 bytes a coordinate, about 100 an object) and their cells' triangle lists.
  std::size_t bytes() const;
  /// The bodies of the loaded chunks.
  std::vector<b2Body*> bodies() const;
  /// The triangle fixtures of the loaded chunks.
  std::vector<b2Fixture*> fixtures() const;
  /// The options given.
  const TerrainOptions& options() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace dyop::box2d
