// Guide, step 2: a level from a tile grid. The solid cells of a grid are merged into rectangles
// (`dyop::box2d::TileGround`, their edge data fixed), a pit is dug in the map, and a crate, a ball
// and a box of two triangles are pushed along it at 4 m/s with the plug-in installed. Exits
// non-zero unless all three glide over the rectangles' seams.
#include <box2d/box2d.h>

#include <cstdio>
#include <cstdlib>
#include <vector>

#include <dyop/box2d.hpp>
#include <dyop/box2d_grid.hpp>

#include "glide.hpp"

int main() {
  if (!dyop::box2d::install(dyop::box2d::Backend::Dyop).ok()) return EXIT_FAILURE;
  bool glided = false;
  {
    b2World world(b2Vec2(0, -10));
    b2BodyDef ground_def;
    b2Body* ground = world.CreateBody(&ground_def);
    // 120 × 4 cells of 0.5 m, the top at y = 0; cells[row · columns + column], row 0 at the bottom.
    dyop::box2d::TileGround map(*ground, {120, 4, 0.5f, b2Vec2(-5, -2)});
    std::vector<std::uint8_t> cells(120 * 4, 1);
    if (const dyop::box2d::GridError e = map.set_cells(cells); e != dyop::box2d::GridError::None) {
      std::fprintf(stderr, "tile map: %s\n", dyop::box2d::describe(e));
      return EXIT_FAILURE;
    }
    map.set_cell(100, 3, false);  // dig a pit two cells wide beyond where the bodies stop:
    map.set_cell(101, 3, false);  // only its chunk is built again

    std::vector<example::Pushed> bodies = example::push_all(world, b2Vec2(0, 0), 4);
    example::step_and_watch(world, bodies, 3);
    glided = example::report("a tile map (TileGround), the plug-in installed", bodies);
  }
  dyop::box2d::uninstall();
  return glided ? EXIT_SUCCESS : EXIT_FAILURE;
}
