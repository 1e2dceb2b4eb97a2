// build/bin/dyop_edges_bench: what finding internal-edge masks costs on large static tile maps.
// Each triangle's masks are found as a contact finds them (`triangle_internal_edges`: one query
// of the world's broad phase, then the triangles it meets); nothing is built beforehand, so the
// cost of "the index" is Box2D's own broad phase, built as fixtures are created (timed apart).
// Grids of 0.5 m tiles, each split in two triangles, 10,000 and 100,000 triangles, in one static
// body, 100 bodies, and one body per tile (up to 10,000 bodies: larger maps put several tiles in a
// body). Wall time, best of three passes over every triangle.
#include <box2d/box2d.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

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

void run(const Map& map) {
  const int tiles = map.triangles / 2;
  const int columns = static_cast<int>(std::sqrt(2.0 * tiles));  // twice as wide as deep
  const int tiles_per_body = (tiles + map.bodies - 1) / map.bodies;
  b2World world(b2Vec2(0, -10));
  const auto build_start = std::chrono::steady_clock::now();
  std::vector<b2Fixture*> fixtures;
  b2Body* body = nullptr;
  int internal = 0;
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
      fixtures.push_back(body->CreateFixture(&shape, 0.0f));
    }
  }
  const double build = seconds_since(build_start);
  double best = 1e30;
  for (int pass = 0; pass < kPasses; ++pass) {
    const auto start = std::chrono::steady_clock::now();
    internal = 0;
    for (const b2Fixture* f : fixtures) {
      internal += __builtin_popcount(dyop::box2d::triangle_internal_edges(*f).edges);
    }
    best = std::min(best, seconds_since(start));
  }
  std::printf("| %7d | %6d | %8.1f | %9.1f | %7.2f | %8d |\n", map.triangles, map.bodies,
              1e3 * build, 1e3 * best, 1e6 * best / map.triangles, internal);
}

}  // namespace

int main() {
  std::printf(
      "| triangles | bodies | broad phase built (ms) | all masks found (ms) | per triangle "
      "(µs) | internal edges |\n|---:|---:|---:|---:|---:|---:|\n");
  for (const Map& m : {Map{10000, 1}, Map{10000, 100}, Map{10000, 5000}, Map{100000, 1},
                       Map{100000, 100}, Map{100000, 10000}}) {
    run(m);
  }
}
