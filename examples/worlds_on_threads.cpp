// Guide, step 8: worlds on threads. The one rule: `install` and `uninstall` change Box2D's
// process-wide contact registry, so call them while no thread steps a world (here: before the
// threads start and after they end). Everything else the plug-in knows about a world lives in
// that world's contacts, so separate worlds step on separate threads as Box2D 2.4 allows. Four
// worlds (a pile of triangles poured onto a ground of triangles, a different pile each) step on
// four threads, then again one after another on this thread. Exits non-zero unless every world
// ends bit for bit where it ended on its thread.
#include <box2d/box2d.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <thread>
#include <vector>

#include <dyop/box2d.hpp>

#include "triangle_ground.hpp"

namespace {

// World `seed`'s pile after 300 steps: every body's position and angle, in creation order.
std::vector<float> pile(int seed) {
  b2World world(b2Vec2(0, -10));
  b2BodyDef def;
  b2Body* ground = world.CreateBody(&def);
  example::add_triangle_ground(ground, -5, 5, 1);
  def.type = b2_dynamicBody;
  std::vector<b2Body*> bodies;
  for (int k = 0; k < 40; ++k) {
    def.position.Set(-3 + 0.7f * static_cast<float>(k % 8), 1 + 0.7f * static_cast<float>(k / 8));
    def.angle = 0.3f * static_cast<float>(k + seed);
    bodies.push_back(world.CreateBody(&def));
    example::add_triangle(bodies.back(), {-0.3f, -0.2f}, {0.3f, -0.2f}, {0, 0.3f}, 1);
  }
  for (int i = 0; i < 300; ++i) world.Step(1.0f / 60, 8, 3);
  std::vector<float> state;
  for (const b2Body* b : bodies) {
    state.insert(state.end(), {b->GetPosition().x, b->GetPosition().y, b->GetAngle()});
  }
  return state;
}

}  // namespace

int main() {
  constexpr int kWorlds = 4;
  // Before any thread steps a world.
  if (!dyop::box2d::install(dyop::box2d::Backend::Dyop).ok()) return EXIT_FAILURE;

  std::vector<std::vector<float>> on_threads(kWorlds);
  std::vector<std::thread> threads;
  for (int w = 0; w < kWorlds; ++w) {
    threads.emplace_back([w, &on_threads] { on_threads[w] = pile(w); });
  }
  for (std::thread& t : threads) t.join();
  const dyop::box2d::Stats s = dyop::box2d::stats();  // every thread's counts, summed

  bool same = true;
  for (int w = 0; w < kWorlds; ++w) {
    const std::vector<float> alone = pile(w);
    const bool equal =
        alone.size() == on_threads[w].size() &&
        std::memcmp(alone.data(), on_threads[w].data(), alone.size() * sizeof(float)) == 0;
    std::printf("world %d: %s\n", w, equal ? "bit for bit as on its thread" : "DIFFERS");
    same = same && equal;
  }
  std::printf("triangle pairs evaluated on the threads: %llu\n",
              static_cast<unsigned long long>(s.triangles(dyop::box2d::Backend::Dyop)));
  dyop::box2d::uninstall();  // after every thread is done
  return same ? EXIT_SUCCESS : EXIT_FAILURE;
}
