// `OutlineTerrain`: a level's outline held in chunks of triangles. Bodies glide across the chunks'
// seams; the edge data is what the rule finds, within chunks and across them, and only the
// ground's outline is open; a crater under resting bodies drops those above it, leaves the far
// ones still and nobody inside the ground; a listener sees what the header says; streaming keeps
// the edits and keeps fixtures and proxies to the loaded chunks; bad input is refused by name with
// nothing changed; and no order of calls breaks it.
#include <gtest/gtest.h>

#include <box2d/box2d.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "dyop/box2d.hpp"
#include "dyop/box2d_internal_edges.hpp"
#include "dyop/box2d_terrain.hpp"
#include "support/level_gliders.hpp"
#include "support/rings.hpp"
#include "support/worlds.hpp"

namespace dyop::box2d::testing {
namespace {
namespace terrain {

constexpr float kVertexSpacing = 0.25f;  // m between the top's vertices

// A flat level: its top y = `top` over [x0, x1] with a vertex every `kVertexSpacing`, its bottom
// `depth` below, counter-clockwise.
Ring flat_level(float x0, float x1, float top, float depth) {
  Ring ring = {{x0, top - depth}, {x1, top - depth}};
  const int n = static_cast<int>(std::lround((x1 - x0) / kVertexSpacing));
  for (int i = n; i >= 0; --i) ring.push_back({x0 + kVertexSpacing * static_cast<float>(i), top});
  return ring;
}

// Small chunks and cells, so that a short run crosses many seams; every vertex kept.
TerrainOptions small_chunks() {
  TerrainOptions o;
  o.chunk = 4;
  o.cell = 1;
  o.simplify = 0;
  o.fixture.friction = 0;
  return o;
}

struct Glide {
  float max_vertical = 0;  // m/s, once settled, over every launch
  float travel = 1;        // least share of the free travel, over every launch
};

// `kind` pushed along a flat terrain whose top is `top`, from every launch point (offsets from a
// chunk's seam at x = 0).
Glide glide(LevelBody kind, float top) {
  Glide g;
  for (const auto& [offset, height] : kLaunchOffsets) {
    World world;
    OutlineTerrain ground(world.get(), small_chunks());
    EXPECT_TRUE(ground.set_outline({flat_level(-4, 24, top, 6)}).ok());
    b2Body* body = add_level_glider(world, kind);
    body->SetTransform(b2Vec2(offset, top + height), 0);
    const int steps = static_cast<int>(kLevelGlideSeconds * kStepsPerSecond);
    for (int step = 0; step < steps; ++step) {
      world.step();
      if (step >= kSettleSteps) {
        g.max_vertical = std::max(g.max_vertical, std::abs(body->GetLinearVelocity().y));
      }
    }
    g.travel = std::min(g.travel,
                        (body->GetPosition().x - offset) / (kLevelPushSpeed * kLevelGlideSeconds));
  }
  return g;
}

class OutlineTerrainSeams : public ::testing::TestWithParam<LevelBody> {};

// A top on a chunk's side (y = 0: the chunks below end there) and a top across the middle of
// chunks (y = 2): the body crosses a seam every 4 m and a cell's side every metre.
TEST_P(OutlineTerrainSeams, EveryBodyGlidesAcrossChunkSeams) {
  ASSERT_TRUE(install(Backend::Dyop).ok());
  for (const float top : {0.0f, 2.0f}) {
    const Glide g = glide(GetParam(), top);
    std::printf("%s across chunk seams, top at y = %.0f: %.4f m/s, %.2f %% of the glide\n",
                name(GetParam()), top, g.max_vertical, 100 * g.travel);
    EXPECT_LE(g.max_vertical, kLevelGlideVertical) << name(GetParam()) << ", top at " << top;
    EXPECT_GE(g.travel, kLevelGlideTravel) << name(GetParam()) << ", top at " << top;
  }
  ASSERT_TRUE(uninstall().ok());
}

INSTANTIATE_TEST_SUITE_P(EveryBody, OutlineTerrainSeams,
                         ::testing::Values(LevelBody::TriangleBox, LevelBody::Box,
                                           LevelBody::Hexagon, LevelBody::Ball),
                         level_body_name);

// The open (not internal) edges of the terrain's fixtures: every fixture's fixed edge data equals
// what the rule finds now; returns the open edges' total length.
double open_length(const OutlineTerrain& terrain) {
  double length = 0;
  for (const b2Fixture* f : terrain.fixtures()) {
    const auto* shape = static_cast<const b2PolygonShape*>(f->GetShape());
    const std::optional<ShapeMasks> fixed = fixed_polygon_edges(*f);
    EXPECT_TRUE(fixed.has_value());
    if (!fixed) continue;
    EXPECT_EQ(*fixed, polygon_internal_edges(*f));
    for (int e = 0; e < 3; ++e) {
      if (!((fixed->edges >> e) & 1)) {
        length += (shape->m_vertices[(e + 1) % 3] - shape->m_vertices[e]).Length();
      }
    }
  }
  return length;
}

// How far the rounding to `terrain_grid` may lengthen or shorten an outline, per metre of it.
constexpr double kRoundingPerMetre = 1e-3;

// A level with a cave and a slanted wall crossing chunks' sides and corners: the edge data of
// every triangle is what the rule finds, and the open edges run along the rings alone (their
// length is the rings' perimeter): every seam between chunks is internal. After a crater across
// a seam and a hole on a corner of four chunks, the same holds with their rims added.
TEST(OutlineTerrainEdgeData, OnlyTheOutlineIsOpenAcrossEveryChunkSeam) {
  World world;
  OutlineTerrain terrain(world.get(), small_chunks());
  const std::vector<Ring> rings = {{{-6, -6}, {10, -6}, {10, 3}, {6, 1}, {-6, 1}},
                                   {{-1, -3}, {3, -3}, {5, -1}, {-1, -1}}};
  ASSERT_TRUE(terrain.set_outline(rings).ok());
  EXPECT_GT(terrain.loaded_chunks(), 8);
  const double outline = perimeter(rings);
  EXPECT_NEAR(open_length(terrain), outline, kRoundingPerMetre * outline);
  // A crater on the seam x = 4, cutting into the top: its rim within the ground is open too.
  const TerrainResult r = terrain.remove(b2Vec2(4, 1), 1.0f);
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_GE(r.chunks, 2);
  // The rim replaces 2 m of top by a half-circle of 1 m radius (within its polygon's error).
  const double with_crater = outline - 2 + b2_pi * 1.0;
  EXPECT_NEAR(open_length(terrain), with_crater, 0.02 + kRoundingPerMetre * with_crater);
  // A hole on the corner (8, 0) of four chunks, wholly inside the ground: its rim is open, every
  // seam through it internal.
  const TerrainResult corner = terrain.remove(b2Vec2(8, 0), 1.0f);
  ASSERT_TRUE(corner.ok()) << corner.message;
  EXPECT_EQ(corner.chunks, 4);
  const double with_hole = with_crater + 2 * b2_pi * 1.0;
  EXPECT_NEAR(open_length(terrain), with_hole, 0.04 + kRoundingPerMetre * with_hole);
}

// A terrain placed and turned by its body definition: edits and loads are in its own frame, and
// the edge data around a crater across a seam, and around a chunk loaded and unloaded, is found
// again where the chunks are in the world.
TEST(OutlineTerrainEdgeData, ATurnedTerrainFindsItsEdgeDataAgainWhereItLies) {
  World world;
  TerrainOptions o = small_chunks();
  o.body.position.Set(40, 30);
  o.body.angle = 0.5f;
  OutlineTerrain terrain(world.get(), o);
  const std::vector<Ring> rings = {rectangle(-6, -6, 10, 1)};
  ASSERT_TRUE(terrain.set_outline(rings).ok());
  ASSERT_TRUE(terrain.remove(b2Vec2(4, 1), 1.0f).ok());
  const double with_crater = perimeter(rings) - 2 + b2_pi * 1.0;
  EXPECT_NEAR(open_length(terrain), with_crater, 0.02 + kRoundingPerMetre * with_crater);
  b2AABB left;  // the chunks x < 4 of the terrain's frame
  left.lowerBound.Set(-6, -6);
  left.upperBound.Set(3, 1);
  ASSERT_TRUE(terrain.load(left).ok());
  ASSERT_LT(terrain.loaded_chunks(), terrain.chunk_count());
  open_length(terrain);  // each loaded triangle's edge data is what the rule finds now
  ASSERT_TRUE(terrain.load_all().ok());
  EXPECT_NEAR(open_length(terrain), with_crater, 0.02 + kRoundingPerMetre * with_crater);
}

// A flat terrain with bodies resting along its top, 1.5 m apart: boxes and balls (friction 0.6).
struct RestingRow {
  World world;
  OutlineTerrain terrain{world.get()};
  std::vector<b2Body*> bodies;
  // `sleeping`: bodies may sleep (as in a game; the tests' worlds keep them awake), and have.
  explicit RestingRow(float x0 = 2, float x1 = 38, bool sleeping = false) {
    world->SetAllowSleeping(sleeping);
    EXPECT_TRUE(terrain.set_outline({flat_level(0, 40, 0, 10)}).ok());
    b2PolygonShape box;
    box.SetAsBox(0.3f, 0.3f);
    b2CircleShape ball;
    ball.m_radius = 0.3f;
    for (float x = x0; x <= x1; x += 1.5f) {
      b2Body* body = add_body(world, b2_dynamicBody, b2Vec2(x, 0.3f));
      b2FixtureDef def;
      def.shape = bodies.size() % 2 ? static_cast<const b2Shape*>(&ball) : &box;
      def.density = 1;
      def.friction = 0.6f;
      body->CreateFixture(&def);
      bodies.push_back(body);
    }
    for (int i = 0; i < 2 * kStepsPerSecond; ++i) world.step();
  }
};

// A crater of 1 m radius dug under a row of resting bodies, awake or asleep: those over it fall in
// and land on its floor (asleep, they are woken); none ends inside the ground or below the
// crater's floor; those 3 m or more from its rim never move (≤ 0.01 m/s); those between lose no
// support (they stay on the top), those on triangles replaced by the edit among them.
TEST(OutlineTerrainEdits, ACraterUnderRestingBodiesDropsThoseAboveItAndNoOneElse) {
  ASSERT_TRUE(install(Backend::Dyop).ok());
  for (const bool sleeping : {false, true}) {
    SCOPED_TRACE(sleeping ? "bodies asleep" : "bodies awake");
    RestingRow row(2, 38, sleeping);
    if (sleeping) {
      for (int i = 0; i < kStepsPerSecond; ++i) row.world.step();
      for (const b2Body* b : row.bodies) ASSERT_FALSE(b->IsAwake());
    }
    const b2Vec2 centre(20.3f, 0);
    constexpr float radius = 1.0f;
    const TerrainResult r = row.terrain.remove(centre, radius);
    ASSERT_TRUE(r.ok()) << r.message;
    std::vector<float> start, vertical(row.bodies.size(), 0);
    for (b2Body* b : row.bodies) start.push_back(b->GetPosition().y);
    for (int i = 0; i < 2 * kStepsPerSecond; ++i) {
      row.world.step();
      for (std::size_t k = 0; k < row.bodies.size(); ++k) {
        vertical[k] = std::max(vertical[k], std::abs(row.bodies[k]->GetLinearVelocity().y));
      }
    }
    float near_worst = 0;
    for (std::size_t k = 0; k < row.bodies.size(); ++k) {
      const b2Body* b = row.bodies[k];
      const float off_centre = std::abs(b->GetPosition().x - centre.x);
      const float gap = off_centre - 0.3f - radius;  // from the body's side to the rim
      EXPECT_FALSE(row.terrain.solid(b->GetPosition())) << "body " << k << " inside the ground";
      EXPECT_LE(skin_penetration(const_cast<b2Body*>(b)), 2 * b2_linearSlop) << "body " << k;
      if (off_centre < radius) {  // its centre over the crater: in it, above its floor
        EXPECT_LT(b->GetPosition().y, start[k] - 0.2f) << "body " << k;
        EXPECT_GT(b->GetPosition().y, centre.y - radius) << "body " << k;
      } else if (gap >= 3) {
        EXPECT_LE(vertical[k], 0.01f) << "body " << k << ", " << gap << " m from the rim";
      } else if (gap >= 0) {  // near, wholly beside it: no support lost
        near_worst = std::max(near_worst, vertical[k]);
        EXPECT_NEAR(b->GetPosition().y, start[k], 0.01f) << "body " << k;
      }
    }
    std::printf(
        "crater, %s: %d triangles destroyed, %d created, %d kept; bodies within 3 m of its "
        "rim: largest vertical speed %.4f m/s\n",
        sleeping ? "bodies asleep" : "bodies awake", r.destroyed, r.created, r.kept, near_worst);
  }
  ASSERT_TRUE(uninstall().ok());
}

// A triangle fixture's points, sorted (to compare triangles whatever their vertex order).
std::vector<float> points_of(const b2Fixture* f) {
  const auto* s = static_cast<const b2PolygonShape*>(f->GetShape());
  std::vector<std::pair<float, float>> p;
  for (int i = 0; i < 3; ++i) p.emplace_back(s->m_vertices[i].x, s->m_vertices[i].y);
  std::sort(p.begin(), p.end());
  return {p[0].first, p[0].second, p[1].first, p[1].second, p[2].first, p[2].second};
}

// An edit triangulates again the cells it touches: every fixture outside them is the same fixture
// with the same triangle after it (Box2D reuses a destroyed fixture's address: the triangle tells);
// the counts add up.
TEST(OutlineTerrainEdits, AnEditRebuildsTheCellsItTouchesAndNothingElse) {
  World world;
  OutlineTerrain terrain(world.get());
  ASSERT_TRUE(terrain.set_outline({flat_level(0, 64, 0, 20)}).ok());
  const std::vector<b2Fixture*> before = terrain.fixtures();
  std::map<const b2Fixture*, std::vector<float>> triangle;
  for (const b2Fixture* f : before) triangle[f] = points_of(f);
  const TerrainResult r = terrain.remove(b2Vec2(33, 0), 1.0f);  // in the cells [32, 34] × [-2, 0]
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_GT(r.destroyed, 0);
  const std::vector<b2Fixture*> after = terrain.fixtures();
  EXPECT_EQ(after.size(), before.size() - r.destroyed + r.created);
  const std::set<const b2Fixture*> now(after.begin(), after.end());
  int outside = 0;
  for (const b2Fixture* f : before) {
    const std::vector<float>& p = triangle[f];  // x, y of its three points, by x
    if (p[0] >= 32 - 1e-3f && p[4] <= 34 + 1e-3f && std::min({p[1], p[3], p[5]}) >= -2 - 1e-3f) {
      continue;  // within the crater's cells
    }
    ++outside;
    EXPECT_EQ(now.count(f), 1u) << "a fixture outside the crater's cells was destroyed";
    if (now.count(f)) {
      EXPECT_EQ(points_of(f), p) << "a fixture outside the crater's cells changed";
    }
  }
  EXPECT_GT(outside, static_cast<int>(before.size()) - 20);
}

// What a contact listener records for one body.
class Events : public b2ContactListener {
 public:
  explicit Events(const b2Body* body) : body_(body) {}
  void BeginContact(b2Contact* c) override {
    if (involves(c)) log += 'B';
  }
  void EndContact(b2Contact* c) override {
    if (involves(c)) log += 'E';
  }
  std::string log;

 private:
  bool involves(const b2Contact* c) const {
    return c->GetFixtureA()->GetBody() == body_ || c->GetFixtureB()->GetBody() == body_;
  }
  const b2Body* body_;
};

// A body on triangles an edit replaces sees EndContact for each of its contacts with them during
// the edit call, and BeginContact with the new triangles in the next step, then nothing; a body on
// triangles the edit does not touch sees nothing at all.
TEST(OutlineTerrainEdits, AListenerSeesEndThenBeginOnReplacedTrianglesAndNothingElsewhere) {
  ASSERT_TRUE(install(Backend::Dyop).ok());
  {
    RestingRow row(17.9f, 30);     // bodies at 17.9, 19.4, 20.9, ...
    b2Body* near = row.bodies[0];  // a box over [17.6, 18.2], 0.1 m beside the crater's rim
    b2Body* far = row.bodies[5];   // x = 25.4: cells away
    Events near_events(near), far_events(far);
    struct Both : b2ContactListener {
      Events* a;
      Events* b;
      void BeginContact(b2Contact* c) override { a->BeginContact(c), b->BeginContact(c); }
      void EndContact(b2Contact* c) override { a->EndContact(c), b->EndContact(c); }
    } both;
    both.a = &near_events;
    both.b = &far_events;
    row.world->SetContactListener(&both);
    const TerrainResult r = row.terrain.remove(b2Vec2(17, -0.2f), 0.5f);  // the cell [16, 18]
    ASSERT_TRUE(r.ok()) << r.message;
    const std::string during = near_events.log;
    row.world.step();
    const std::string next = near_events.log.substr(during.size());
    for (int i = 0; i < kStepsPerSecond; ++i) row.world.step();
    row.world->SetContactListener(nullptr);
    std::printf(
        "listener: body on replaced triangles: \"%s\" during the edit, \"%s\" in the next "
        "step, \"%s\" after\n",
        during.c_str(), next.c_str(), near_events.log.substr(during.size() + next.size()).c_str());
    EXPECT_FALSE(during.empty());
    EXPECT_EQ(during, std::string(during.size(), 'E'));
    EXPECT_FALSE(next.empty());
    EXPECT_EQ(next, std::string(next.size(), 'B'));
    EXPECT_EQ(near_events.log.size(), during.size() + next.size()) << near_events.log;
    EXPECT_EQ(far_events.log, "");
  }
  ASSERT_TRUE(uninstall().ok());
}

// A wall added stands on the ground: a body dropped on it lands on its top; a body asleep where it
// is built (on a platform of its own, whose contact goes on) is woken and pushed out of it;
// removing the wall again gives the ground's area back.
TEST(OutlineTerrainEdits, AWallAddedIsSolidAndRemovedAgainLeavesTheGroundAsItWas) {
  ASSERT_TRUE(install(Backend::Dyop).ok());
  {
    World world;
    world->SetAllowSleeping(true);
    OutlineTerrain terrain(world.get());
    ASSERT_TRUE(terrain.set_outline({flat_level(0, 40, 0, 10)}).ok());
    const double area = terrain.area();
    b2Body* platform = add_body(world, b2_staticBody, b2Vec2(16.5f, 1.9f));
    b2PolygonShape slab;
    slab.SetAsBox(0.5f, 0.1f);
    platform->CreateFixture(&slab, 0);
    b2Body* asleep = add_split_box(world, b2Vec2(16.5f, 2.3f), 0.3f);
    for (int i = 0; i < kStepsPerSecond; ++i) world.step();
    ASSERT_FALSE(asleep->IsAwake());
    const TerrainResult r = terrain.add(rectangle(15, -1, 17, 3));  // 1 m into the ground
    ASSERT_TRUE(r.ok()) << r.message;
    EXPECT_NEAR(terrain.area(), area + 6, 1e-3);
    EXPECT_TRUE(terrain.solid(b2Vec2(16, 2.5f)));
    EXPECT_TRUE(asleep->IsAwake());
    b2Body* dropped = add_split_box(world, b2Vec2(16, 5), 0.3f);
    for (int i = 0; i < 2 * kStepsPerSecond; ++i) world.step();
    EXPECT_NEAR(dropped->GetPosition().y, 3.3f, 0.02f);
    EXPECT_FALSE(terrain.solid(asleep->GetPosition()));
    EXPECT_NEAR(open_length(terrain), perimeter({flat_level(0, 40, 0, 10)}) + 6, 0.05);
    ASSERT_TRUE(terrain.remove(rectangle(15, 0, 17, 3)).ok());
    EXPECT_NEAR(terrain.area(), area, 1e-3);
  }
  ASSERT_TRUE(uninstall().ok());
}

// The number of proxies of the terrain's bodies in the world's broad phase.
int terrain_proxies(const OutlineTerrain& terrain) {
  int n = 0;
  for (const b2Body* body : terrain.bodies()) {
    for (const b2Fixture* f = body->GetFixtureList(); f; f = f->GetNext())
      n += f->GetShape()->GetChildCount();
  }
  return n;
}

// Loading by region: only the chunks overlapping it have bodies, and the world's broad phase holds
// one proxy per triangle of them; unloading leaves none; a camera swept along the level keeps the
// count to the chunks it overlaps.
TEST(OutlineTerrainStreaming, FixturesAndProxiesFollowTheLoadedChunks) {
  World world;
  OutlineTerrain terrain(world.get());
  ASSERT_TRUE(terrain.set_outline({flat_level(0, 160, 0, 20)}).ok());
  ASSERT_EQ(terrain.chunk_count(), 10 * 2);  // x: 10 chunks, y: [-32, -16] and [-16, 0]
  const int all = world->GetProxyCount();
  EXPECT_EQ(all, terrain_proxies(terrain));
  EXPECT_EQ(all, terrain.triangle_count());
  ASSERT_TRUE(terrain.unload().ok());
  EXPECT_EQ(terrain.loaded_chunks(), 0);
  EXPECT_EQ(world->GetProxyCount(), 0);
  EXPECT_EQ(world->GetBodyCount(), 0);
  for (float x = 0; x < 140; x += 7) {
    b2AABB camera;
    camera.lowerBound.Set(x + 1, -10);
    camera.upperBound.Set(x + 20, 5);  // within the upper row of chunks
    ASSERT_TRUE(terrain.load(camera).ok());
    int overlapped = 0;  // chunks [16 i, 16 i + 16] meeting [x + 1, x + 20], sides included
    for (int i = 0; i < 10; ++i) overlapped += 16.0f * i <= x + 20 && 16.0f * i + 16 >= x + 1;
    EXPECT_EQ(terrain.loaded_chunks(), overlapped) << "camera at " << x;
    EXPECT_EQ(world->GetProxyCount(), static_cast<int>(terrain.fixtures().size()));
    EXPECT_EQ(world->GetProxyCount(), terrain_proxies(terrain));
    EXPECT_LT(world->GetProxyCount(), all / 3);
  }
  ASSERT_TRUE(terrain.load_all().ok());
  EXPECT_EQ(world->GetProxyCount(), all);
}

// The triangles of the loaded chunks, each as its sorted points (to compare two terrains).
std::multiset<std::vector<float>> triangles_of(const OutlineTerrain& terrain) {
  std::multiset<std::vector<float>> out;
  for (const b2Fixture* f : terrain.fixtures()) out.insert(points_of(f));
  return out;
}

// A crater dug and a wall built while their chunks are unloaded are there when the chunks load:
// the same triangles as the same edits made while loaded, the same area, edge data fixed.
TEST(OutlineTerrainStreaming, EditsMadeWhileUnloadedAreThereWhenLoaded) {
  World world;
  OutlineTerrain loaded(world.get());
  OutlineTerrain streamed(world.get(), [] {
    TerrainOptions o;
    o.body.position.Set(0, 100);  // apart from the other, in the same world
    return o;
  }());
  const std::vector<Ring> level = {flat_level(0, 64, 0, 20)};
  ASSERT_TRUE(loaded.set_outline(level).ok());
  ASSERT_TRUE(streamed.set_outline(level).ok());
  b2AABB camera;
  camera.lowerBound.Set(0, -20);
  camera.upperBound.Set(10, 0);
  ASSERT_TRUE(streamed.load(camera).ok());
  for (OutlineTerrain* t : {&loaded, &streamed}) {
    ASSERT_TRUE(t->remove(b2Vec2(48, 0), 2.0f).ok());        // a crater across chunks 2 and 3
    ASSERT_TRUE(t->add(rectangle(50, -1, 52, 4)).ok());      // a wall
    ASSERT_TRUE(t->remove(rectangle(20, -8, 44, -6)).ok());  // a tunnel
  }
  EXPECT_FALSE(streamed.solid(b2Vec2(48, -1.5f)));
  EXPECT_TRUE(streamed.solid(b2Vec2(51, 3)));
  EXPECT_NEAR(streamed.area(), loaded.area(), 1e-9);
  EXPECT_LT(static_cast<int>(streamed.fixtures().size()), loaded.triangle_count() / 2);
  ASSERT_TRUE(streamed.load_all().ok());
  EXPECT_EQ(triangles_of(streamed), triangles_of(loaded));
  EXPECT_NEAR(open_length(streamed), open_length(loaded), 1e-3);
}

// Seams as chunks appear and disappear: one chunk loaded alone has its side toward the unloaded
// neighbour open; once the neighbour loads, the seam is internal on both sides; once it unloads
// again, open again; every triangle's edge data is what the rule finds at each stage.
TEST(OutlineTerrainStreaming, SeamsAreFixedAsChunksAppearAndDisappear) {
  World world;
  OutlineTerrain terrain(world.get());
  ASSERT_TRUE(terrain.set_outline({rectangle(0, -4, 32, 0)}).ok());  // chunks 0 and 1, 4 m deep
  const auto region = [](float x0, float x1) {
    b2AABB r;
    r.lowerBound.Set(x0, -2);
    r.upperBound.Set(x1, -1);
    return r;
  };
  ASSERT_TRUE(terrain.load(region(2, 10)).ok());
  ASSERT_EQ(terrain.loaded_chunks(), 1);
  EXPECT_NEAR(open_length(terrain), 16 + 4 + 16 + 4, 1e-3);  // the seam x = 16 is open
  ASSERT_TRUE(terrain.load(region(2, 20)).ok());
  ASSERT_EQ(terrain.loaded_chunks(), 2);
  EXPECT_NEAR(open_length(terrain), 2 * 32 + 2 * 4, 1e-3);  // internal
  ASSERT_TRUE(terrain.load(region(18, 20)).ok());
  ASSERT_EQ(terrain.loaded_chunks(), 1);
  EXPECT_NEAR(open_length(terrain), 16 + 4 + 16 + 4, 1e-3);  // open again
}

// Bad input is refused with its named error and message, and changes nothing: not the ground, not
// the world.
TEST(OutlineTerrainInput, BadInputIsRefusedByNameAndChangesNothing) {
  World world;
  for (const auto& [chunk, cell] : {std::pair{0.0f, 2.0f},
                                    {16.0f, 3.0f},
                                    {16.0f, 0.001f},
                                    {std::nanf(""), 2.0f},
                                    {-16.0f, 2.0f}}) {
    TerrainOptions o;
    o.chunk = chunk;
    o.cell = cell;
    OutlineTerrain bad(world.get(), o);
    EXPECT_EQ(bad.set_outline({rectangle(0, 0, 4, 4)}).error, TerrainError::Layout)
        << chunk << ", " << cell;
    EXPECT_EQ(bad.remove(b2Vec2(1, 1), 1).error, TerrainError::Layout);
    EXPECT_EQ(bad.load_all().error, TerrainError::Layout);
  }
  OutlineTerrain terrain(world.get());
  ASSERT_TRUE(terrain.set_outline({flat_level(0, 40, 0, 10)}).ok());
  const double area = terrain.area();
  const int proxies = world->GetProxyCount();
  const float nan = std::nanf("");
  const auto expect_refused = [&](const TerrainResult& r, TerrainError e, const char* what) {
    EXPECT_EQ(r.error, e) << what << ": " << r.message;
    EXPECT_STREQ(r.message, describe(e)) << what;
    EXPECT_EQ(terrain.area(), area) << what;
    EXPECT_EQ(world->GetProxyCount(), proxies) << what;
  };
  expect_refused(terrain.set_outline({}), TerrainError::Rings, "no rings");
  EXPECT_EQ(terrain.set_outline({}).outline, OutlineError::NoRings);
  const TerrainResult bow = terrain.remove(Ring{{0, 0}, {4, 4}, {4, 0}, {0, 6}});
  expect_refused(bow, TerrainError::Rings, "a bow tie");
  EXPECT_EQ(bow.outline, OutlineError::SelfIntersection);
  const TerrainResult few = terrain.add(Ring{{0, 0}, {1, 1}, {0, 0}});
  expect_refused(few, TerrainError::Rings, "two points");
  EXPECT_EQ(few.outline, OutlineError::TooFewPoints);
  EXPECT_EQ(few.ring, 0);
  expect_refused(terrain.remove(Ring{{0, 0}, {nan, 1}, {1, 0}}), TerrainError::Rings, "NaN");
  expect_refused(terrain.remove(b2Vec2(1, 1), nan), TerrainError::Circle, "NaN radius");
  expect_refused(terrain.remove(b2Vec2(1, 1), 0), TerrainError::Circle, "zero radius");
  expect_refused(terrain.add(b2Vec2(nan, 1), 1), TerrainError::Circle, "NaN centre");
  expect_refused(terrain.add(b2Vec2(2e4f, 0), 1), TerrainError::TooLarge, "far circle");
  expect_refused(terrain.add(rectangle(0, 0, 1e5f, 1)), TerrainError::TooLarge, "far wall");
  b2AABB inverted;
  inverted.lowerBound.Set(5, 5);
  inverted.upperBound.Set(0, 10);
  expect_refused(terrain.load(inverted), TerrainError::Region, "inverted region");
  b2AABB infinite;
  infinite.lowerBound.Set(0, 0);
  infinite.upperBound.Set(INFINITY, 1);
  expect_refused(terrain.load(infinite), TerrainError::Region, "infinite region");
  EXPECT_EQ(terrain.loaded_chunks(), terrain.chunk_count());
  // During a step: from a contact listener, Box2D's world is locked.
  struct Editor : b2ContactListener {
    OutlineTerrain* terrain;
    std::vector<TerrainResult> results;
    void BeginContact(b2Contact*) override {
      results.push_back(terrain->remove(b2Vec2(5, 0), 1));
      results.push_back(terrain->unload());
    }
  } editor;
  editor.terrain = &terrain;
  world->SetContactListener(&editor);
  add_split_box(world, b2Vec2(5, 0.31f), 0.3f);
  world.step();
  world->SetContactListener(nullptr);
  ASSERT_FALSE(editor.results.empty());
  for (const TerrainResult& r : editor.results) {
    EXPECT_EQ(r.error, TerrainError::WorldLocked) << r.message;
  }
  EXPECT_EQ(terrain.area(), area);
}

// Random calls in any order (three seeded sequences) — outlines, craters, tunnels, walls, loads and
// unloads, steps with bodies on the ground — never crash, and leave a consistent terrain: the
// loaded fixtures are the triangles of the loaded chunks, each with the edge data the rule finds,
// every body finite.
TEST(OutlineTerrainInput, AnyOrderOfCallsLeavesAConsistentTerrain) {
  ASSERT_TRUE(install(Backend::Dyop).ok());
  for (const unsigned seed : {63u, 64u, 65u}) {
    SCOPED_TRACE(seed);
    World world;
    OutlineTerrain terrain(world.get(), small_chunks());
    std::mt19937 random(seed);
    std::uniform_real_distribution<float> x(-6, 30), y(-8, 4), size(0.1f, 3);
    for (int i = 0; i < 8; ++i) add_split_box(world, b2Vec2(x(random), 2), 0.3f);
    for (int call = 0; call < 120; ++call) {
      const int kind = static_cast<int>(random() % 9);
      const b2Vec2 p(x(random), y(random));
      const float s = size(random);
      b2AABB region;
      region.lowerBound = p;
      region.upperBound = p + b2Vec2(s * 4, s * 2);
      TerrainResult r;
      switch (kind) {
        case 0:
          r = terrain.set_outline({flat_level(-4, 28, 0, 6), rectangle(2, -4, 8, -2)});
          break;
        case 1:
          r = terrain.remove(p, s);
          break;
        case 2:
          r = terrain.add(p, s);
          break;
        case 3:
          r = terrain.remove(rectangle(p.x, p.y, p.x + 2 * s, p.y + s));
          break;
        case 4:
          r = terrain.add(Ring{p, p + b2Vec2(s, 0), p + b2Vec2(0, s)});
          break;
        case 5:
          r = terrain.load(region);
          break;
        case 6:
          r = call % 2 ? terrain.load_all() : terrain.unload();
          break;
        default:
          for (int k = 0; k < 5; ++k) world.step();
          break;
      }
      ASSERT_TRUE(r.ok()) << "call " << call << ": " << r.message;
      ASSERT_TRUE(finite_state(world)) << "call " << call;
    }
    ASSERT_TRUE(terrain.load_all().ok());
    EXPECT_EQ(static_cast<int>(terrain.fixtures().size()), terrain.triangle_count());
    EXPECT_EQ(world->GetProxyCount(), terrain_proxies(terrain) + 8 * 2);
    open_length(terrain);  // every fixture's edge data is what the rule finds
  }
  ASSERT_TRUE(uninstall().ok());
}

}  // namespace terrain
}  // namespace
}  // namespace dyop::box2d::testing
