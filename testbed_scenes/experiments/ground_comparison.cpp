#include "experiments/ground_comparison.hpp"

#include <box2d/box2d.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <optional>
#include <stdexcept>

#include "dyop/box2d_grid.hpp"
#include "experiments/everyday_bodies.hpp"
#include "experiments/ground_measures.hpp"
#include "level_outline.hpp"  // examples/: the 300 m outline level
#include "scenes/installation.hpp"
#include "scenes/metrics.hpp"
#include "worlds/world.hpp"
#ifdef DYOP_WITH_OUTLINES
#include "dyop/box2d_outline.hpp"
#endif

namespace dyop::experiments {
namespace {

using Ring = std::vector<b2Vec2>;

constexpr float kPush = 4;        // m/s, the glides' push
constexpr int kGlideSteps = 240;  // 4 s: 16 m at kPush, within every level's flat stretch
constexpr int kPlacementSteps = 180;
constexpr int kPlacedBoxes = 10;     // 2 m apart from x = 2.5 m, within the flat stretch
constexpr float kDeepStart = -0.1f;  // m: a box's centre started under the top, 0.4 m inside

// The tile grid: 256 × 64 cells of 0.5 m; its surface row 48 over the first 48 columns (the
// flat stretch, top at y = 0), hills beyond, caves under, all below the top of the flat stretch.
constexpr int kColumns = 256;
constexpr int kRows = 64;
constexpr float kCell = 0.5f;
constexpr int kFlatColumns = 48;
const b2Vec2 kGridOrigin(0, -kFlatColumns* kCell);

std::vector<std::uint8_t> tile_cells() {
  std::vector<std::uint8_t> cells(static_cast<std::size_t>(kColumns) * kRows, 0);
  for (int c = 0; c < kColumns; ++c) {
    const double x = c - kFlatColumns;
    const int surface =
        c < kFlatColumns
            ? kFlatColumns
            : kFlatColumns +
                  static_cast<int>(std::lround(10 * std::sin(x / 10) * std::sin(x / 27)));
    for (int r = 0; r < std::min(surface, kRows); ++r) {
      // Eight caves, ellipses of 10 × 4 cells centred on row 24.
      const int k = std::clamp((c - 16) / 30, 0, 7);
      const double dx = (c - (16 + 30 * k + 15)) / 10.0;
      const double dy = (r - 24) / 4.0;
      const bool cave = dx * dx + dy * dy < 1;
      cells[static_cast<std::size_t>(r) * kColumns + c] = cave ? 0 : 1;
    }
  }
  return cells;
}

// The column whose top cell a refresh digs, on a hill's flank.
constexpr int kPitColumn = 200;

// The flat level: 60 m of top with a vertex every 0.25 m, 10 m deep (counter-clockwise).
std::vector<Ring> flat_rings() {
  Ring ring = {{0, -10}, {60, -10}};
  for (int i = 240; i >= 0; --i) ring.push_back({0.25f * static_cast<float>(i), 0});
  return {ring};
}

double elapsed_ms(std::chrono::steady_clock::time_point since) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - since)
      .count();
}

// One level built one way in a world of its own.
class Built {
 public:
  Built(GroundLevel level, GroundBuild build) : level_(level), build_(build) {
    if (level == GroundLevel::TileGrid) cells_ = tile_cells();  // the game's map, not timed
    ground_ = worlds::add_body(world, b2_staticBody, b2Vec2(0, 0));
    const auto start = std::chrono::steady_clock::now();
    make();
    build_ms = elapsed_ms(start);
  }

  // Digs a cell (tile grid: the top cell of column `kPitColumn`, its chunk built again by the
  // builders, every loop traced again for the chain), or builds an outline level again;
  // milliseconds.
  double refresh() {
    const auto start = std::chrono::steady_clock::now();
    if (level_ == GroundLevel::TileGrid) {
      int row = kRows - 1;
      while (row > 0 && !cells_[static_cast<std::size_t>(row) * kColumns + kPitColumn]) --row;
      cells_[static_cast<std::size_t>(row) * kColumns + kPitColumn] = 0;
      if (tiles_) {
        tiles_->set_cell(kPitColumn, row, false);
        return elapsed_ms(start);
      }
    }
    clear();
    make();
    return elapsed_ms(start);
  }

  worlds::World world;  // the testbed's: sleeping off, its step and iterations
  double build_ms = 0;
  double boundary = 0;
  int proxies = 0;
  double bytes = 0;
  int fixtures() const { return static_cast<int>(fixtures_.size()); }

 private:
  void make() {
    const std::vector<Ring> loops =
        level_ == GroundLevel::TileGrid
            ? tile_loops(cells_, kColumns, kRows, kCell, kGridOrigin)
            : chain_loops_of(level_ == GroundLevel::Flat ? flat_rings() : level_outline());
    boundary = boundary_length(loops);
    if (build_ == GroundBuild::Edges) {
      for (const Ring& loop : loops) {
        for (std::size_t i = 0; i < loop.size(); ++i) {
          b2EdgeShape edge;
          edge.SetTwoSided(loop[i], loop[(i + 1) % loop.size()]);
          fixtures_.push_back(ground_->CreateFixture(&edge, 0));
        }
      }
      proxies = fixtures();
      bytes = fixtures_bytes<b2EdgeShape>(fixtures_.size());
      return;
    }
    if (build_ == GroundBuild::Chain) {
      for (const Ring& loop : loops) {
        b2ChainShape chain;
        chain.CreateLoop(loop.data(), static_cast<int>(loop.size()));
        fixtures_.push_back(ground_->CreateFixture(&chain, 0));
        proxies += chain.GetChildCount();
        bytes += chain_bytes(chain);
      }
      return;
    }
    if (level_ == GroundLevel::TileGrid) {
      tiles_ = std::make_unique<box2d::TileGround>(
          *ground_, box2d::GridLayout{kColumns, kRows, kCell, kGridOrigin});
      if (tiles_->set_cells(cells_) != box2d::GridError::None) {
        throw std::runtime_error("grounds: the tile grid was refused");
      }
      fixtures_ = tiles_->fixtures();
    } else {
#ifdef DYOP_WITH_OUTLINES
      const box2d::OutlineResult r = box2d::add_outline(*ground_, loops);
      if (!r.ok()) throw std::runtime_error(std::string("grounds: outline refused: ") + r.message);
      fixtures_ = r.mesh.fixtures;
#else
      throw std::runtime_error("grounds: built without dyop::box2d_outlines (GEOS)");
#endif
    }
    proxies = fixtures();
    bytes = fixtures_bytes<b2PolygonShape>(fixtures_.size());
  }

  void clear() {
    for (b2Fixture* f : fixtures_) ground_->DestroyFixture(f);
    fixtures_.clear();
    tiles_.reset();
    proxies = 0;
    bytes = 0;
  }

  GroundLevel level_;
  GroundBuild build_;
  b2Body* ground_ = nullptr;
  std::vector<std::uint8_t> cells_;
  std::unique_ptr<box2d::TileGround> tiles_;
  std::vector<b2Fixture*> fixtures_;
};

// Bodies of one measurement pass through each other (one negative group): each meets the ground
// alone, as in a world of its own.
constexpr int16 kApart = -1;

b2Body* add_apart(worlds::World& world, const b2Shape* shape, const b2Vec2& at, float friction) {
  b2Body* body = add_everyday_body(world, shape, at, friction);
  for (b2Fixture* f = body->GetFixtureList(); f; f = f->GetNext()) {
    b2Filter filter = f->GetFilterData();
    filter.groupIndex = kApart;
    f->SetFilterData(filter);
  }
  return body;
}

// The glides' bodies, resting on the flat stretch at x = 2 m and pushed at kPush.
std::vector<b2Body*> add_gliders(worlds::World& world, const EverydayShapes& shapes) {
  std::vector<b2Body*> bodies;
  for (const auto& entry : shapes.all()) {
    const b2Shape* shape = entry.second;
    bodies.push_back(add_apart(world, shape, {2, resting_height(shape) + 0.005f}, 0));
    bodies.back()->SetLinearVelocity({kPush, 0});
  }
  return bodies;
}

// A placement trial's kPlacedBoxes boxes, centres at height `y` moving down at `speed`.
std::vector<b2Body*> add_placed_boxes(worlds::World& world, const EverydayShapes& shapes, float y,
                                      float speed) {
  std::vector<b2Body*> boxes;
  for (int k = 0; k < kPlacedBoxes; ++k) {
    b2Body* b = add_apart(world, &shapes.box, {2.5f + 2 * static_cast<float>(k), y}, 0.6f);
    b->SetLinearVelocity({0, -speed});
    boxes.push_back(b);
  }
  return boxes;
}

std::vector<GroundGlide> glides(Built& built, const EverydayShapes& shapes) {
  const std::vector<b2Body*> bodies = add_gliders(built.world, shapes);
  std::vector<double> vertical(bodies.size(), 0);
  for (int i = 0; i < kGlideSteps; ++i) {
    built.world.step();
    for (std::size_t k = 0; k < bodies.size() && i > 0; ++k) {
      vertical[k] = std::max(vertical[k], std::abs(double{bodies[k]->GetLinearVelocity().y}));
    }
  }
  std::vector<GroundGlide> out;
  for (std::size_t k = 0; k < bodies.size(); ++k) {
    out.push_back({shapes.all()[k].first, vertical[k],
                   (bodies[k]->GetPosition().x - 2) / (kPush * kGlideSteps * worlds::time_step)});
  }
  return out;
}

std::vector<GroundPlacement> placements(Built& built, const EverydayShapes& shapes) {
  struct Trial {
    const char* label;
    float y;      // the centre's start height (0.3: resting on the top)
    float speed;  // downward, m/s
  };
  const Trial trials[] = {{"started 0.1 m inside", 0.2f, 0},
                          {"started 0.25 m inside", 0.05f, 0},
                          {"started 0.4 m inside (centre under the top)", kDeepStart, 0},
                          {"thrown down at 30 m/s", 5, 30},
                          {"thrown down at 100 m/s", 5, 100},
                          {"thrown down at 300 m/s", 5, 300}};
  std::vector<std::vector<b2Body*>> boxes;
  for (const Trial& t : trials) {
    boxes.push_back(add_placed_boxes(built.world, shapes, t.y, t.speed));
  }
  for (int i = 0; i < kPlacementSteps; ++i) built.world.step();
  std::vector<GroundPlacement> out;
  for (std::size_t k = 0; k < boxes.size(); ++k) {
    const int on_top = static_cast<int>(std::count_if(
        boxes[k].begin(), boxes[k].end(), [](const b2Body* b) { return b->GetPosition().y > 0; }));
    out.push_back({trials[k].label, on_top, kPlacedBoxes});
  }
  return out;
}

// The level's length along x and the height above which the crowd is dropped.
std::pair<float, float> crowd_span(GroundLevel level) {
  switch (level) {
    case GroundLevel::Flat:
      return {60, 1};
    case GroundLevel::TileGrid:
      return {kColumns * kCell, 7};
    case GroundLevel::Outline:
      break;
  }
  return {300, 4};
}

// The crowd's narrow phase and step (ms, summed over its steps) on `built`.
std::pair<double, double> crowd(Built& built, GroundLevel level, const GroundTiming& timing,
                                const EverydayShapes& shapes) {
  const auto [length, height] = crowd_span(level);
  const auto all = shapes.all();
  const int per_row = static_cast<int>((length - 2) / 0.85f);
  for (int k = 0; k < timing.bodies; ++k) {
    add_everyday_body(built.world, all[static_cast<std::size_t>(k) % all.size()].second,
                      {1 + 0.85f * static_cast<float>(k % per_row),
                       height + 0.9f * static_cast<float>(k / per_row)},
                      0.6f);
  }
  double collide = 0, step = 0;
  for (int i = 0; i < timing.steps; ++i) {
    built.world.step();
    collide += built.world->GetProfile().collide;
    step += built.world->GetProfile().step;
  }
  return {collide, step};
}

scenes::Runner runner_of(GroundWay way) {
  return way.plugin ? scenes::Runner{box2d::Backend::Dyop} : scenes::Runner{};
}

}  // namespace

const char* name(GroundLevel level) {
  switch (level) {
    case GroundLevel::Flat:
      return "flat";
    case GroundLevel::TileGrid:
      return "tile-grid";
    case GroundLevel::Outline:
      break;
  }
  return "outline";
}

const char* name(GroundBuild build) {
  switch (build) {
    case GroundBuild::Chain:
      return "chain";
    case GroundBuild::Edges:
      return "edges";
    case GroundBuild::Builder:
      break;
  }
  return "builders";
}

std::string name(GroundWay way) {
  return std::string(name(way.build)) + (way.plugin ? ", plug-in" : ", Box2D's own");
}

bool builders_available(GroundLevel level) {
#ifdef DYOP_WITH_OUTLINES
  (void)level;
  return true;
#else
  return level == GroundLevel::TileGrid;
#endif
}

std::vector<std::vector<b2Vec2>> tile_loops(const std::vector<std::uint8_t>& cells, int columns,
                                            int rows, float cell, const b2Vec2& origin) {
  if (columns < 1 || rows < 1 ||
      cells.size() != static_cast<std::size_t>(columns) * static_cast<std::size_t>(rows)) {
    throw std::invalid_argument("tile_loops: cells must be columns × rows long");
  }
  const auto solid = [&](int c, int r) {
    return c >= 0 && r >= 0 && c < columns && r < rows &&
           cells[static_cast<std::size_t>(r) * columns + c] != 0;
  };
  const auto vertex = [&](int i, int j) { return j * (columns + 1) + i; };
  // The boundary's unit edges, each with the solid on its left; a corner starts at most two (two
  // cells meeting there only by the corner).
  struct Edge {
    int from, to;
    int dx, dy;
  };
  std::vector<Edge> edges;
  std::vector<std::array<int, 2>> starting(static_cast<std::size_t>(vertex(columns, rows)) + 1,
                                           {-1, -1});
  const auto add = [&](int i, int j, int dx, int dy) {
    const int e = static_cast<int>(edges.size());
    edges.push_back({vertex(i, j), vertex(i + dx, j + dy), dx, dy});
    auto& at = starting[static_cast<std::size_t>(vertex(i, j))];
    (at[0] < 0 ? at[0] : at[1]) = e;
  };
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < columns; ++c) {
      if (!solid(c, r)) continue;
      if (!solid(c, r - 1)) add(c, r, 1, 0);           // bottom, along +x
      if (!solid(c + 1, r)) add(c + 1, r, 0, 1);       // right, along +y
      if (!solid(c, r + 1)) add(c + 1, r + 1, -1, 0);  // top, along −x
      if (!solid(c - 1, r)) add(c, r + 1, 0, -1);      // left, along −y
    }
  }
  std::vector<bool> used(edges.size(), false);
  std::vector<std::vector<b2Vec2>> loops;
  for (std::size_t first = 0; first < edges.size(); ++first) {
    if (used[first]) continue;
    std::vector<int> path;  // edges in order
    for (int e = static_cast<int>(first); !used[static_cast<std::size_t>(e)];) {
      used[static_cast<std::size_t>(e)] = true;
      path.push_back(e);
      const Edge& in = edges[static_cast<std::size_t>(e)];
      const auto& next = starting[static_cast<std::size_t>(in.to)];
      e = next[0];
      // Two cells meeting by a corner: turn left, around the cell the loop came along.
      if (next[1] >= 0) {
        const Edge& a = edges[static_cast<std::size_t>(next[0])];
        if (in.dx * a.dy - in.dy * a.dx < 0) e = next[1];
      }
    }
    // The corners where the direction turns (straight runs merged).
    std::vector<b2Vec2> loop;
    for (std::size_t k = 0; k < path.size(); ++k) {
      const Edge& in = edges[static_cast<std::size_t>(path[(k + path.size() - 1) % path.size()])];
      const Edge& out = edges[static_cast<std::size_t>(path[k])];
      if (in.dx == out.dx && in.dy == out.dy) continue;
      const int i = out.from % (columns + 1);
      const int j = out.from / (columns + 1);
      loop.push_back(
          {origin.x + cell * static_cast<float>(i), origin.y + cell * static_cast<float>(j)});
    }
    loops.push_back(std::move(loop));
  }
  return loops;
}

GroundTiming ground_timing(GroundLevel level, bool quick, std::optional<int> steps) {
  const bool large = level != GroundLevel::Flat;
  GroundTiming t =
      quick ? GroundTiming{large ? 300 : 160, 180, 2} : GroundTiming{large ? 800 : 240, 480, 3};
  if (steps) t.steps = std::max(1, *steps);
  return t;
}

std::array<GroundRun, ground_way_count> compare_ground(GroundLevel level,
                                                       const GroundTiming& timing,
                                                       const box2d::Config& config) {
  if (!builders_available(level)) {
    throw std::runtime_error(std::string("grounds: no builder for level ") + name(level) +
                             " in this build (dyop::box2d_outlines needs GEOS)");
  }
  const EverydayShapes shapes;
  std::array<GroundRun, ground_way_count> out;
  std::array<std::vector<double>, ground_way_count> builds, collide, step;
  for (std::size_t w = 0; w < ground_ways.size(); ++w) {
    const GroundWay way = ground_ways[w];
    GroundRun& r = out[w];
    const scenes::Installation installed(runner_of(way), config);
    r.level = level;
    r.way = way;
    Built gliding(level, way.build);
    r.boundary = gliding.boundary;
    r.fixtures = gliding.fixtures();
    r.proxies = gliding.proxies;
    r.bytes = gliding.bytes;
    r.glides = glides(gliding, shapes);
    Built placing(level, way.build);
    r.placements = placements(placing, shapes);
    r.refresh_ms = placing.refresh();
    builds[w] = {gliding.build_ms, placing.build_ms};
  }
  for (int run = 0; run < timing.runs; ++run) {
    for (std::size_t w = 0; w < ground_ways.size(); ++w) {
      const scenes::Installation installed(runner_of(ground_ways[w]), config);
      Built built(level, ground_ways[w].build);
      builds[w].push_back(built.build_ms);
      const auto [c, s] = crowd(built, level, timing, shapes);
      collide[w].push_back(c);
      step[w].push_back(s);
    }
  }
  for (std::size_t w = 0; w < ground_ways.size(); ++w) {
    GroundRun& r = out[w];
    r.build_ms = scenes::median(builds[w]);
    r.narrow_ms = scenes::median(collide[w]);
    r.step_ms = scenes::median(step[w]);
  }
  return out;
}

std::string ground_recording_name(GroundLevel level) {
  return std::string("grounds-") + name(level);
}

std::optional<GroundLevel> ground_level_of_recording(const std::string& name) {
  for (const GroundLevel level : ground_levels) {
    if (ground_recording_name(level) == name) return level;
  }
  return std::nullopt;
}

LockstepRecording record_ground(GroundLevel level, const std::array<scenes::Runner, 2>& runners,
                                int steps, const std::array<box2d::Config, 2>& configs) {
  if (!builders_available(level)) {
    throw std::runtime_error(std::string("grounds: no builder for level ") + name(level) +
                             " in this build (dyop::box2d_outlines needs GEOS)");
  }
  const EverydayShapes shapes;
  return record_sides(ground_recording_name(level), runners, steps, configs, [&](int side) {
    auto built =
        std::make_shared<Built>(level, side == 0 ? GroundBuild::Chain : GroundBuild::Builder);
    add_gliders(built->world, shapes);
    add_placed_boxes(built->world, shapes, kDeepStart, 0);
    return SideWorld{built, &built->world, 1};
  });
}

}  // namespace dyop::experiments
