// Guide, step 1: the plug-in in a game that already exists. The game builds its level as Box2D
// programs do, fixture by fixture: a run of 0.5 m tiles (a `SetAsBox` fixture each, then two
// triangles each) and a ramp, all on one static body. Two lines bring the plug-in in
// (`install`), one more fixes the level's edge data once it is built (`fix_internal_edges`). A
// crate, a ball and a box of two triangles are pushed along the tiles at 4 m/s, first under Box2D's
// own contact, then under the plug-in. Exits non-zero unless all three glide under the plug-in.
#include <box2d/box2d.h>

#include <cstdio>
#include <cstdlib>
#include <vector>

#include <dyop/box2d.hpp>                 // install, make_triangle
#include <dyop/box2d_internal_edges.hpp>  // fix_internal_edges

#include "glide.hpp"
#include "triangle_ground.hpp"

namespace {

// The game's own level code: 60 tiles of 0.5 m whose tops are at y = 0, the first 30 a `SetAsBox`
// fixture each, the next 30 two triangle fixtures each, then a ramp up.
void build_level(b2World& world) {
  b2BodyDef def;
  b2Body* level = world.CreateBody(&def);
  for (int i = 0; i < 60; ++i) {
    const float x = -2 + 0.5f * static_cast<float>(i);
    if (i < 30) {
      b2PolygonShape tile;
      tile.SetAsBox(0.25f, 0.25f, b2Vec2(x + 0.25f, -0.25f), 0);
      level->CreateFixture(&tile, 0);
    } else {  // make_triangle names what is wrong where Box2D 2.4 would assert (here: throws)
      example::add_triangle(level, {x, -0.5f}, {x + 0.5f, -0.5f}, {x + 0.5f, 0});
      example::add_triangle(level, {x, -0.5f}, {x + 0.5f, 0}, {x, 0});
    }
  }
  example::add_triangle(level, {28, 0}, {34, 0}, {34, 2});  // the ramp
}

// The level, the three bodies pushed along the tiles for 5 s; true when all glide.
bool run(const char* title) {
  b2World world(b2Vec2(0, -10));
  build_level(world);
  // Recommended once a level is built: its edge data computed once and kept in its fixtures.
  // Without it the contacts find the same masks themselves (a little slower).
  dyop::box2d::fix_internal_edges(world);
  std::vector<example::Pushed> bodies = example::push_all(world, b2Vec2(0, 0), 4);
  example::step_and_watch(world, bodies, 5);
  return example::report(title, bodies);
}

}  // namespace

int main() {
  run("Box2D's own contact (each fixture alone: ghost collisions on the tiles' seams)");

  // The two lines: the header above, and this call, at any moment (here between two worlds).
  if (!dyop::box2d::install(dyop::box2d::Backend::Dyop).ok()) return EXIT_FAILURE;
  const bool glided = run("the plug-in installed");
  const dyop::box2d::Stats s = dyop::box2d::stats();
  std::printf(
      "pairs answered: %llu triangle, %llu polygon, %llu circle; %llu kept, %llu under "
      "the internal-edge rule\n",
      static_cast<unsigned long long>(s.triangles(dyop::box2d::Backend::Dyop)),
      static_cast<unsigned long long>(s.polygon_pairs),
      static_cast<unsigned long long>(s.circle_pairs), static_cast<unsigned long long>(s.recycled),
      static_cast<unsigned long long>(s.internal_edge_pairs));
  dyop::box2d::uninstall();  // Box2D's own contact again, for worlds made from now on
  return glided ? EXIT_SUCCESS : EXIT_FAILURE;
}
