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

namespace {

using Ring = std::vector<b2Vec2>;

// The ground's outline, counter-clockwise: the top from x = 300 back to 0 (a vertex every 0.25 m),
// then the bottom at y = -20, with a notch cut into the right side under an overhang.
Ring outline() {
  Ring ring;
  for (int i = 1200; i >= 0; --i) {
    const float x = 0.25f * static_cast<float>(i);
    const float hills = x < 40 ? 0 : 3 * std::sin((x - 40) / 12) * std::sin((x - 40) / 31);
    ring.push_back({x, hills});
  }
  ring.insert(ring.end(), {{0, -20}, {300, -20}, {300, -12}, {292, -12}, {292, -6}, {300, -6}});
  return ring;
}

// A cave: an ellipse of 24 vertices.
Ring cave(float cx, float cy, float rx, float ry) {
  Ring ring;
  for (int i = 0; i < 24; ++i) {
    const float a = static_cast<float>(i) * 2 * b2_pi / 24;
    ring.push_back({cx + rx * std::cos(a), cy + ry * std::sin(a)});
  }
  return ring;
}

}  // namespace

int main() {
  if (!dyop::box2d::install(dyop::box2d::Backend::Dyop).ok()) return EXIT_FAILURE;
  bool glided = false;
  {
    b2World world(b2Vec2(0, -10));
    b2BodyDef ground_def;
    b2Body* ground = world.CreateBody(&ground_def);
    std::vector<Ring> rings = {outline()};
    for (int k = 0; k < 10; ++k) rings.push_back(cave(20 + 27 * static_cast<float>(k), -10, 6, 3));

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
