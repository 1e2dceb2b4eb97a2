#include <box2d/b2_polygon_shape.h>
#include <box2d/b2_world.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>

#include "dyop/box2d.hpp"
#include "dyop/box2d_grid.hpp"
#include "dyop/box2d_internal_edges.hpp"

namespace dyop::box2d {
namespace {

// A run of full cells merged into one rectangle: columns [c0, c1), rows [r0, r1).
struct Rectangle {
  int c0, c1, r0, r1;
};

// Every kind past `Solid` is a slope: a part of its cell.
bool slope(TileKind k) { return k > TileKind::Solid; }

// True when the ground of kind `k` fills the cell's right side (`right`) or left side wholly.
bool full_side(TileKind k, bool right) {
  const TileSurface s = tile_surface(k);
  const int height = right ? s.right : s.left;
  return s.ceiling ? height == 0 : height == 2;
}

// A map's bytes read as kinds: the ground's own, or a map being checked before it is taken.
//
// Slope cells make pieces: a slope cell alone, or joined to the cell beside it across a side both
// fill wholly (a full cell at a slope's top, or a slope meeting a slope at a peak), one convex
// fixture. Why: where a ramp meets a flat at a convex joint, the flat's rectangle and the slope
// would each have a corner there with one edge internal, and a ball still on the slope would touch
// the rectangle's corner from behind its internal edge and be pushed off the slope's line (the
// rule closes only vertices where the outline is flat or concave); one piece has the joint as its
// own vertex between two outline edges, as a ground drawn in one polygon does. The union is
// convex: both cells fill the shared side, and the outline turns down (or stays flat) over it. A
// slope fills at most one side wholly, so a piece spans at most three cells (slope, full cell,
// slope).
struct Cells {
  const std::vector<std::uint8_t>& bytes;
  int columns, rows;

  TileKind kind(int c, int r) const {
    if (c < 0 || r < 0 || c >= columns || r >= rows) return TileKind::Empty;
    return tile_kind(bytes[static_cast<std::size_t>(r * columns + c)]);
  }
  // True when cells (c, r) and (c + 1, r) lie in one piece.
  bool joined(int c, int r) const {
    const TileKind a = kind(c, r), b = kind(c + 1, r);
    return (slope(a) || slope(b)) && full_side(a, true) && full_side(b, false);
  }
  // True when cell (c, r) lies in a piece (else a full cell is merged into a rectangle).
  bool in_piece(int c, int r) const {
    return slope(kind(c, r)) || joined(c - 1, r) || joined(c, r);
  }
  // The columns [first, end) of the piece holding cell (c, r).
  int first(int c, int r) const {
    while (joined(c - 1, r)) --c;
    return c;
  }
  int end(int c, int r) const {
    while (joined(c, r)) ++c;
    return c + 1;
  }
};

// The full cells of the window [c0, c1) × [r0, r1) outside pieces, merged greedily: each row's
// maximal runs not yet covered, each grown upward while the rows above hold the same run full and
// uncovered. Every such cell lies in exactly one rectangle.
std::vector<Rectangle> merge(const Cells& cells, int c0, int c1, int r0, int r1) {
  const int w = c1 - c0;
  std::vector<std::uint8_t> covered(static_cast<std::size_t>(w * (r1 - r0)), 0);
  const auto solid = [&](int c, int r) {
    return cells.kind(c, r) == TileKind::Solid && !cells.in_piece(c, r) &&
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

// A point of the grid in half cells (x from column 0's left side, y from row 0's bottom).
struct HalfPoint {
  int x, y;
};

// The outline of piece [c0, c1) of row `r`, counter-clockwise in half cells, without repeated or
// collinear points (integers: the test is exact): along the cells' bottoms, then back along their
// tops. Where two cells of a piece meet, both fill the side, so one point serves each end of it.
std::vector<HalfPoint> piece_outline(const Cells& cells, int c0, int c1, int r) {
  std::vector<HalfPoint> p;
  const auto bottom = [&](int c, bool right) {
    const TileSurface s = tile_surface(cells.kind(c, r));
    return 2 * r + (s.ceiling ? (right ? s.right : s.left) : 0);
  };
  const auto top = [&](int c, bool right) {
    const TileSurface s = tile_surface(cells.kind(c, r));
    return 2 * r + (s.ceiling ? 2 : (right ? s.right : s.left));
  };
  p.push_back({2 * c0, bottom(c0, false)});
  for (int c = c0; c < c1; ++c) p.push_back({2 * c + 2, bottom(c, true)});
  p.push_back({2 * c1, top(c1 - 1, true)});
  for (int c = c1 - 1; c >= c0; --c) p.push_back({2 * c, top(c, false)});
  // Drop a point equal to the one before it, or on the line through its neighbours, until none.
  for (bool dropped = true; dropped && p.size() > 3;) {
    dropped = false;
    for (std::size_t i = 0; i < p.size() && p.size() > 3; ++i) {
      const HalfPoint& a = p[(i + p.size() - 1) % p.size()];
      const HalfPoint& b = p[i];
      const HalfPoint& c = p[(i + 1) % p.size()];
      const std::int64_t cross = static_cast<std::int64_t>(b.x - a.x) * (c.y - a.y) -
                                 static_cast<std::int64_t>(b.y - a.y) * (c.x - a.x);
      if (cross == 0) {
        p.erase(p.begin() + static_cast<std::ptrdiff_t>(i));
        dropped = true;
      }
    }
  }
  return p;
}

// The fixture shape of piece [c0, c1) of row `r`, or nothing when Box2D would not take it. Its
// corners are placed on the grid's lines in half cells, computed from the same integers wherever
// two pieces share a corner, so that neighbours meet bit for bit and the rule sees their shared
// edges whole. A triangle is `make_triangle`'s; a larger piece is checked as a fan of triangles
// first, since `b2PolygonShape::Set` would weld close points or assert on a flat hull, then made by
// `Set`, which keeps every point of a convex outline whose fan triangles are valid.
std::optional<b2PolygonShape> piece_shape(const GridLayout& g, const Cells& cells, int c0, int c1,
                                          int r) {
  const std::vector<HalfPoint> outline = piece_outline(cells, c0, c1, r);
  const float half = 0.5f * g.cell;
  std::array<b2Vec2, b2_maxPolygonVertices> p;
  const int n = static_cast<int>(outline.size());
  if (n < 3 || n > b2_maxPolygonVertices) return std::nullopt;
  for (int i = 0; i < n; ++i) {
    p[i] = b2Vec2(g.origin.x + half * static_cast<float>(outline[i].x),
                  g.origin.y + half * static_cast<float>(outline[i].y));
  }
  const TriangleShape first = make_triangle(p[0], p[1], p[2]);
  if (!first.ok()) return std::nullopt;
  if (n == 3) return first.shape;
  for (int i = 2; i + 1 < n; ++i) {
    if (!make_triangle(p[0], p[i], p[i + 1]).ok()) return std::nullopt;
  }
  b2PolygonShape polygon;
  polygon.Set(p.data(), n);
  if (polygon.m_count != n) return std::nullopt;  // Box2D 2.4.2's Set welds within 2 cm
  return polygon;
}

// True when every piece starting in columns [c0, c1) of row `r` makes a shape.
bool pieces_valid(const GridLayout& g, const Cells& cells, int c0, int c1, int r) {
  for (int c = std::max(c0, 0); c < std::min(c1, cells.columns); ++c) {
    if (!cells.in_piece(c, r) || cells.first(c, r) != c) continue;
    if (!piece_shape(g, cells, c, cells.end(c, r), r)) return false;
  }
  return true;
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
    case GridError::SlopeShape:
      return "a slope cell Box2D would not take: its corners too close for float at their "
             "distance from the body origin";
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
  const Cells view{cells, layout_.columns, layout_.rows};
  for (int r = 0; r < layout_.rows; ++r) {
    if (!pieces_valid(layout_, view, 0, layout_.columns, r)) return GridError::SlopeShape;
  }
  cells_ = cells;
  chunks_.resize(static_cast<std::size_t>(chunk_columns() * chunk_rows()));
  for (int k = 0; k < static_cast<int>(chunks_.size()); ++k) build_chunk(k);
  return GridError::None;
}

GridError TileGround::set_cell(int column, int row, TileKind kind) {
  if (const GridError e = check(); e != GridError::None) return e;
  if (cells_.empty()) return GridError::Size;  // no `set_cells` yet
  if (column < 0 || row < 0 || column >= layout_.columns || row >= layout_.rows) {
    return GridError::OutOfRange;
  }
  std::uint8_t& cell = cells_[static_cast<std::size_t>(row * layout_.columns + column)];
  const std::uint8_t value = static_cast<std::uint8_t>(kind);
  if (tile_kind(cell) == tile_kind(value)) return GridError::None;
  // A piece spans at most three cells, so the change reaches the cells within two columns. The
  // chunks to build again are those of each cell there whose kind or piece changed, and those
  // that own its piece (the chunk of the piece's first cell) before and after.
  const Cells view{cells_, layout_.columns, layout_.rows};
  const int lo = std::max(column - 2, 0), hi = std::min(column + 3, layout_.columns);
  const auto pieces = [&] {
    std::array<std::array<int, 3>, 5> out{};
    for (int c = lo; c < hi; ++c) {
      const bool in = view.in_piece(c, row);
      out[static_cast<std::size_t>(c - lo)] = {static_cast<int>(view.kind(c, row)),
                                               in ? view.first(c, row) : c,
                                               in ? view.end(c, row) : c};
    }
    return out;
  };
  const auto before = pieces();
  const std::uint8_t old = cell;
  cell = value;
  if (!pieces_valid(layout_, view, lo - 2, hi, row)) {
    cell = old;
    return GridError::SlopeShape;
  }
  const auto after = pieces();
  std::vector<int> chunks;
  const auto chunk_of = [&](int c) {
    return (row / layout_.chunk) * chunk_columns() + c / layout_.chunk;
  };
  for (std::size_t i = 0; i < before.size(); ++i) {
    if (before[i] == after[i]) continue;
    chunks.insert(chunks.end(), {chunk_of(lo + static_cast<int>(i)), chunk_of(before[i][1]),
                                 chunk_of(after[i][1])});
  }
  std::sort(chunks.begin(), chunks.end());
  chunks.erase(std::unique(chunks.begin(), chunks.end()), chunks.end());
  for (const int k : chunks) build_chunk(k);
  return GridError::None;
}

GridError TileGround::set_cell(int column, int row, bool solid) {
  return set_cell(column, row, solid ? TileKind::Solid : TileKind::Empty);
}

bool TileGround::solid(int column, int row) const { return kind(column, row) != TileKind::Empty; }

TileKind TileGround::kind(int column, int row) const {
  if (cells_.empty() || column < 0 || row < 0 || column >= layout_.columns || row >= layout_.rows) {
    return TileKind::Empty;
  }
  return tile_kind(cells_[static_cast<std::size_t>(row * layout_.columns + column)]);
}

std::vector<b2Fixture*> TileGround::fixtures() const {
  std::vector<b2Fixture*> out;
  for (const std::vector<b2Fixture*>& chunk : chunks_)
    out.insert(out.end(), chunk.begin(), chunk.end());
  return out;
}

void TileGround::build_chunk(int k) {
  const GridLayout& g = layout_;
  const int c0 = (k % chunk_columns()) * g.chunk;
  const int r0 = (k / chunk_columns()) * g.chunk;
  const int c1 = std::min(c0 + g.chunk, g.columns);
  const int r1 = std::min(r0 + g.chunk, g.rows);
  // Where the chunk's old fixtures lay (body frame): the chunk, and as far as its pieces reached
  // into the next chunk.
  b2Vec2 low(g.origin.x + g.cell * static_cast<float>(c0),
             g.origin.y + g.cell * static_cast<float>(r0));
  b2Vec2 high(g.origin.x + g.cell * static_cast<float>(c1),
              g.origin.y + g.cell * static_cast<float>(r1));
  std::vector<b2Fixture*>& fixtures = chunks_[static_cast<std::size_t>(k)];
  for (b2Fixture* f : fixtures) {
    const auto& shape = static_cast<const b2PolygonShape&>(*f->GetShape());
    for (int i = 0; i < shape.m_count; ++i) {
      low = b2Min(low, shape.m_vertices[i]);
      high = b2Max(high, shape.m_vertices[i]);
    }
    body_->DestroyFixture(f);
  }
  fixtures.clear();
  b2FixtureDef def = def_;
  const Cells view{cells_, g.columns, g.rows};
  for (const Rectangle& r : merge(view, c0, c1, r0, r1)) {
    const float hx = 0.5f * g.cell * static_cast<float>(r.c1 - r.c0);
    const float hy = 0.5f * g.cell * static_cast<float>(r.r1 - r.r0);
    const b2Vec2 center(g.origin.x + g.cell * static_cast<float>(r.c0) + hx,
                        g.origin.y + g.cell * static_cast<float>(r.r0) + hy);
    b2PolygonShape box;
    box.SetAsBox(hx, hy, center, 0);
    def.shape = &box;
    fixtures.push_back(body_->CreateFixture(&def));
  }
  // The pieces starting in the chunk (one may reach two cells into the next chunk, which leaves
  // its cells out of its rectangles).
  for (int r = r0; r < r1; ++r) {
    for (int c = c0; c < c1; ++c) {
      if (!view.in_piece(c, r) || view.first(c, r) != c) continue;
      // Checked when the cells were set: the same integers give the same shape.
      const b2PolygonShape shape = *piece_shape(g, view, c, view.end(c, r), r);
      def.shape = &shape;
      fixtures.push_back(body_->CreateFixture(&def));
    }
  }
  // The new fixtures' edge data, and again that of the fixed neighbours of the old ones (a chunk
  // dug empty creates nothing, yet its neighbours' edges along it became outline): where the old
  // fixtures lay grown by a cell, its four corners placed in the world (the body may be turned).
  b2World& world = *body_->GetWorld();
  fix_internal_edges(world, fixtures);
  low -= b2Vec2(g.cell, g.cell);
  high += b2Vec2(g.cell, g.cell);
  b2AABB region;
  region.lowerBound = region.upperBound = body_->GetWorldPoint(low);
  for (const b2Vec2& corner : {b2Vec2(high.x, low.y), high, b2Vec2(low.x, high.y)}) {
    const b2Vec2 p = body_->GetWorldPoint(corner);
    region.lowerBound = b2Min(region.lowerBound, p);
    region.upperBound = b2Max(region.upperBound, p);
  }
  refresh_internal_edges(world, region);
}

}  // namespace dyop::box2d
