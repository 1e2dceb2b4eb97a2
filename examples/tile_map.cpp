// A tile map for a game's everyday bodies: the solid cells of a grid merged into rectangles
// (`dyop::box2d::TileGround`), a `SetAsBox` crate and a ball pushed along it at 4 m/s with the
// plug-in installed, a pit dug in the map beyond where they stop. Prints each body's largest
// vertical speed (0 m/s: a glide, no ghost collision at the seams of the rectangles) and how far
// it went.
#include <box2d/box2d.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include <dyop/box2d.hpp>
#include <dyop/box2d_grid.hpp>

int main() {
  if (!dyop::box2d::install(dyop::box2d::Backend::Dyop).ok()) return 1;
  {
    b2World world(b2Vec2(0, -10));
    b2BodyDef ground_def;
    b2Body* ground = world.CreateBody(&ground_def);
    // 120 × 4 cells of 0.5 m, the top at y = 0, a pit two cells wide at column 100.
    dyop::box2d::TileGround map(*ground, {120, 4, 0.5f, b2Vec2(-5, -2)});
    std::vector<std::uint8_t> cells(120 * 4, 1);
    if (const dyop::box2d::GridError e = map.set_cells(cells); e != dyop::box2d::GridError::None) {
      std::fprintf(stderr, "tile map: %s\n", dyop::box2d::describe(e));
      return 1;
    }
    map.set_cell(100, 3, false);  // dig
    map.set_cell(101, 3, false);

    b2Body* bodies[2];
    for (int k = 0; k < 2; ++k) {
      b2BodyDef def;
      def.type = b2_dynamicBody;
      def.position.Set(0, 0.3f);
      bodies[k] = world.CreateBody(&def);
      b2PolygonShape crate;
      crate.SetAsBox(0.3f, 0.3f);
      b2CircleShape ball;
      ball.m_radius = 0.3f;
      b2FixtureDef fixture;
      fixture.shape = k == 0 ? static_cast<const b2Shape*>(&crate) : &ball;
      fixture.density = 1;
      fixture.friction = 0;
      fixture.filter.groupIndex = -1;  // the two bodies pass through each other
      bodies[k]->CreateFixture(&fixture);
      bodies[k]->SetLinearVelocity(b2Vec2(4, 0));
    }
    float vertical[2] = {0, 0};
    for (int step = 0; step < 180; ++step) {
      world.Step(1.0f / 60, 8, 3);
      for (int k = 0; k < 2; ++k) {
        vertical[k] = std::fmax(vertical[k], std::fabs(bodies[k]->GetLinearVelocity().y));
      }
    }
    for (int k = 0; k < 2; ++k) {
      std::printf("%s: largest vertical speed %.3f m/s, travelled %.2f m of %.2f\n",
                  k == 0 ? "crate" : "ball", vertical[k], bodies[k]->GetPosition().x, 4 * 3.0);
    }
    const dyop::box2d::Stats s = dyop::box2d::stats();
    std::printf("pairs answered exactly beyond triangles: %llu\n",
                static_cast<unsigned long long>(s.exact_pairs));
  }
  dyop::box2d::uninstall();
  return 0;
}
