// Guide, step 3: a level made of Box2D's own edge shapes. The ground is a `b2ChainShape` loop (the
// outline of a block, a vertex every 0.25 m along its top, as a level editor exports it); above
// it, a bridge of two-sided `b2EdgeShape` planks 0.5 m long. A crate, a ball and a box of two
// triangles are pushed at 4 m/s along each, first under Box2D's own contact, then under the
// plug-in, which answers edge and chain pairs exactly with the internal-edge rule. Exits non-zero
// unless all six glide under the plug-in.
#include <box2d/box2d.h>

#include <cstdio>
#include <cstdlib>
#include <vector>

#include <dyop/box2d.hpp>
#include <dyop/box2d_internal_edges.hpp>

#include "glide.hpp"

namespace {

void build_level(b2World& world) {
  b2BodyDef def;
  b2Body* ground = world.CreateBody(&def);
  // The chain: counter-clockwise, so that its solid side is inside (a chain's edges are
  // one-sided: bodies meet them from outside the loop).
  std::vector<b2Vec2> loop = {{-2, -2}, {40, -2}};
  for (int i = 0; i <= 168; ++i) loop.push_back({40 - 0.25f * static_cast<float>(i), 0});
  b2ChainShape chain;
  chain.CreateLoop(loop.data(), static_cast<int>(loop.size()));
  ground->CreateFixture(&chain, 0);

  // The bridge: planks end to end at y = 3 (two-sided: either face can be stood on).
  def.position.Set(0, 3);
  b2Body* bridge = world.CreateBody(&def);
  for (int i = 0; i < 80; ++i) {
    b2EdgeShape plank;
    plank.SetTwoSided(b2Vec2(-2 + 0.5f * static_cast<float>(i), 0),
                      b2Vec2(-1.5f + 0.5f * static_cast<float>(i), 0));
    bridge->CreateFixture(&plank, 0);
  }
  // Optional: the planks' ends fixed once (a contact would find them in the broad phase).
  dyop::box2d::fix_internal_edges(world);
}

bool run(const char* title) {
  b2World world(b2Vec2(0, -10));
  build_level(world);
  std::vector<example::Pushed> chain = example::push_all(world, b2Vec2(0, 0), 4);
  std::vector<example::Pushed> bridge = example::push_all(world, b2Vec2(0, 3), 4);
  std::vector<example::Pushed> all = chain;
  all.insert(all.end(), bridge.begin(), bridge.end());
  example::step_and_watch(world, all, 5);
  std::printf("%s\n", title);
  const bool on_chain = example::report(" on the chain", {all.begin(), all.begin() + 3});
  const bool on_bridge = example::report(" on the bridge of edges", {all.begin() + 3, all.end()});
  return on_chain && on_bridge;
}

}  // namespace

int main() {
  run("Box2D's own contact");
  if (!dyop::box2d::install(dyop::box2d::Backend::Dyop).ok()) return EXIT_FAILURE;
  const bool glided = run("the plug-in installed");
  std::printf("edge and chain pairs answered: %llu\n",
              static_cast<unsigned long long>(dyop::box2d::stats().edge_pairs));
  dyop::box2d::uninstall();
  return glided ? EXIT_SUCCESS : EXIT_FAILURE;
}
