#pragma once
/// \file
/// A tile map's solid cells as Box2D fixtures for the plug-in: the cells of each chunk merged into
/// few rectangles (`SetAsBox` fixtures), their edge data fixed (`fix_internal_edges`), and a
/// refresh of one chunk when a cell is dug or built. Part of the optional `dyop::box2d_grounds`
/// library (it needs Box2D and the plug-in only).
///
///     dyop::box2d::TileGround ground(*body, {256, 64, 0.5f, b2Vec2(0, 0)});
///     if (ground.set_cells(solid) != dyop::box2d::GridError::None) { /* describe(...) */ }
///     ground.set_cell(10, 63, false);  // dig: its chunk is built again
///
/// Units and frames: metres, the body's frame; cell (column, row) spans [origin.x + column·cell,
/// + cell] × [origin.y + row·cell, + cell], row 0 at the bottom.

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
};

/// A static, human-readable description of `e`.
const char* describe(GridError e);

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
/// (the internal-edge rule handles the T-junctions where they meet). Call it between steps.
class TileGround {
 public:
  /// A ground on `body` laid out as `layout`, its fixtures made like `def` (friction, density,
  /// filter...; `def.shape` is ignored). Nothing is created until `set_cells`.
  TileGround(b2Body& body, const GridLayout& layout, const b2FixtureDef& def = b2FixtureDef());

  /// Sets every cell (`cells[row · columns + column]` nonzero: solid) and builds every chunk again.
  /// Refused (`Size`, `CellSize`, `TooLarge`, `WorldLocked`): nothing changes.
  GridError set_cells(const std::vector<std::uint8_t>& cells);

  /// Digs (`solid` false) or builds one cell, and builds its chunk again (edge data refreshed there
  /// and next to it). Refused (`OutOfRange`, `WorldLocked`, or a layout `set_cells` refused):
  /// nothing changes.
  GridError set_cell(int column, int row, bool solid);

  /// True when cell (column, row) is solid; false outside the grid.
  bool solid(int column, int row) const;

  /// The fixtures of every chunk, chunk by chunk (row-major from the lower left).
  std::vector<b2Fixture*> fixtures() const;

  /// The layout given.
  const GridLayout& layout() const { return layout_; }

 private:
  GridError check() const;
  int chunk_columns() const;
  int chunk_rows() const;
  // Destroys chunk `k`'s fixtures, merges its solid cells into rectangles and creates them.
  void build_chunk(int k);

  b2Body* body_;
  GridLayout layout_;
  b2FixtureDef def_;
  std::vector<std::uint8_t> cells_;
  std::vector<std::vector<b2Fixture*>> chunks_;
};

}  // namespace dyop::box2d
