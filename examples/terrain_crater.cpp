// A crater blown into a level held in chunks (`dyop::box2d::OutlineTerrain`): the 300 m level of
// `outline_ground.cpp` in 16 m chunks of triangles, a row of crates resting on its flat stretch,
// then a crater of 1 m radius dug under two of them between steps. Prints how long the edit took
// and what it changed, what a contact listener saw, and where the crates went: the two over the
// crater fall into it, the others never move (their largest vertical speed after the edit).
#include <box2d/box2d.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

#include <dyop/box2d.hpp>
#include <dyop/box2d_terrain.hpp>

#include "level_outline.hpp"

namespace {

// Counts the contacts that begin and end.
class Counter : public b2ContactListener {
 public:
  void BeginContact(b2Contact*) override { ++begun; }
  void EndContact(b2Contact*) override { ++ended; }
  int begun = 0;
  int ended = 0;
};

}  // namespace

int main() {
  if (!dyop::box2d::install(dyop::box2d::Backend::Dyop).ok()) return 1;
  bool ok = true;
  {
    b2World world(b2Vec2(0, -10));
    dyop::box2d::OutlineTerrain terrain(world);  // 16 m chunks, 2 m cells: the defaults
    const dyop::box2d::TerrainResult built = terrain.set_outline(level_outline());
    if (!built.ok()) {
      std::fprintf(stderr, "outline: ring %d: %s\n", built.ring, built.message);
      return 1;
    }
    std::printf("terrain: %d chunks, %d triangles\n", terrain.chunk_count(),
                terrain.triangle_count());

    // Crates 0.6 m wide every 1.5 m along the flat stretch, resting.
    std::vector<b2Body*> crates;
    for (int k = 0; k < 20; ++k) {
      b2BodyDef def;
      def.type = b2_dynamicBody;
      def.position.Set(5 + 1.5f * static_cast<float>(k), 0.3f);
      b2Body* crate = world.CreateBody(&def);
      b2PolygonShape box;
      box.SetAsBox(0.3f, 0.3f);
      crate->CreateFixture(&box, 1.0f);
      crates.push_back(crate);
    }
    for (int step = 0; step < 120; ++step) world.Step(1.0f / 60, 8, 3);

    Counter events;
    world.SetContactListener(&events);
    const b2Vec2 centre(20.75f, 0);  // under the crates at 20 m and 21.5 m
    const auto start = std::chrono::steady_clock::now();
    const dyop::box2d::TerrainResult dug = terrain.remove(centre, 1.0f);
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    if (!dug.ok()) {
      std::fprintf(stderr, "crater: %s\n", dug.message);
      return 1;
    }
    std::printf(
        "crater dug in %.2f ms: %d chunk(s) changed, %d triangles destroyed, %d created, "
        "%d kept\n",
        ms, dug.chunks, dug.destroyed, dug.created, dug.kept);
    std::printf("listener during the edit: %d EndContact, %d BeginContact\n", events.ended,
                events.begun);
    std::vector<float> vertical(crates.size(), 0);
    for (int step = 0; step < 120; ++step) {
      world.Step(1.0f / 60, 8, 3);
      if (step == 0) {
        std::printf("listener in the next step: %d BeginContact in all\n", events.begun);
      }
      for (std::size_t k = 0; k < crates.size(); ++k) {
        vertical[k] = std::fmax(vertical[k], std::fabs(crates[k]->GetLinearVelocity().y));
      }
    }
    world.SetContactListener(nullptr);
    for (std::size_t k = 0; k < crates.size(); ++k) {
      const b2Vec2 p = crates[k]->GetPosition();
      const bool over = std::fabs(p.x - centre.x) < 1;
      std::printf("crate at x = %5.2f m: y = %6.3f m, largest vertical speed %.4f m/s%s\n", p.x,
                  p.y, vertical[k], over ? "  (over the crater)" : "");
      // Those over the crater fall into it; the others, 3 m away or more, feel nothing.
      if (over ? !(p.y < 0) : std::fabs(p.x - centre.x) >= 3 && vertical[k] > 0.01f) ok = false;
    }
  }
  dyop::box2d::uninstall();
  return ok ? 0 : 1;
}
