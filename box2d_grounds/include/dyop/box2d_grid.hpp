#pragma once
/// \file
/// A tile map's cells as Box2D fixtures for the plug-in: the full cells of each chunk merged into
/// few rectangles (`SetAsBox` fixtures), each slope cell (45° and 1:2, floors and ceilings:
/// `TileKind`) a convex fixture of its own, their edge data fixed (`fix_internal_edges`), and a
/// refresh of one chunk when a cell is dug, built or changed. Part of the optional
/// `dyop::box2d_grounds` library (it needs Box2D and the plug-in only).
///
///     dyop::box2d::TileGround ground(*body, {256, 64, 0.5f, b2Vec2(0, 0)});
///     if (ground.set_cells(solid) != dyop::box2d::GridError::None) { /* describe(...) */ }
///     ground.set_cell(10, 63, false);                             // dig: its chunk is built again
///     ground.set_cell(11, 62, dyop::box2d::TileKind::FloorRising);  // a 45° ramp up to the right
///
/// Units and frames: metres, the body's frame; cell (column, row) spans [origin.x + column·cell,
/// + cell] × [origin.y + row·cell, + cell], row 0 at the bottom. In `TileKind`, points of a cell
/// are given in cell units: (0, 0) its lower left corner, (1, 1) its upper right one.

#include <box2d/b2_body.h>
#include <box2d/b2_fixture.h>

#include <cstdint>
#include <vector>

namespace dyop::box2d {

/// Why a grid call was refused; it then changed nothing.
enum class GridError : std::uint8_t {
  None,         ///< done
  WorldLocked,  ///< called during a step (Box2D creates and destroys no fixture then)
  Size,         ///< columns, rows or chunk below 1, or cells not columns × rows long
  CellSize,     ///< cell not finite or below `min_grid_cell` (Box2D would weld the corners)
  TooLarge,     ///< a corner farther than `max_triangle_coordinate` from the body origin
  OutOfRange,   ///< `set_cell` of a cell outside the grid
  /// a slope cell whose triangle or trapezoid Box2D would not take: its corners too close for float
  /// at their distance from the body origin (`make_triangle` refuses a half of it)
  SlopeShape,
};

/// A static, human-readable description of `e`.
const char* describe(GridError e);

/// What fills a cell: nothing, the whole cell, or the part of it on one side of a straight surface.
/// A map's cells are bytes (`set_cells`): 0 is `Empty`, and every value that names no kind below
/// stands for `Solid`, as "nonzero: solid" did before the slopes (`tile_kind`). Floors are solid
/// below their surface, ceilings above it; "rising" surfaces go up from left to right, "falling"
/// ones down. Full cells are merged into rectangles; a slope cell is a convex fixture of its own
/// (a triangle or a trapezoid), joined to the cell beside it where both fill their shared side.
enum class TileKind : std::uint8_t {
  Empty = 0,  ///< nothing
  Solid = 1,  ///< the whole cell
  /// 45° half-tile, solid below the diagonal from (0, 0) to (1, 1): a triangle with its right
  /// angle at (1, 0).
  FloorRising = 2,
  /// 45° half-tile, solid below the diagonal from (0, 1) to (1, 0): right angle at (0, 0).
  FloorFalling = 3,
  /// 45° half-tile hanging from the top, solid above the diagonal from (0, 0) to (1, 1): right
  /// angle at (0, 1).
  CeilingRising = 4,
  /// 45° half-tile hanging from the top, solid above the diagonal from (0, 1) to (1, 0): right
  /// angle at (1, 1).
  CeilingFalling = 5,
  /// 1:2 ramp up to the right over two cells, its left cell: solid below (0, 0)–(1, ½), a
  /// triangle. Its right cell is `GentleFloorRisingHigh`.
  GentleFloorRisingLow = 6,
  /// 1:2 ramp up to the right, its right cell: solid below (0, ½)–(1, 1), a trapezoid.
  GentleFloorRisingHigh = 7,
  /// 1:2 ramp down to the right over two cells, its left cell: solid below (0, 1)–(1, ½), a
  /// trapezoid. Its right cell is `GentleFloorFallingLow`.
  GentleFloorFallingHigh = 8,
  /// 1:2 ramp down to the right, its right cell: solid below (0, ½)–(1, 0), a triangle.
  GentleFloorFallingLow = 9,
  /// 1:2 ceiling rising to the right over two cells, its left cell: solid above (0, 0)–(1, ½), a
  /// trapezoid. Its right cell is `GentleCeilingRisingHigh`.
  GentleCeilingRisingLow = 10,
  /// 1:2 ceiling rising to the right, its right cell: solid above (0, ½)–(1, 1), a triangle.
  GentleCeilingRisingHigh = 11,
  /// 1:2 ceiling falling to the right over two cells, its left cell: solid above (0, 1)–(1, ½), a
  /// triangle. Its right cell is `GentleCeilingFallingLow`.
  GentleCeilingFallingHigh = 12,
  /// 1:2 ceiling falling to the right, its right cell: solid above (0, ½)–(1, 0), a trapezoid.
  GentleCeilingFallingLow = 13,
};

/// The kind a map's byte stands for: itself when it names a `TileKind`, else `Solid` (nonzero)
/// or `Empty` (0).
constexpr TileKind tile_kind(std::uint8_t cell) {
  return cell <= static_cast<std::uint8_t>(TileKind::GentleCeilingFallingLow)
             ? static_cast<TileKind>(cell)
             : TileKind::Solid;
}

/// Where a cell's ground ends: a straight surface across the cell, given by its heights at the
/// cell's left and right sides, the ground below it (a floor) or above it (a ceiling). `Solid` is
/// a floor as high as the cell on both sides, `Empty` one at its bottom.
struct TileSurface {
  int left = 0;          ///< height at the cell's left side, half cells: 0 (bottom) to 2 (top)
  int right = 0;         ///< height at the cell's right side, half cells: 0 to 2
  bool ceiling = false;  ///< true: the ground lies above the surface; false: below it
};

/// The surface of cell kind `k` (a value naming no kind: `Solid`'s).
constexpr TileSurface tile_surface(TileKind k) {
  switch (k) {
    case TileKind::Empty:
      return {0, 0, false};
    case TileKind::Solid:
      break;
    case TileKind::FloorRising:
      return {0, 2, false};
    case TileKind::FloorFalling:
      return {2, 0, false};
    case TileKind::CeilingRising:
      return {0, 2, true};
    case TileKind::CeilingFalling:
      return {2, 0, true};
    case TileKind::GentleFloorRisingLow:
      return {0, 1, false};
    case TileKind::GentleFloorRisingHigh:
      return {1, 2, false};
    case TileKind::GentleFloorFallingHigh:
      return {2, 1, false};
    case TileKind::GentleFloorFallingLow:
      return {1, 0, false};
    case TileKind::GentleCeilingRisingLow:
      return {0, 1, true};
    case TileKind::GentleCeilingRisingHigh:
      return {1, 2, true};
    case TileKind::GentleCeilingFallingHigh:
      return {2, 1, true};
    case TileKind::GentleCeilingFallingLow:
      return {1, 0, true};
  }
  return {2, 2, false};
}

/// Smallest cell side accepted (metres). Why: Box2D 2.4 welds polygon vertices closer than
/// 0.5·b2_linearSlop; twice b2_linearSlop keeps a cell's corners well apart.
inline constexpr float min_grid_cell = 2 * b2_linearSlop;

/// Where the grid lies and how it is cut: its size in cells, the cell side, the lower left corner
/// of cell (0, 0), and the chunk side in cells (a refresh builds one chunk again).
struct GridLayout {
  int columns = 0;      ///< cells along x, ≥ 1
  int rows = 0;         ///< cells along y, ≥ 1
  float cell = 1;       ///< metres, ≥ `min_grid_cell`
  b2Vec2 origin{0, 0};  ///< body frame, metres: the lower left corner of cell (0, 0)
  int chunk = 16;       ///< cells per chunk side, ≥ 1 (default 16: 16 × 16 cells)
};

/// A tile map on one body. Owned by the caller (no state outside it and its body); the fixtures it
/// makes belong to the body, which frees them with itself. Rectangles never cross a chunk's border
/// (the internal-edge rule handles the T-junctions where they meet); a slope's piece belongs to the
/// chunk of its first cell and may reach two cells into the next one. Call it between steps.
class TileGround {
 public:
  /// A ground on `body` laid out as `layout`, its fixtures made like `def` (friction, density,
  /// filter...; `def.shape` is ignored). Nothing is created until `set_cells`.
  TileGround(b2Body& body, const GridLayout& layout, const b2FixtureDef& def = b2FixtureDef());

  /// Sets every cell (`cells[row · columns + column]`: a `TileKind` as `tile_kind` reads it; 0
  /// empty, 1 and any value naming no kind solid) and builds every chunk again. Refused (`Size`,
  /// `CellSize`, `TooLarge`, `WorldLocked`, `SlopeShape`): nothing changes.
  GridError set_cells(const std::vector<std::uint8_t>& cells);

  /// Makes cell (column, row) of kind `kind` and, when its kind changed (`tile_kind` of the byte it
  /// held), builds its chunk again (and the chunk beside it where a piece across their border
  /// changed; edge data refreshed there and next to it). Refused
  /// (`OutOfRange`, `WorldLocked`, `SlopeShape`, or a layout `set_cells` refused): nothing
  /// changes.
  GridError set_cell(int column, int row, TileKind kind);

  /// Digs (`solid` false: `TileKind::Empty`) or fills (`TileKind::Solid`) one cell, as
  /// `set_cell(column, row, kind)` does.
  GridError set_cell(int column, int row, bool solid);

  /// True when cell (column, row) holds ground (any kind but `Empty`); false outside the grid.
  bool solid(int column, int row) const;

  /// The kind of cell (column, row) (`tile_kind` of its byte); `Empty` outside the grid.
  TileKind kind(int column, int row) const;

  /// The fixtures of every chunk, chunk by chunk (row-major from the lower left).
  std::vector<b2Fixture*> fixtures() const;

  /// The layout given.
  const GridLayout& layout() const { return layout_; }

 private:
  GridError check() const;
  int chunk_columns() const;
  int chunk_rows() const;
  // Destroys chunk `k`'s fixtures, merges its full cells outside pieces into rectangles and
  // creates them, and creates a fixture for each piece starting in it.
  void build_chunk(int k);

  b2Body* body_;
  GridLayout layout_;
  b2FixtureDef def_;
  std::vector<std::uint8_t> cells_;
  std::vector<std::vector<b2Fixture*>> chunks_;
};

}  // namespace dyop::box2d
