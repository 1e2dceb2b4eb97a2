// Guide, step 2: a level from its outline. 300 m of ground whose top runs flat for 40 m and then
// over hills, with caves under it and an overhang at its end, given as the rings a Box2D user
// would feed `b2ChainShape`, triangulated by `dyop::box2d::add_outline` with its edge data fixed.
// Prints what was built and how long it took, then pushes a crate, a ball and a box of two
// triangles along the flat stretch at 4 m/s with the plug-in installed. Exits non-zero unless all
// three glide over the triangles' seams.
#include <box2d/box2d.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include <dyop/box2d.hpp>
#include <dyop/box2d_outline.hpp>

#include "glide.hpp"
#include "level_outline.hpp"

int main() {
  if (!dyop::box2d::install(dyop::box2d::Backend::Dyop).ok()) return EXIT_FAILURE;
  bool glided = false;
  {
    b2World world(b2Vec2(0, -10));
    b2BodyDef ground_def;
    b2Body* ground = world.CreateBody(&ground_def);
    const std::vector<std::vector<b2Vec2>> rings = level_outline();

    const auto start = std::chrono::steady_clock::now();
    const dyop::box2d::OutlineResult r = dyop::box2d::add_outline(*ground, rings);
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    if (!r.ok()) {
      std::fprintf(stderr, "outline: ring %d: %s\n", r.ring, r.message);
      return EXIT_FAILURE;
    }
    std::printf("outline of %zu rings: %d vertices kept, %zu triangles, built in %.1f ms\n",
                rings.size(), r.vertices, r.mesh.fixtures.size(), ms);

    std::vector<example::Pushed> bodies = example::push_all(world, b2Vec2(2, 0), 4);
    example::step_and_watch(world, bodies, 6);
    glided =
        example::report("a level from its outline (add_outline), the plug-in installed", bodies);
  }
  dyop::box2d::uninstall();
  return glided ? EXIT_SUCCESS : EXIT_FAILURE;
}
