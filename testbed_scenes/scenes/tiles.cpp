// `tiles`: the sliders of `slide` (a frictionless box and L, a rubber wheel) launched along flat
// grounds of 0.5 m square tiles, each split in triangles, laid out as levels are: in one static
// body, one static body per tile (each turned by a multiple of a quarter turn, as tile maps turn
// tiles: its vertices then land where its neighbours' are only to float rounding), chunks of
// 8 × 8 tiles per body, cells alternately split in two and in five with the five-triangle cell's
// left side split at mid height (T-junctions: its vertex lies inside the neighbour's side), in one
// body and one body per cell, and tiles as bodies added ahead of the slider and removed behind it
// while it goes (disabled and enabled, or moved far away and back by `SetTransform`). Box2D's own
// contact collides each fixture alone; the plug-in's internal-edge rule joins the edges that
// static bodies share and those that T-junctions cover.
// `tile-map`: a crowd on a tile map as a level has it: lanes of tiles as bodies, boxes and L
// bodies sliding along them in a row, and debris falling onto a lane of its own;
// `tile-map-unfixed` the same brought over as most loaders do, its edge data never fixed.
#include <cmath>
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "dyop/box2d_internal_edges.hpp"
#include "scenes/builders.hpp"

namespace dyop::scenes::detail {
namespace {

enum class Layout { OneBody, Tiles, Chunks, TJunctions, TJunctionTiles, Changing };

struct Ground {
  const char* name;
  Layout layout;
};

constexpr Ground kGrounds[] = {
    {"one-body", Layout::OneBody},
    {"tiles", Layout::Tiles},
    {"chunks-8x8", Layout::Chunks},
    {"t-junctions", Layout::TJunctions},
    {"t-junction-tiles", Layout::TJunctionTiles},
    {"changing-tiles", Layout::Changing},
};

struct Launch {
  const char* body;
  float speed;  // m/s along +x
};

// The sliders of `slide`, at its speeds.
constexpr Launch kLaunches[] = {{"box", 6}, {"L", 6}, {"wheel", 1.8f}};

constexpr float kTile = 0.5f;  // m, side of a tile
// Every lane's ground runs from kTilesStart over kColumns tiles: 6 s at 6 m/s (the full run) from x
// = 0.
constexpr float kTilesStart = -2.0f;
constexpr int kColumns = 80;
constexpr int kRows = 2;                 // tiles deep (chunks: kChunk)
constexpr int kChunk = 8;                // tiles on a chunk's side
constexpr float kTilesLaneGap = 6.0f;    // m between lane tops: a chunk ground is 4 m deep
constexpr double kLaunchJitter = 0.001;  // m, launch position noise from the seed
// m: sliders start this far past a junction (their corner, or the L's left end). Why not on
// it: a box launched with cores touching and its middle on a junction is parted from the ground
// by the position solver unevenly over the junction's points (with any contact, Box2D's own too),
// so it starts tilted by up to 0.013 rad and its first fall back (0.07 to 0.1 m/s) would count as
// a trip. Why 0.4 of a tile: the L, with a junction of its own in the middle of its bottom, is
// thrown up at 0.089 m/s once in its run on 0.5 m cells for about half of the launch points
// between 0 and 0.2 m, on one body as on tiles (the rule as it was before edges were shared
// across bodies does the same: a limit of the rule within one body, not of the tiles), and
// never from 0.2 m over seeds 0 to 2.
constexpr float kLaunchOffset = 0.4f * kTile;
// Changing tiles: a column is there while it lies within this distance of the slider's centre
// (m). Why 1.5 m: columns arrive 1.25 m ahead of a 0.5 m body, every 5 steps at 6 m/s, and the
// pairs of the tile it is on are found under a stamp that moves with each change.
constexpr float kPresentReach = 1.5f;
// m below the lane: where `SetTransform` parks a removed tile, below every lane.
constexpr float kParkedDepth = 1000.0f;

// A cell of the ground (world frame): its corners and how it is split.
struct Cell {
  b2Vec2 bl;
  bool five;  // split in five (left side split at mid height) rather than in two
};

// The cell's triangles, world frame.
std::vector<std::array<b2Vec2, 3>> cell_triangles(const Cell& c) {
  const b2Vec2 br(c.bl.x + kTile, c.bl.y), tr(c.bl.x + kTile, c.bl.y + kTile),
      tl(c.bl.x, c.bl.y + kTile);
  if (!c.five) return {{tl, c.bl, tr}, {tr, c.bl, br}};
  const b2Vec2 mid(c.bl.x, c.bl.y + 0.5f * kTile),
      centre = c.bl + b2Vec2(0.5f * kTile, 0.5f * kTile);
  return {{tl, mid, centre},
          {mid, c.bl, centre},
          {c.bl, br, centre},
          {br, tr, centre},
          {tr, tl, centre}};
}

// Adds cell `c`'s triangles to `body`, placed by its transform.
void add_cell(b2Body* body, const Cell& c, const Material& m) {
  const b2Transform& xf = body->GetTransform();
  for (const auto& t : cell_triangles(c)) {
    add_triangle(body, b2MulT(xf, t[0]), b2MulT(xf, t[1]), b2MulT(xf, t[2]), m);
  }
}

// Ground of lane `top`: the cell in `column` and `row` (0: top row).
Cell cell_at(const Ground& g, float top, int column, int row) {
  const bool junctions = g.layout == Layout::TJunctions || g.layout == Layout::TJunctionTiles;
  return {b2Vec2(kTilesStart + column * kTile, top - (row + 1) * kTile),
          junctions && column % 2 == 1};
}

// The tiles of a changing ground, one static body per tile in column order, and where each sits.
struct ChangingGround {
  std::vector<b2Body*> tiles;  // kRows per column
  std::vector<b2Vec2> home;
  std::vector<bool> present;
};

// Adds or removes each column of `g` so that those within kPresentReach of `x` are there: even
// columns by enabling and disabling their bodies, odd ones by moving them home or parking them.
void update_changing(ChangingGround& g, float x) {
  for (std::size_t k = 0; k < g.tiles.size(); ++k) {
    const int column = static_cast<int>(k) / kRows;
    const float left = kTilesStart + column * kTile;
    const bool wanted = left + kTile >= x - kPresentReach && left <= x + kPresentReach;
    if (wanted == g.present[k]) continue;
    g.present[k] = wanted;
    b2Body* tile = g.tiles[k];
    if (column % 2 == 0) {
      tile->SetEnabled(wanted);
    } else {
      tile->SetTransform(wanted ? g.home[k] : g.home[k] - b2Vec2(0, kParkedDepth), 0);
    }
    // The tile's fixed edge data and its neighbours' found again where it came or went, as the
    // plug-in asks of a fixed ground changed by hand (a parked tile is refreshed when it is back).
    b2AABB home;
    home.lowerBound = g.home[k];
    home.upperBound = g.home[k] + b2Vec2(kTile, kTile);
    box2d::refresh_internal_edges(*tile->GetWorld(), home);
  }
}

// Lays out ground `g` with its top at y = `top`; a changing ground is returned to be updated.
std::shared_ptr<ChangingGround> add_ground(World& world, const Ground& g, float top,
                                           const Material& m) {
  const int rows = g.layout == Layout::Chunks ? kChunk : kRows;
  switch (g.layout) {
    case Layout::OneBody:
    case Layout::TJunctions: {
      b2Body* body = add_body(world, b2_staticBody, b2Vec2(0, 0));
      for (int row = 0; row < rows; ++row) {
        for (int i = 0; i < kColumns; ++i) add_cell(body, cell_at(g, top, i, row), m);
      }
      return nullptr;
    }
    case Layout::Chunks:
      for (int c = 0; c < kColumns / kChunk; ++c) {
        b2Body* body =
            add_body(world, b2_staticBody, b2Vec2(kTilesStart + c * kChunk * kTile, top));
        for (int row = 0; row < rows; ++row) {
          for (int i = c * kChunk; i < (c + 1) * kChunk; ++i)
            add_cell(body, cell_at(g, top, i, row), m);
        }
      }
      return nullptr;
    default:
      break;
  }
  auto changing = std::make_shared<ChangingGround>();
  for (int i = 0; i < kColumns; ++i) {
    for (int row = 0; row < rows; ++row) {
      const Cell c = cell_at(g, top, i, row);
      const b2Vec2 centre = c.bl + b2Vec2(0.5f * kTile, 0.5f * kTile);
      // Tiles turned by quarter turns: cos(π/2) is not 0 in floats, so their vertices meet their
      // neighbours' only within rounding.
      const float angle = g.layout == Layout::Tiles ? 1.5707963f * ((i + row) % 4) : 0.0f;
      b2Body* body =
          add_body(world, b2_staticBody, g.layout == Layout::Changing ? c.bl : centre, angle);
      add_cell(body, c, m);
      changing->tiles.push_back(body);
      changing->home.push_back(body->GetPosition());
      changing->present.push_back(true);
    }
  }
  return g.layout == Layout::Changing ? changing : nullptr;
}

// The tile map: kMapLanes lanes of tiles as bodies, kMapSliders sliders on each, spaced
// kMapSpacing apart (a multiple of a tile: each starts kLaunchOffset past a junction), and a
// lane below them where kMapDebris triangles fall. Why 3 m/s: a slider then moves 5 cm a step,
// so recycling keeps none of its contacts and every one runs the rule.
constexpr int kMapLanes = 4;
constexpr int kMapSliders = 12;
constexpr float kMapSpacing = 1.5f;
constexpr float kMapSpeed = 3.0f;
constexpr int kMapDebris = 60;

}  // namespace

WorldBuild build_tile_map_unfixed(World& world, workloads::Random& rng) {
  WorldBuild build = build_tile_map(world, rng);
  build.fix_edge_data = false;
  return build;
}

WorldBuild build_tile_map(World& world, workloads::Random& rng) {
  WorldBuild build;
  const Ground lanes{"tiles", Layout::Tiles};
  for (int lane = 0; lane < kMapLanes; ++lane) {
    const float top = -kTilesLaneGap * static_cast<float>(lane);
    add_ground(world, lanes, top, slider_ice);
    const std::string name = "lane-" + std::to_string(lane + 1);
    for (int i = 0; i < kMapSliders; ++i) {
      const float x =
          kLaunchOffset + kMapSpacing * static_cast<float>(i) + jitter(rng, kLaunchJitter);
      build.sliders.push_back(
          launch_slider(world, i % 2 == 0 ? "box" : "L", name, x, top, kMapSpeed));
    }
  }
  const float debris_top = -kTilesLaneGap * static_cast<float>(kMapLanes);
  add_ground(world, lanes, debris_top, slider_rubber);
  const float length = kColumns * kTile;
  for (int i = 0; i < kMapDebris; ++i) {
    const b2Vec2 at(
        kTilesStart + length * (static_cast<float>(i) + 0.5f) / kMapDebris + jitter(rng, 0.1),
        debris_top + rng.uniformf(0.5, 2.5));
    add_random_triangle(world, rng, at, rng.uniform(0.1, 0.25));
  }
  return build;
}

WorldBuild build_tiles(World& world, workloads::Random& rng) {
  WorldBuild build;
  std::vector<std::pair<std::shared_ptr<ChangingGround>, b2Body*>> changing;
  int lane = 0;
  for (const Ground& g : kGrounds) {
    for (const Launch& l : kLaunches) {
      const float top = -kTilesLaneGap * static_cast<float>(lane++);
      const bool rolling = std::string(l.body) == "wheel";
      const auto ground = add_ground(world, g, top, rolling ? slider_rubber : slider_ice);
      const float x = kLaunchOffset + jitter(rng, kLaunchJitter);
      build.sliders.push_back(launch_slider(world, l.body, g.name, x, top, l.speed));
      if (ground) {
        update_changing(*ground, x);
        changing.emplace_back(ground, build.sliders.back().body);
      }
    }
  }
  build.before_step = [changing](int) {
    for (const auto& [ground, slider] : changing) update_changing(*ground, slider->GetPosition().x);
  };
  return build;
}

}  // namespace dyop::scenes::detail
