#include <box2d/b2_polygon_shape.h>
#include <box2d/b2_world.h>

#include <algorithm>
#include <cmath>

#include "dyop/box2d.hpp"
#include "dyop/box2d_grid.hpp"
#include "dyop/box2d_internal_edges.hpp"

namespace dyop::box2d {
namespace {

// A run of solid cells merged into one rectangle: columns [c0, c1), rows [r0, r1).
struct Rectangle {
  int c0, c1, r0, r1;
};

// The solid cells of the window [c0, c1) × [r0, r1) of a grid `columns` wide, merged greedily:
// each row's maximal runs not yet covered, each grown upward while the rows above hold the same
// run solid and uncovered. Every solid cell lies in exactly one rectangle.
std::vector<Rectangle> merge(const std::vector<std::uint8_t>& cells, int columns, int c0, int c1,
                             int r0, int r1) {
  const int w = c1 - c0;
  std::vector<std::uint8_t> covered(static_cast<std::size_t>(w * (r1 - r0)), 0);
  const auto solid = [&](int c, int r) {
    return cells[static_cast<std::size_t>(r * columns + c)] != 0 &&
           covered[static_cast<std::size_t>((r - r0) * w + (c - c0))] == 0;
  };
  std::vector<Rectangle> out;
  for (int r = r0; r < r1; ++r) {
    for (int c = c0; c < c1;) {
      if (!solid(c, r)) {
        ++c;
        continue;
      }
      int end = c;
      while (end < c1 && solid(end, r)) ++end;
      int top = r + 1;
      while (top < r1) {
        bool whole = true;
        for (int k = c; k < end && whole; ++k) whole = solid(k, top);
        if (!whole) break;
        ++top;
      }
      for (int rr = r; rr < top; ++rr) {
        for (int k = c; k < end; ++k)
          covered[static_cast<std::size_t>((rr - r0) * w + (k - c0))] = 1;
      }
      out.push_back({c, end, r, top});
      c = end;
    }
  }
  return out;
}

}  // namespace

const char* describe(GridError e) {
  switch (e) {
    case GridError::None:
      return "done";
    case GridError::WorldLocked:
      return "the world is stepping: change the grid between steps";
    case GridError::Size:
      return "columns, rows or chunk below 1, or the cells are not columns x rows long";
    case GridError::CellSize:
      return "the cell side is not finite or below min_grid_cell (Box2D would weld its corners)";
    case GridError::TooLarge:
      return "a corner of the grid lies beyond max_triangle_coordinate from the body origin";
    case GridError::OutOfRange:
      return "a cell outside the grid";
  }
  return "unknown grid error";
}

TileGround::TileGround(b2Body& body, const GridLayout& layout, const b2FixtureDef& def)
    : body_(&body), layout_(layout), def_(def) {}

GridError TileGround::check() const {
  const GridLayout& g = layout_;
  if (g.columns < 1 || g.rows < 1 || g.chunk < 1) return GridError::Size;
  if (!std::isfinite(g.cell) || !(g.cell >= min_grid_cell)) return GridError::CellSize;
  const double far_x = std::max(std::abs(double(g.origin.x)),
                                std::abs(double(g.origin.x) + double(g.cell) * g.columns));
  const double far_y = std::max(std::abs(double(g.origin.y)),
                                std::abs(double(g.origin.y) + double(g.cell) * g.rows));
  if (!(std::max(far_x, far_y) <= max_triangle_coordinate)) return GridError::TooLarge;
  if (body_->GetWorld()->IsLocked()) return GridError::WorldLocked;
  return GridError::None;
}

int TileGround::chunk_columns() const {
  return (layout_.columns + layout_.chunk - 1) / layout_.chunk;
}
int TileGround::chunk_rows() const { return (layout_.rows + layout_.chunk - 1) / layout_.chunk; }

GridError TileGround::set_cells(const std::vector<std::uint8_t>& cells) {
  if (const GridError e = check(); e != GridError::None) return e;
  if (cells.size() != static_cast<std::size_t>(layout_.columns) * layout_.rows) {
    return GridError::Size;
  }
  cells_ = cells;
  chunks_.resize(static_cast<std::size_t>(chunk_columns() * chunk_rows()));
  for (int k = 0; k < static_cast<int>(chunks_.size()); ++k) build_chunk(k);
  return GridError::None;
}

GridError TileGround::set_cell(int column, int row, bool solid) {
  if (const GridError e = check(); e != GridError::None) return e;
  if (cells_.empty()) return GridError::Size;  // no `set_cells` yet
  if (column < 0 || row < 0 || column >= layout_.columns || row >= layout_.rows) {
    return GridError::OutOfRange;
  }
  std::uint8_t& cell = cells_[static_cast<std::size_t>(row * layout_.columns + column)];
  if ((cell != 0) == solid) return GridError::None;
  cell = solid ? 1 : 0;
  build_chunk((row / layout_.chunk) * chunk_columns() + column / layout_.chunk);
  return GridError::None;
}

bool TileGround::solid(int column, int row) const {
  if (cells_.empty() || column < 0 || row < 0 || column >= layout_.columns || row >= layout_.rows) {
    return false;
  }
  return cells_[static_cast<std::size_t>(row * layout_.columns + column)] != 0;
}

std::vector<b2Fixture*> TileGround::fixtures() const {
  std::vector<b2Fixture*> out;
  for (const std::vector<b2Fixture*>& chunk : chunks_)
    out.insert(out.end(), chunk.begin(), chunk.end());
  return out;
}

void TileGround::build_chunk(int k) {
  std::vector<b2Fixture*>& fixtures = chunks_[static_cast<std::size_t>(k)];
  for (b2Fixture* f : fixtures) body_->DestroyFixture(f);
  fixtures.clear();
  const GridLayout& g = layout_;
  const int c0 = (k % chunk_columns()) * g.chunk;
  const int r0 = (k / chunk_columns()) * g.chunk;
  const int c1 = std::min(c0 + g.chunk, g.columns);
  const int r1 = std::min(r0 + g.chunk, g.rows);
  b2FixtureDef def = def_;
  for (const Rectangle& r : merge(cells_, g.columns, c0, c1, r0, r1)) {
    const float hx = 0.5f * g.cell * static_cast<float>(r.c1 - r.c0);
    const float hy = 0.5f * g.cell * static_cast<float>(r.r1 - r.r0);
    const b2Vec2 center(g.origin.x + g.cell * static_cast<float>(r.c0) + hx,
                        g.origin.y + g.cell * static_cast<float>(r.r0) + hy);
    b2PolygonShape box;
    box.SetAsBox(hx, hy, center, 0);
    def.shape = &box;
    fixtures.push_back(body_->CreateFixture(&def));
  }
  // The new rectangles' edge data, and again that of the fixed neighbours around the chunk
  // (a chunk dug empty creates nothing, yet its neighbours' edges along it became outline).
  b2World& world = *body_->GetWorld();
  fix_internal_edges(world, fixtures);
  // The chunk grown by a cell, its four corners placed in the world (the body may be turned).
  const float x0 = g.origin.x + g.cell * static_cast<float>(c0 - 1);
  const float y0 = g.origin.y + g.cell * static_cast<float>(r0 - 1);
  const float x1 = g.origin.x + g.cell * static_cast<float>(c1 + 1);
  const float y1 = g.origin.y + g.cell * static_cast<float>(r1 + 1);
  b2AABB region;
  region.lowerBound = region.upperBound = body_->GetWorldPoint(b2Vec2(x0, y0));
  for (const b2Vec2& corner : {b2Vec2(x1, y0), b2Vec2(x1, y1), b2Vec2(x0, y1)}) {
    const b2Vec2 p = body_->GetWorldPoint(corner);
    region.lowerBound = b2Min(region.lowerBound, p);
    region.upperBound = b2Max(region.upperBound, p);
  }
  refresh_internal_edges(world, region);
}

}  // namespace dyop::box2d
