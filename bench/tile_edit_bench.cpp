// build/bin/dyop_tile_edit_bench: what one cell edit of a `TileGround` costs, slopes included.
// A 256 × 64 map of 0.5 m cells in chunks of 16 × 16 (hills whose surface steps are 45° and 1:2
// slope cells), then edits one at a time, each timed alone (wall clock): digging a surface cell,
// filling it again, making a surface cell a slope, and making a slope another kind; the median,
// 90th percentile and largest of each, and of a map without slopes for comparison. The edits are
// seeded and undone in turn, so every run times the same ones.
#include <box2d/box2d.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "dyop/box2d.hpp"
#include "dyop/box2d_grid.hpp"

namespace {

using dyop::box2d::TileKind;

constexpr int kColumns = 256, kRows = 64;
constexpr float kCell = 0.5f;
constexpr int kEdits = 2000;  // per kind of edit

// The surface height of column c (rows of ground), hills of up to 10 rows.
int surface(int c) {
  return 40 + static_cast<int>(std::lround(10 * std::sin(c / 10.0) * std::sin(c / 27.0)));
}

// The map: full cells under the surface, and where the surface steps by a row from one column to
// the next, a 45° slope cell on the lower column; `slopes` false leaves the steps square.
std::vector<std::uint8_t> map_cells(bool slopes) {
  std::vector<std::uint8_t> cells(static_cast<std::size_t>(kColumns) * kRows, 0);
  for (int c = 0; c < kColumns; ++c) {
    const int h = surface(c);
    for (int r = 0; r < h; ++r) cells[static_cast<std::size_t>(r * kColumns + c)] = 1;
    if (!slopes) continue;
    const TileKind step = c + 1 < kColumns && surface(c + 1) > h ? TileKind::FloorRising
                          : c > 0 && surface(c - 1) > h          ? TileKind::FloorFalling
                          : c % 7 == 0                           ? TileKind::GentleFloorRisingLow
                          : c % 7 == 1                           ? TileKind::GentleFloorRisingHigh
                                                                 : TileKind::Empty;
    cells[static_cast<std::size_t>(h * kColumns + c)] = static_cast<std::uint8_t>(step);
  }
  return cells;
}

double median_of(std::vector<double> v, double share) {
  std::sort(v.begin(), v.end());
  return v[static_cast<std::size_t>(share * static_cast<double>(v.size() - 1))];
}

// Times `kEdits` edits `edit(cell, undo)` at random surface columns, each alone, undoing each
// (untimed) before the next; prints the median, 90th percentile and largest in milliseconds. The
// world steps after each edit and each undo, as a game's does between them: Box2D 2.4 keeps every
// fixture created since the last step in its broad phase's move buffer and searches it linearly
// for each fixture destroyed, so edits without steps would time that search.
template <class Edit>
void time_edits(b2World& world, const char* what, Edit edit) {
  std::mt19937 rng(63);
  std::uniform_int_distribution<int> column(1, kColumns - 2);
  std::vector<double> ms;
  for (int i = 0; i < kEdits; ++i) {
    const int c = column(rng);
    const auto start = std::chrono::steady_clock::now();
    edit(c, false);
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                     .count());
    world.Step(1.0f / 60, 8, 3);
    edit(c, true);
    world.Step(1.0f / 60, 8, 3);
  }
  std::printf("%-46s median %.4f ms, p90 %.4f ms, largest %.4f ms\n", what, median_of(ms, 0.5),
              median_of(ms, 0.9), median_of(ms, 1.0));
}

void run(bool slopes) {
  b2World world(b2Vec2(0, -10));
  b2BodyDef def;
  b2Body* body = world.CreateBody(&def);
  dyop::box2d::TileGround ground(*body, {kColumns, kRows, kCell, b2Vec2(0, 0)});
  const auto start = std::chrono::steady_clock::now();
  if (ground.set_cells(map_cells(slopes)) != dyop::box2d::GridError::None) return;
  std::printf(
      "%s: %zu fixtures, built in %.1f ms\n", slopes ? "map with slopes" : "map without slopes",
      ground.fixtures().size(),
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  world.Step(1.0f / 60, 8, 3);
  // The top ground cell of column c (a slope where there is one).
  const auto top = [&](int c) {
    int r = kRows - 1;
    while (r > 0 && !ground.solid(c, r)) --r;
    return r;
  };
  std::vector<TileKind> before(kColumns);
  time_edits(world, "  dig the top cell", [&](int c, bool undo) {
    const int r = top(c) + (undo ? 1 : 0);
    if (!undo) before[static_cast<std::size_t>(c)] = ground.kind(c, r);
    ground.set_cell(c, r, undo ? before[static_cast<std::size_t>(c)] : TileKind::Empty);
  });
  time_edits(world, "  fill the cell above the top",
             [&](int c, bool undo) { ground.set_cell(c, top(c) + (undo ? 0 : 1), !undo); });
  if (!slopes) return;
  constexpr TileKind kinds[] = {TileKind::FloorRising,
                                TileKind::FloorFalling,
                                TileKind::GentleFloorRisingLow,
                                TileKind::GentleFloorRisingHigh,
                                TileKind::GentleFloorFallingHigh,
                                TileKind::GentleFloorFallingLow};
  time_edits(world, "  make the cell above the top a slope", [&](int c, bool undo) {
    const int r = top(c) + (undo ? 0 : 1);
    ground.set_cell(c, r, undo ? TileKind::Empty : kinds[c % std::size(kinds)]);
  });
  time_edits(world, "  make the top cell another kind of slope", [&](int c, bool undo) {
    const int r = top(c);
    if (!undo) before[static_cast<std::size_t>(c)] = ground.kind(c, r);
    ground.set_cell(c, r,
                    undo ? before[static_cast<std::size_t>(c)] : kinds[(c + 1) % std::size(kinds)]);
  });
}

}  // namespace

int main() {
  run(false);
  run(true);
  return 0;
}
