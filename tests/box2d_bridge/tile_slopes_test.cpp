// `TileGround`'s slope cells: every kind, and every neighbourhood of kinds, covers its part of the
// grid once with fixtures Box2D takes and edge data fixed as the rule finds it; on ramps the slope
// faces meeting flat tops and other slopes are internal where they meet, a convex joint's corner
// being the only open vertex; an edit gives what a full build gives; and the everyday bodies glide
// up and down 45° and 1:2 ramps and across the four joints of a ramp and a flat (its foot, concave,
// both ways; its crest, convex, both ways), floors and ceilings alike, as far as the contact
// impulses let them (foot) or as over the same outline drawn without seams (crest).
#include <gtest/gtest.h>

#include <box2d/box2d.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "dyop/box2d.hpp"
#include "dyop/box2d_grid.hpp"
#include "dyop/box2d_internal_edges.hpp"
#include "support/level_gliders.hpp"
#include "support/worlds.hpp"

namespace dyop::box2d::testing {
namespace {

constexpr TileKind kAllKinds[] = {TileKind::Empty,
                                  TileKind::Solid,
                                  TileKind::FloorRising,
                                  TileKind::FloorFalling,
                                  TileKind::CeilingRising,
                                  TileKind::CeilingFalling,
                                  TileKind::GentleFloorRisingLow,
                                  TileKind::GentleFloorRisingHigh,
                                  TileKind::GentleFloorFallingHigh,
                                  TileKind::GentleFloorFallingLow,
                                  TileKind::GentleCeilingRisingLow,
                                  TileKind::GentleCeilingRisingHigh,
                                  TileKind::GentleCeilingFallingHigh,
                                  TileKind::GentleCeilingFallingLow};

bool same(TileSurface s, TileSurface t) {
  return s.left == t.left && s.right == t.right && s.ceiling == t.ceiling;
}

// The kind whose surface is `s`; a full cell (a floor at the top, a ceiling at the bottom) is
// `Solid`, an empty one `Empty`.
TileKind kind_of(TileSurface s) {
  if (s.left == s.right && (s.left == 0 || s.left == 2)) {
    return (s.left == 2) != s.ceiling ? TileKind::Solid : TileKind::Empty;
  }
  for (const TileKind k : kAllKinds) {
    if (same(tile_surface(k), s)) return k;
  }
  ADD_FAILURE() << "no kind for " << s.left << ", " << s.right << ", " << s.ceiling;
  return TileKind::Empty;
}

// `k` mirrored left to right (`across`) and upside down (`upside_down`).
TileKind mirrored(TileKind k, bool across, bool upside_down) {
  TileSurface s = tile_surface(k);
  if (across) std::swap(s.left, s.right);
  if (upside_down) s = {2 - s.left, 2 - s.right, !s.ceiling};
  return kind_of(s);
}

// True when point (u, v) of a cell (cell units, inside it) lies in the ground of kind `k`.
bool in_ground(TileKind k, float u, float v) {
  const TileSurface s = tile_surface(k);
  const float height =
      0.5f * (static_cast<float>(s.left) + static_cast<float>(s.right - s.left) * u);
  return s.ceiling ? v > height : v < height;
}

// How many fixtures of `ground` hold point (u, v) of cell (column, row), found through the world's
// broad phase.
int fixtures_at(const TileGround& ground, int column, int row, float u, float v) {
  const GridLayout& g = ground.layout();
  const b2Vec2 local(g.origin.x + g.cell * (static_cast<float>(column) + u),
                     g.origin.y + g.cell * (static_cast<float>(row) + v));
  const std::vector<b2Fixture*> fixtures = ground.fixtures();
  if (fixtures.empty()) return 0;
  const b2Body& body = *fixtures.front()->GetBody();
  const b2Vec2 p = body.GetWorldPoint(local);
  struct Count : b2QueryCallback {
    b2Vec2 p;
    const b2Body* body;
    int n = 0;
    bool ReportFixture(b2Fixture* f) override {
      n += f->GetBody() == body && f->TestPoint(p);
      return true;
    }
  } count;
  count.p = p;
  count.body = &body;
  b2AABB box;
  box.lowerBound = p - b2Vec2(1e-4f, 1e-4f);
  box.upperBound = p + b2Vec2(1e-4f, 1e-4f);
  body.GetWorld()->QueryAABB(&count, box);
  return count.n;
}

// Every cell's ground held by one fixture and the rest of it by none (points off the cells' lines
// and diagonals), every fixture a convex polygon of at most 7 vertices (its edge data kept in its
// shape) with its edge data fixed as the rule finds it.
void expect_every_kind_covered(const TileGround& ground) {
  const GridLayout& g = ground.layout();
  for (int r = 0; r < g.rows; ++r) {
    for (int c = 0; c < g.columns; ++c) {
      for (const float u : {0.1f, 0.37f, 0.63f, 0.9f}) {
        for (const float v : {0.07f, 0.31f, 0.44f, 0.56f, 0.69f, 0.93f}) {
          ASSERT_EQ(fixtures_at(ground, c, r, u, v), in_ground(ground.kind(c, r), u, v) ? 1 : 0)
              << "cell " << c << ", " << r << " at " << u << ", " << v;
        }
      }
    }
  }
  for (const b2Fixture* f : ground.fixtures()) {
    ASSERT_EQ(f->GetType(), b2Shape::e_polygon);
    const int count = static_cast<const b2PolygonShape*>(f->GetShape())->m_count;
    EXPECT_GE(count, 3);
    EXPECT_LE(count, 7);
    const std::optional<ShapeMasks> fixed = fixed_polygon_edges(*f);
    ASSERT_TRUE(fixed.has_value());
    EXPECT_EQ(*fixed, polygon_internal_edges(*f));
  }
}

TEST(TileSlopes, KindsAreTheBytesOfTheMapAndTheSurfacesTheHeaderNames) {
  EXPECT_EQ(tile_kind(0), TileKind::Empty);
  EXPECT_EQ(tile_kind(1), TileKind::Solid);
  EXPECT_EQ(tile_kind(2), TileKind::FloorRising);
  EXPECT_EQ(tile_kind(13), TileKind::GentleCeilingFallingLow);
  for (const int solid : {14, 100, 255}) {
    EXPECT_EQ(tile_kind(static_cast<std::uint8_t>(solid)), TileKind::Solid) << solid;
  }
  EXPECT_TRUE(same(tile_surface(TileKind::Solid), {2, 2, false}));
  EXPECT_TRUE(same(tile_surface(TileKind::FloorRising), {0, 2, false}));
  EXPECT_TRUE(same(tile_surface(TileKind::CeilingFalling), {2, 0, true}));
  EXPECT_TRUE(same(tile_surface(TileKind::GentleFloorRisingHigh), {1, 2, false}));
  EXPECT_TRUE(same(tile_surface(TileKind::GentleCeilingFallingLow), {1, 0, true}));
  EXPECT_EQ(mirrored(TileKind::FloorRising, true, false), TileKind::FloorFalling);
  EXPECT_EQ(mirrored(TileKind::FloorRising, false, true), TileKind::CeilingFalling);
  EXPECT_EQ(mirrored(TileKind::GentleFloorRisingLow, true, false), TileKind::GentleFloorFallingLow);
  EXPECT_EQ(mirrored(TileKind::GentleFloorRisingLow, false, true),
            TileKind::GentleCeilingFallingHigh);
  EXPECT_EQ(mirrored(TileKind::Solid, true, true), TileKind::Solid);
}

// Each kind alone and amid full cells, then every row of three kinds side by side (the most a
// piece joins), in a turned body off the origin, the third kind in the next chunk so that pieces
// reach across chunks.
TEST(TileSlopes, EveryKindAndNeighbourhoodIsCoveredOnceWithFixedEdgeData) {
  for (const TileKind k : kAllKinds) {
    for (const bool surrounded : {false, true}) {
      World world;
      b2Body* body = add_body(world, b2_staticBody, b2Vec2(3.0f, -2.0f), 0.3f);
      TileGround ground(*body, {3, 3, 0.5f, b2Vec2(-1, 0), 8});
      std::vector<std::uint8_t> cells(9, surrounded ? 1 : 0);
      cells[4] = static_cast<std::uint8_t>(k);
      ASSERT_EQ(ground.set_cells(cells), GridError::None);
      EXPECT_EQ(ground.kind(1, 1), k);
      EXPECT_EQ(ground.solid(1, 1), k != TileKind::Empty);
      expect_every_kind_covered(ground);
    }
  }
  constexpr int n = static_cast<int>(std::size(kAllKinds));
  World world;
  b2Body* body = add_body(world, b2_staticBody, b2Vec2(-40.0f, 7.0f), -1.1f);
  std::vector<std::uint8_t> cells;
  for (const TileKind a : kAllKinds) {
    for (const TileKind b : kAllKinds) {
      for (const TileKind c : kAllKinds) {
        cells.insert(cells.end(), {0, 0, static_cast<std::uint8_t>(a), static_cast<std::uint8_t>(b),
                                   static_cast<std::uint8_t>(c)});
      }
    }
  }
  TileGround ground(*body, {5, n * n * n, 0.25f, b2Vec2(1, 2), 4});
  ASSERT_EQ(ground.set_cells(cells), GridError::None);
  expect_every_kind_covered(ground);
}

// A ramp between two flats, described in its canonical frame — a floor rising to the right, its
// foot at (0, 0), its crest at (run, rise) — and built mirrored left to right (`across`: a floor
// falling to the right) and upside down (`upside_down`: a ceiling, gravity reversed): as a tile
// map, or as the same outline without seams (`seamless`: the ramp and the high flat one convex
// polygon, the low flat a box beside it).
struct RampCase {
  bool gentle;       // 1:2 (two cells a row), else 45°
  bool across;       // mirrored left to right
  bool upside_down;  // a ceiling under gravity reversed
};

constexpr float kRampCell = 0.25f;     // metres
constexpr int kRampRise = 32;          // rows the ramp climbs (8 m)
constexpr int kRampBase = 2;           // full rows under the low flat
constexpr int kRampFlat = 64;          // columns of each flat (16 m)
constexpr float kRampGravity = 10.0f;  // m/s²

class Ramp {
 public:
  Ramp(World& world, const RampCase& c, bool seamless = false) : case_(c) {
    body_ = add_body(world, b2_staticBody, b2Vec2(0, 0));
    if (seamless) {
      add_seamless(world);
    } else {
      add_tiles();
    }
  }

  // The gravity of the case: down, or up for a ceiling.
  static b2Vec2 gravity(const RampCase& c) {
    return b2Vec2(0, c.upside_down ? kRampGravity : -kRampGravity);
  }
  // Canonical frame to world and back (a mirror is its own inverse).
  b2Vec2 to_world(const b2Vec2& p) const {
    return b2Vec2(case_.across ? -p.x : p.x, case_.upside_down ? -p.y : p.y);
  }
  b2Vec2 to_canonical(const b2Vec2& p) const { return to_world(p); }

  float angle() const { return std::atan2(1.0f, case_.gentle ? 2.0f : 1.0f); }  // of the slope
  float run() const { return kRampRise * kRampCell * (case_.gentle ? 2.0f : 1.0f); }
  float rise() const { return kRampRise * kRampCell; }
  float length() const { return std::hypot(run(), rise()); }  // along the slope
  float flat() const { return kRampFlat * kRampCell; }
  b2Vec2 along() const { return b2Vec2(std::cos(angle()), std::sin(angle())); }  // up the slope
  float slope_gravity() const { return kRampGravity * std::sin(angle()); }       // down the slope

  // A glider of kind `kind` lying on the ground at canonical point `p`, turned as the slope
  // (`on_slope`) or level, moving at canonical velocity `v`.
  b2Body* add_glider(World& world, LevelBody kind, const b2Vec2& p, bool on_slope,
                     const b2Vec2& v) const {
    b2Body* body = add_level_glider(world, kind, !case_.upside_down);
    const float a = on_slope ? angle() : 0.0f;
    body->SetTransform(to_world(p), case_.across != case_.upside_down ? -a : a);
    body->SetLinearVelocity(to_world(v));
    return body;
  }

  const TileGround& ground() const { return *ground_; }

 private:
  void add_tiles() {
    const int ramp_columns = kRampRise * (case_.gentle ? 2 : 1);
    const int columns = 2 * kRampFlat + ramp_columns;
    const int rows = kRampBase + kRampRise;
    std::vector<std::uint8_t> cells(static_cast<std::size_t>(columns * rows), 0);
    const auto set = [&](int i, int j, TileKind k) {  // canonical cell (i, j)
      const int column = case_.across ? columns - 1 - i : i;
      const int row = case_.upside_down ? rows - 1 - j : j;
      cells[static_cast<std::size_t>(row * columns + column)] =
          static_cast<std::uint8_t>(mirrored(k, case_.across, case_.upside_down));
    };
    for (int i = 0; i < columns; ++i) {
      const int k = i - kRampFlat;  // column of the ramp
      const int climbed = std::clamp(case_.gentle ? k / 2 : k, 0, kRampRise);
      for (int j = 0; j < kRampBase + climbed; ++j) set(i, j, TileKind::Solid);
      if (k < 0 || k >= ramp_columns) continue;
      const TileKind top = !case_.gentle ? TileKind::FloorRising
                           : k % 2 == 0  ? TileKind::GentleFloorRisingLow
                                         : TileKind::GentleFloorRisingHigh;
      set(i, kRampBase + climbed, top);
    }
    const b2Vec2 low(-flat(), -kRampBase * kRampCell);  // the map's canonical corners
    const b2Vec2 high =
        low + kRampCell * b2Vec2(static_cast<float>(columns), static_cast<float>(rows));
    ground_ = std::make_unique<TileGround>(
        *body_, GridLayout{columns, rows, kRampCell, b2Min(to_world(low), to_world(high)), 8});
    EXPECT_EQ(ground_->set_cells(cells), GridError::None);
  }

  void add_seamless(World& world) {
    const float bottom = -kRampBase * kRampCell;
    const auto add = [&](std::vector<b2Vec2> points) {
      for (b2Vec2& p : points) p = to_world(p);
      b2PolygonShape shape;
      shape.Set(points.data(), static_cast<int>(points.size()));
      b2FixtureDef def;
      def.shape = &shape;
      def.friction = 0;
      body_->CreateFixture(&def);
    };
    add({b2Vec2(0, 0), b2Vec2(0, bottom), b2Vec2(run() + flat(), bottom),
         b2Vec2(run() + flat(), rise()), b2Vec2(run(), rise())});
    add({b2Vec2(-flat(), bottom), b2Vec2(0, bottom), b2Vec2(0, 0), b2Vec2(-flat(), 0)});
    fix_internal_edges(world.get());
  }

  RampCase case_;
  b2Body* body_ = nullptr;
  std::unique_ptr<TileGround> ground_;
};

std::string ramp_name(const RampCase& c) {
  return std::string(c.gentle ? "1:2 " : "45° ") + (c.upside_down ? "ceiling " : "floor ") +
         (c.across != c.upside_down ? "falling" : "rising");
}

constexpr RampCase kRampCases[] = {
    {false, false, false}, {false, true, false}, {false, false, true}, {false, true, true},
    {true, false, false},  {true, true, false},  {true, false, true},  {true, true, true}};

// On every ramp, in the canonical frame: an edge is internal unless it lies on the outline (the
// low flat, the slope, the high flat, the map's sides and bottom), and a vertex is closed unless
// it is a convex corner of the outline (the crest and the map's four corners).
TEST(TileSlopes, SlopeFacesMeetingFlatTopsAndOtherSlopesAreInternalWhereTheyMeet) {
  for (const RampCase& c : kRampCases) {
    World world;
    const Ramp ramp(world, c);
    const float bottom = -kRampBase * kRampCell;
    const float left = -ramp.flat(), right = ramp.run() + ramp.flat();
    constexpr float kNear = 1e-4f;
    const auto on_outline = [&](const b2Vec2& p) {
      const float surface = std::clamp(p.x * ramp.rise() / ramp.run(), 0.0f, ramp.rise());
      return std::abs(p.y - surface) < kNear || std::abs(p.y - bottom) < kNear ||
             std::abs(p.x - left) < kNear || std::abs(p.x - right) < kNear;
    };
    const auto convex_corner = [&](const b2Vec2& p) {
      for (const b2Vec2& q :
           {b2Vec2(ramp.run(), ramp.rise()), b2Vec2(left, 0), b2Vec2(left, bottom),
            b2Vec2(right, ramp.rise()), b2Vec2(right, bottom)}) {
        if (b2Distance(p, q) < kNear) return true;
      }
      return false;
    };
    int outline_edges = 0;
    for (const b2Fixture* f : ramp.ground().fixtures()) {
      const auto* shape = static_cast<const b2PolygonShape*>(f->GetShape());
      const ShapeMasks m = *fixed_polygon_edges(*f);
      for (int i = 0; i < shape->m_count; ++i) {
        const b2Vec2 p = ramp.to_canonical(shape->m_vertices[i]);
        const b2Vec2 q = ramp.to_canonical(shape->m_vertices[(i + 1) % shape->m_count]);
        const bool outline = on_outline(p) && on_outline(q) && on_outline(0.5f * (p + q));
        outline_edges += outline;
        EXPECT_EQ((m.edges >> i) & 1, outline ? 0 : 1)
            << ramp_name(c) << ": edge " << p.x << ", " << p.y << " to " << q.x << ", " << q.y;
        EXPECT_EQ((m.closed_vertices >> i) & 1, convex_corner(p) ? 0 : 1)
            << ramp_name(c) << ": vertex " << p.x << ", " << p.y;
      }
    }
    EXPECT_GT(outline_edges, kRampRise) << ramp_name(c);  // a face at least per slope row
  }
}

// A glider's state after each step, in the ramp's canonical frame: its body origin (the middle of
// its bottom) and its velocity.
struct Sample {
  b2Vec2 p, v;
};

// Steps `world` for at most `seconds` and records `body`, stopping once it is within 1 m of the
// map's ends (beyond them it would fall off).
std::vector<Sample> record(World& world, const Ramp& ramp, b2Body* body, float seconds) {
  std::vector<Sample> out;
  const int steps = static_cast<int>(seconds * kStepsPerSecond);
  for (int i = 0; i < steps; ++i) {
    world.step();
    const Sample s{ramp.to_canonical(body->GetPosition()),
                   ramp.to_canonical(body->GetLinearVelocity())};
    out.push_back(s);
    if (s.p.x < 1.0f - ramp.flat() || s.p.x > ramp.run() + ramp.flat() - 1.0f) break;
  }
  return out;
}

// The first sample from `from` on that meets `test`, or the number of samples.
template <class Test>
int first(const std::vector<Sample>& samples, int from, Test test) {
  int i = std::max(from, 0);
  while (i < static_cast<int>(samples.size()) && !test(samples[static_cast<std::size_t>(i)])) ++i;
  return i;
}

// A glide over samples [from, to) along a stretch of ground with unit tangent `tangent`, along
// which gravity pulls by `pull` (m/s²): the largest speed along the ground's normal, and the path
// travelled along the tangent against the frictionless path from the state at `from` (integrated
// as Box2D does: the speed first, then the position).
struct Glide {
  float normal = 0;  // m/s
  float travel = 0;  // share of the frictionless path
  int samples = 0;
};

Glide glide(const std::vector<Sample>& samples, int from, int to, const b2Vec2& tangent,
            float pull) {
  Glide g;
  to = std::min(to, static_cast<int>(samples.size()));
  if (from < 0 || to - from < 2) return g;
  const b2Vec2 normal(-tangent.y, tangent.x);
  float speed = b2Dot(samples[static_cast<std::size_t>(from)].v, tangent);
  float ideal = 0, actual = 0;
  for (int i = from + 1; i < to; ++i) {
    const Sample& s = samples[static_cast<std::size_t>(i)];
    speed += pull / kStepsPerSecond;
    ideal += std::abs(speed) / kStepsPerSecond;
    actual += std::abs(b2Dot(s.p - samples[static_cast<std::size_t>(i - 1)].p, tangent));
    g.normal = std::max(g.normal, std::abs(b2Dot(s.v, normal)));
  }
  g.travel = ideal > 0 ? actual / ideal : 0;
  g.samples = to - from;
  return g;
}

constexpr LevelBody kLevelBodies[] = {LevelBody::TriangleBox, LevelBody::Box, LevelBody::Hexagon,
                                      LevelBody::Ball};

std::string level_body_name(LevelBody b) {
  static const char* names[] = {"TriangleBox", "Box", "Hexagon", "Ball"};
  return names[static_cast<int>(b)];
}

// Steps a launched body needs to settle on the ground (0.25 s): the position solver lifts it out
// of the skins it starts in.
constexpr int kLaunchSettle = 15;
// Steps after a joint before a body counts as settled on the stretch beyond it (0.75 s): a polygon
// that took the joint on a corner rocks onto a face meanwhile (a hexagon takes the longest).
constexpr int kJointSettle = 45;

class RampGlide : public ::testing::TestWithParam<LevelBody> {};

// Launched up the slope at 4 m/s from 1 m above the foot: the body climbs and slides back down as
// on a frictionless plane, until the frictionless body is back where it started.
TEST_P(RampGlide, BodiesGlideUpAndDownEveryRampAsOnAFrictionlessPlane) {
  const LevelBody kind = GetParam();
  ASSERT_TRUE(install(Backend::Dyop).ok());
  for (const RampCase& c : kRampCases) {
    World world(Ramp::gravity(c));
    const Ramp ramp(world, c);
    b2Body* body =
        ramp.add_glider(world, kind, 1.0f * ramp.along(), true, kLevelPushSpeed * ramp.along());
    const float back = 2 * kLevelPushSpeed / ramp.slope_gravity();  // s, up and down again
    const std::vector<Sample> samples = record(world, ramp, body, back);
    const Glide g = glide(samples, kLaunchSettle, static_cast<int>(samples.size()), ramp.along(),
                          -ramp.slope_gravity());
    std::printf("%s on the %s ramp: %.4f m/s across it, %.2f %% of the glide\n", name(kind),
                ramp_name(c).c_str(), g.normal, 100 * g.travel);
    EXPECT_LE(g.normal, kLevelGlideVertical) << ramp_name(c);
    EXPECT_GE(g.travel, kLevelGlideTravel) << ramp_name(c);
  }
  ASSERT_TRUE(uninstall().ok());
}

INSTANTIATE_TEST_SUITE_P(EveryBody, RampGlide, ::testing::ValuesIn(kLevelBodies),
                         [](const auto& info) { return level_body_name(info.param); });

// The joints where a ramp meets a flat, crossed either way.
enum class Joint {
  FootDown,  // concave: down the slope onto the low flat
  FootUp,    // concave: from the low flat up the slope
  Crest,     // convex: up the slope onto the high flat
  Brink,     // convex: from the high flat down the slope
};

const char* name(Joint j) {
  static const char* names[] = {"FootDown", "FootUp", "Crest", "Brink"};
  return names[static_cast<int>(j)];
}

// A body across a joint: its glide on the stretch beyond, once settled, and the speed it kept
// there against what it should have (`Crossing::bound`).
struct Crossing {
  Glide glide;
  float kept = 0;   // m/s
  float bound = 0;  // m/s; for a convex joint, set from the seamless ground's crossing
};

Crossing cross(Joint joint, const RampCase& c, LevelBody kind, bool seamless = false) {
  World world(Ramp::gravity(c));
  const Ramp ramp(world, c, seamless);
  const b2Vec2 level(1, 0);
  const int settle = kJointSettle;
  Crossing out;
  switch (joint) {
    case Joint::FootDown: {
      // From rest 3 m up the slope. The flat pushes only up and the slope only forward, so the
      // speed along the flat is at least the part along it of the speed the slope gave.
      b2Body* body = ramp.add_glider(world, kind, 3.0f * ramp.along(), true, b2Vec2(0, 0));
      const std::vector<Sample> samples = record(world, ramp, body, 4.0f);
      const int past = first(samples, 0, [](const Sample& s) { return s.p.x < -0.5f; });
      for (int i = 0; i < past; ++i) {
        out.bound = std::max(out.bound, samples[static_cast<std::size_t>(i)].v.Length());
      }
      out.bound *= std::cos(ramp.angle());
      out.glide = glide(samples, past + settle, static_cast<int>(samples.size()), -level, 0);
      if (past + settle < static_cast<int>(samples.size())) {
        out.kept = -samples[static_cast<std::size_t>(past + settle)].v.x;
      }
      return out;
    }
    case Joint::FootUp: {
      // Pushed at 7 m/s along the low flat. The slope pushes only along its normal and the flat
      // only up, so the speed up the slope, plus what gravity has taken since the impact, is at
      // least the part along the slope of the push. Glides up and back to 1 m above the foot.
      constexpr float kPush = 7.0f;
      b2Body* body = ramp.add_glider(world, kind, b2Vec2(-3, 0), false, b2Vec2(kPush, 0));
      const std::vector<Sample> samples = record(world, ramp, body, 4.0f);
      const int impact = first(samples, 0, [&](const Sample& s) { return s.v.x < kPush - 0.01f; });
      const int settled = impact + settle;
      const int back =
          first(samples, settled, [&](const Sample& s) { return b2Dot(s.p, ramp.along()) < 1.0f; });
      out.glide = glide(samples, settled, back, ramp.along(), -ramp.slope_gravity());
      if (settled < static_cast<int>(samples.size())) {
        out.kept = b2Dot(samples[static_cast<std::size_t>(settled)].v, ramp.along()) +
                   ramp.slope_gravity() * static_cast<float>(settle + 1) / kStepsPerSecond;
      }
      out.bound = kPush * std::cos(ramp.angle());
      return out;
    }
    case Joint::Crest: {
      // Up the slope from 2 m below the crest, at 4 m/s there: each body flies over the crest
      // and lands on a face (faster, a hexagon lands on a vertex and tumbles on the seamless
      // ground too).
      const float speed = std::sqrt(16.0f + 4.0f * ramp.slope_gravity());
      b2Body* body = ramp.add_glider(world, kind, (ramp.length() - 2.0f) * ramp.along(), true,
                                     speed * ramp.along());
      const std::vector<Sample> samples = record(world, ramp, body, 4.0f);
      const int past =
          first(samples, 0, [&](const Sample& s) { return s.p.x > ramp.run() + 0.5f; });
      out.glide = glide(samples, past + settle, static_cast<int>(samples.size()), level, 0);
      if (past + settle < static_cast<int>(samples.size())) {
        out.kept = samples[static_cast<std::size_t>(past + settle)].v.x;
      }
      return out;
    }
    case Joint::Brink: {
      // At 2 m/s along the high flat 3 m from the brink, over it and down the slope to 1 m above
      // the foot; the speed kept is the one there.
      b2Body* body = ramp.add_glider(world, kind, b2Vec2(ramp.run() + 3.0f, ramp.rise()), false,
                                     b2Vec2(-2.0f, 0));
      const std::vector<Sample> samples = record(world, ramp, body, 4.0f);
      const int past =
          first(samples, 0, [&](const Sample& s) { return s.p.x < ramp.run() - 0.5f; });
      const int foot = first(samples, past + settle,
                             [&](const Sample& s) { return b2Dot(s.p, ramp.along()) < 1.0f; });
      out.glide = glide(samples, past + settle, foot, -ramp.along(), ramp.slope_gravity());
      if (foot < static_cast<int>(samples.size())) {
        // Its speed as it passed the mark (the sample is up to a step beyond it), by the energy
        // of a frictionless slide.
        const Sample& at = samples[static_cast<std::size_t>(foot)];
        const float u = b2Dot(at.v, ramp.along());
        const float beyond = 1.0f - b2Dot(at.p, ramp.along());
        out.kept = std::sqrt(std::max(0.0f, u * u - 2 * ramp.slope_gravity() * beyond));
      }
      return out;
    }
  }
  return out;
}

struct JointCase {
  Joint joint;
  LevelBody body;
};

class RampJoints : public ::testing::TestWithParam<JointCase> {};

// Across each joint of every ramp: once settled beyond it, the body glides (no speed along the
// ground's normal, the frictionless travel) and has kept the speed the joint leaves it: at a foot
// what the contact impulses allow at least, at a crest what it keeps over the same outline drawn
// without seams.
TEST_P(RampJoints, BodiesCrossEveryJointOfRampAndFlatAndGlideOn) {
  const JointCase j = GetParam();
  ASSERT_TRUE(install(Backend::Dyop).ok());
  for (const RampCase& c : kRampCases) {
    const Crossing x = cross(j.joint, c, j.body);
    float bound = x.bound;
    if (j.joint == Joint::Crest || j.joint == Joint::Brink) {
      bound = cross(j.joint, c, j.body, true).kept;
    }
    std::printf(
        "%s across the %s ramp's %s: %d samples settled, %.4f m/s across, %.2f %% of the "
        "glide; kept %.4f m/s of %.4f\n",
        name(j.body), ramp_name(c).c_str(), name(j.joint), x.glide.samples, x.glide.normal,
        100 * x.glide.travel, x.kept, bound);
    EXPECT_GE(x.glide.samples, 20) << ramp_name(c);
    EXPECT_LE(x.glide.normal, kLevelGlideVertical) << ramp_name(c);
    EXPECT_GE(x.glide.travel, kLevelGlideTravel) << ramp_name(c);
    EXPECT_GE(x.kept, kLevelGlideTravel * bound) << ramp_name(c);
  }
  ASSERT_TRUE(uninstall().ok());
}

std::vector<JointCase> all_joint_cases() {
  std::vector<JointCase> out;
  for (const Joint j : {Joint::FootDown, Joint::FootUp, Joint::Crest, Joint::Brink}) {
    for (const LevelBody b : kLevelBodies) out.push_back({j, b});
  }
  return out;
}

INSTANTIATE_TEST_SUITE_P(EveryBody, RampJoints, ::testing::ValuesIn(all_joint_cases()),
                         [](const auto& info) {
                           return std::string(name(info.param.joint)) + "_" +
                                  level_body_name(info.param.body);
                         });

// Every fixture of `ground` by its vertices in the body frame (rounded to 0.1 mm), sorted: what
// two builds of one map must share.
std::vector<std::vector<std::array<long, 2>>> shapes_of(const TileGround& ground) {
  std::vector<std::vector<std::array<long, 2>>> out;
  for (const b2Fixture* f : ground.fixtures()) {
    const auto* shape = static_cast<const b2PolygonShape*>(f->GetShape());
    std::vector<std::array<long, 2>> points;
    for (int i = 0; i < shape->m_count; ++i) {
      points.push_back(
          {std::lround(shape->m_vertices[i].x * 1e4f), std::lround(shape->m_vertices[i].y * 1e4f)});
    }
    std::sort(points.begin(), points.end());
    out.push_back(points);
  }
  std::sort(out.begin(), out.end());
  return out;
}

// Random edits of kinds (seeded) on a map in chunks of three columns: after each, the ground is
// the one a full build of its cells makes, covered exactly with its edge data fixed; chunks far
// from the edit keep their fixtures.
TEST(TileSlopes, EditsOfKindsGiveWhatAFullBuildGives) {
  constexpr int kColumns = 12, kRows = 4;
  World world;
  b2Body* body = add_body(world, b2_staticBody, b2Vec2(1.0f, 2.0f), 0.2f);
  TileGround ground(*body, {kColumns, kRows, 0.5f, b2Vec2(-3, -1), 3});
  std::vector<std::uint8_t> cells(kColumns * kRows, 1);
  ASSERT_EQ(ground.set_cells(cells), GridError::None);
  std::mt19937 rng(63);
  std::uniform_int_distribution<int> column(0, kColumns - 1), row(0, kRows - 1),
      kind(0, static_cast<int>(std::size(kAllKinds)) - 1);
  const GridLayout& g = ground.layout();
  for (int edit = 0; edit < 300; ++edit) {
    const int c = column(rng), r = row(rng);
    const TileKind k = kAllKinds[kind(rng)];
    // The fixtures wholly more than a chunk and two cells away from the cell (a piece's reach).
    std::vector<b2Fixture*> far;
    for (b2Fixture* f : ground.fixtures()) {
      const auto* shape = static_cast<const b2PolygonShape*>(f->GetShape());
      float lo = 1e9f, hi = -1e9f;
      for (int i = 0; i < shape->m_count; ++i) {
        lo = std::min(lo, (shape->m_vertices[i].x - g.origin.x) / g.cell);
        hi = std::max(hi, (shape->m_vertices[i].x - g.origin.x) / g.cell);
      }
      const float reach = static_cast<float>(g.chunk + 2);
      if (hi < static_cast<float>(c) - reach || lo > static_cast<float>(c + 1) + reach) {
        far.push_back(f);
      }
    }
    ASSERT_EQ(ground.set_cell(c, r, k), GridError::None);
    const std::vector<b2Fixture*> now = ground.fixtures();
    for (const b2Fixture* f : far) {
      EXPECT_NE(std::find(now.begin(), now.end(), f), now.end()) << "edit " << edit;
    }
    cells[static_cast<std::size_t>(r * kColumns + c)] = static_cast<std::uint8_t>(k);
    ASSERT_EQ(ground.kind(c, r), k);
    World fresh_world;
    TileGround fresh(*add_body(fresh_world, b2_staticBody, b2Vec2(1.0f, 2.0f), 0.2f),
                     ground.layout());
    ASSERT_EQ(fresh.set_cells(cells), GridError::None);
    ASSERT_EQ(shapes_of(ground), shapes_of(fresh))
        << "edit " << edit << ": cell " << c << ", " << r << " made " << static_cast<int>(k);
    expect_every_kind_covered(ground);
  }
  // `true` fills a slope cell, `false` digs it.
  ASSERT_EQ(ground.set_cell(4, 2, TileKind::FloorRising), GridError::None);
  const std::vector<b2Fixture*> kept = ground.fixtures();
  ASSERT_EQ(ground.set_cell(4, 2, TileKind::FloorRising), GridError::None);
  EXPECT_EQ(ground.fixtures(), kept);
  ASSERT_EQ(ground.set_cell(4, 2, true), GridError::None);
  EXPECT_EQ(ground.kind(4, 2), TileKind::Solid);
  ASSERT_EQ(ground.set_cell(4, 2, false), GridError::None);
  EXPECT_EQ(ground.kind(4, 2), TileKind::Empty);
}

// Far from the body origin, half a small cell is below float's resolution: a slope cell is refused
// (`SlopeShape`) where full cells are still taken as before, and a refusal changes nothing.
TEST(TileSlopes, SlopesFloatCannotPlaceAreRefusedAndChangeNothing) {
  World world;
  b2Body* body = add_body(world, b2_staticBody, b2Vec2(0, 0));
  TileGround ground(*body, {4, 2, 0.02f, b2Vec2(1e6f, 0), 8});
  std::vector<std::uint8_t> cells(8, 1);
  ASSERT_EQ(ground.set_cells(cells), GridError::None);
  const std::vector<b2Fixture*> before = ground.fixtures();
  EXPECT_EQ(ground.set_cell(1, 1, TileKind::FloorRising), GridError::SlopeShape);
  EXPECT_EQ(ground.kind(1, 1), TileKind::Solid);
  EXPECT_EQ(ground.fixtures(), before);
  cells[5] = static_cast<std::uint8_t>(TileKind::GentleFloorRisingHigh);
  EXPECT_EQ(ground.set_cells(cells), GridError::SlopeShape);
  EXPECT_EQ(ground.kind(1, 1), TileKind::Solid);
  EXPECT_EQ(ground.fixtures(), before);
  EXPECT_STRNE(describe(GridError::SlopeShape), describe(GridError::None));
}

}  // namespace
}  // namespace dyop::box2d::testing
