// build/bin/dyop_edges_bench: what finding internal-edge masks costs on large static tile maps.
// Each triangle's masks are found as a contact finds them (`triangle_internal_edges`: one query
// of the world's broad phase, then the triangles it meets); nothing is built beforehand, so the
// cost of "the index" is Box2D's own broad phase, built as fixtures are created (timed apart).
// Grids of 0.5 m tiles, each split in two triangles, 10,000 and 100,000 triangles, in one static
// body, 100 bodies, and one body per tile (up to 10,000 bodies: larger maps put several tiles in a
// body). Wall time, best of three worlds: every triangle's masks found a first time (its group
// searched) and again (a static triangle's memoised finding, after the same query).
// Then a box of two triangles gliding 600 steps across a one-body ground of 10,000 triangles:
// the first step (Box2D's pair search, the masks found) and the rest, under Box2D's own contact,
// the plug-in finding masks at contact time, and the plug-in on a ground whose edge data was
// fixed beforehand (`fix_internal_edges`, timed apart). Best of three worlds each.
#include <box2d/box2d.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

#include "dyop/box2d.hpp"
#include "dyop/box2d_internal_edges.hpp"

namespace {

constexpr float kTile = 0.5f;
constexpr int kPasses = 3;

struct Map {
  int triangles;
  int bodies;
};

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

// Creates `map`'s tiles as triangle fixtures of static bodies, the top row's top at y = kTile.
std::vector<b2Fixture*> build_ground(b2World& world, const Map& map) {
  const int tiles = map.triangles / 2;
  const int columns = static_cast<int>(std::sqrt(2.0 * tiles));  // twice as wide as deep
  const int tiles_per_body = (tiles + map.bodies - 1) / map.bodies;
  std::vector<b2Fixture*> fixtures;
  b2Body* body = nullptr;
  for (int t = 0; t < tiles; ++t) {
    const b2Vec2 bl(kTile * (t % columns), -kTile * (t / columns));
    if (t % tiles_per_body == 0) {
      b2BodyDef def;
      def.position = bl;  // each body in a frame of its own
      body = world.CreateBody(&def);
    }
    const b2Vec2 br = bl + b2Vec2(kTile, 0), tr = bl + b2Vec2(kTile, kTile),
                 tl = bl + b2Vec2(0, kTile);
    const b2Transform& xf = body->GetTransform();
    for (const auto& tri : {std::vector<b2Vec2>{tl, bl, tr}, std::vector<b2Vec2>{tr, bl, br}}) {
      b2Vec2 local[3] = {b2MulT(xf, tri[0]), b2MulT(xf, tri[1]), b2MulT(xf, tri[2])};
      b2PolygonShape shape;
      shape.Set(local, 3);
      b2FixtureDef def;
      def.shape = &shape;
      def.friction = 0;
      fixtures.push_back(body->CreateFixture(&def));
    }
  }
  return fixtures;
}

// Seconds to find every fixture's masks once; `internal`: the internal edges found.
double find_all(const std::vector<b2Fixture*>& fixtures, int& internal) {
  const auto start = std::chrono::steady_clock::now();
  internal = 0;
  for (const b2Fixture* f : fixtures) {
    internal += __builtin_popcount(dyop::box2d::triangle_internal_edges(*f).edges);
  }
  return seconds_since(start);
}

void run(const Map& map) {
  double build = 1e30;
  double first = 1e30;
  double again = 1e30;
  int internal = 0;
  for (int pass = 0; pass < kPasses; ++pass) {
    b2World world(b2Vec2(0, -10));
    const auto build_start = std::chrono::steady_clock::now();
    const std::vector<b2Fixture*> fixtures = build_ground(world, map);
    build = std::min(build, seconds_since(build_start));
    first = std::min(first, find_all(fixtures, internal));
    again = std::min(again, find_all(fixtures, internal));
  }
  std::printf("| %7d | %6d | %8.1f | %9.1f | %7.2f | %7.2f | %8d |\n", map.triangles, map.bodies,
              1e3 * build, 1e3 * first, 1e6 * first / map.triangles, 1e6 * again / map.triangles,
              internal);
}

enum class Glide { Box2DOwn, FoundAtContactTime, FixedBeforehand };

struct GlideTimes {
  double fix = 0;    // fix_internal_edges (seconds)
  double first = 0;  // the first step
  double rest = 0;   // the other steps
  float travel = 0;  // how far the box went (metres)
};

constexpr int kGlideSteps = 600;

// One world: the ground of `triangles` in one body, a frictionless box of two triangles sliding
// along its top at 3 m/s, stepped kGlideSteps times at 60 Hz.
GlideTimes glide(int triangles, Glide how) {
  b2World world(b2Vec2(0, -10));
  build_ground(world, Map{triangles, 1});
  b2BodyDef def;
  def.type = b2_dynamicBody;
  def.position.Set(1.0f, kTile + 0.25f);
  def.linearVelocity.Set(3.0f, 0);
  b2Body* box = world.CreateBody(&def);
  const b2Vec2 corners[4] = {{-0.25f, -0.25f}, {0.25f, -0.25f}, {0.25f, 0.25f}, {-0.25f, 0.25f}};
  for (const auto& tri : {std::vector<b2Vec2>{corners[0], corners[1], corners[2]},
                          std::vector<b2Vec2>{corners[0], corners[2], corners[3]}}) {
    b2PolygonShape shape;
    shape.Set(tri.data(), 3);
    b2FixtureDef fixture;
    fixture.shape = &shape;
    fixture.density = 1;
    fixture.friction = 0;
    box->CreateFixture(&fixture);
  }
  GlideTimes t;
  if (how == Glide::FixedBeforehand) {
    const auto start = std::chrono::steady_clock::now();
    dyop::box2d::fix_internal_edges(world);
    t.fix = seconds_since(start);
  }
  auto start = std::chrono::steady_clock::now();
  world.Step(1.0f / 60, 8, 3);
  t.first = seconds_since(start);
  start = std::chrono::steady_clock::now();
  for (int i = 1; i < kGlideSteps; ++i) world.Step(1.0f / 60, 8, 3);
  t.rest = seconds_since(start);
  t.travel = box->GetPosition().x - 1.0f;
  return t;
}

void run_glide(int triangles) {
  const struct {
    Glide how;
    const char* name;
  } rows[] = {{Glide::Box2DOwn, "Box2D's own contact"},
              {Glide::FoundAtContactTime, "dyop, masks found at contact time"},
              {Glide::FixedBeforehand, "dyop, edge data fixed beforehand"}};
  for (const auto& row : rows) {
    GlideTimes best{1e30, 1e30, 1e30, 0};
    for (int pass = 0; pass < kPasses; ++pass) {
      if (row.how != Glide::Box2DOwn) dyop::box2d::install(dyop::box2d::Backend::Dyop);
      const GlideTimes t = glide(triangles, row.how);
      dyop::box2d::uninstall();
      best = {std::min(best.fix, t.fix), std::min(best.first, t.first), std::min(best.rest, t.rest),
              t.travel};
    }
    std::printf("| %s | %d | %.2f | %.2f | %.2f | %.2f |\n", row.name, triangles, 1e3 * best.fix,
                1e3 * best.first, 1e3 * best.rest, best.travel);
  }
}

}  // namespace

int main() {
  std::printf(
      "| triangles | bodies | broad phase built (ms) | all masks found (ms) | per triangle "
      "(µs) | found again, per triangle (µs) | internal edges |\n"
      "|---:|---:|---:|---:|---:|---:|---:|\n");
  for (const Map& m : {Map{10000, 1}, Map{10000, 100}, Map{10000, 5000}, Map{100000, 1},
                       Map{100000, 100}, Map{100000, 10000}}) {
    run(m);
  }
  std::printf(
      "\n| a box gliding %d steps | ground triangles | fix_internal_edges (ms) | first step (ms) "
      "| other steps (ms) | travel (m) |\n|---|---:|---:|---:|---:|---:|\n",
      kGlideSteps);
  run_glide(10000);
}
