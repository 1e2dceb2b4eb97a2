// A tile map with slopes (`dyop::box2d::TileKind`): a high flat, a 1:2 ramp down to a long low
// flat and a 45° ramp up at its end, under an overhang whose underside slopes at 45°. A `SetAsBox`
// crate and a ball, frictionless, are pushed off the high flat with the plug-in installed: they
// slide down the ramp and along the low flat. Prints, for each, its speed at the foot of the ramp,
// the least speed along the flat this leaves it (the flat only pushes up, the slope only forward),
// its speed and largest vertical speed on the flat once settled (0 m/s: no ghost collision at the
// seams of the cells), then a cell of the map made a slope between two steps.
#include <box2d/box2d.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

#include <dyop/box2d.hpp>
#include <dyop/box2d_grid.hpp>

using dyop::box2d::TileKind;

int main() {
  if (!dyop::box2d::install(dyop::box2d::Backend::Dyop).ok()) return 1;
  bool ok = true;
  {
    b2World world(b2Vec2(0, -10));
    b2BodyDef ground_def;
    b2Body* ground = world.CreateBody(&ground_def);
    // 120 × 16 cells of 0.5 m, the low flat's top at y = 0: 2 rows of ground, 8 more under the
    // high flat (columns 0 to 9), a 1:2 ramp down over columns 10 to 25, the 45° ramp up from
    // column 110, and an overhang over columns 40 to 49 (rows 12 to 15).
    constexpr int columns = 120, rows = 16;
    std::vector<std::uint8_t> cells(columns * rows, 0);
    const auto set = [&](int c, int r, TileKind k) {
      cells[r * columns + c] = static_cast<std::uint8_t>(k);
    };
    for (int c = 0; c < columns; ++c) {
      int height = 2;  // full rows of the column
      if (c < 10) height = 10;
      if (c >= 10 && c < 26) {  // the 1:2 ramp down: each row over two cells, high then low
        height = 9 - (c - 10) / 2;
        set(c, height,
            c % 2 == 0 ? TileKind::GentleFloorFallingHigh : TileKind::GentleFloorFallingLow);
      }
      if (c >= 110) {  // the 45° ramp up
        height = 2 + (c - 110);
        set(c, height, TileKind::FloorRising);
      }
      for (int r = 0; r < height; ++r) set(c, r, TileKind::Solid);
      if (c >= 40 && c < 50) {  // the overhang, its underside a 45° ceiling at each end
        for (int r = 13; r < rows; ++r) set(c, r, TileKind::Solid);
        set(c, 12,
            c == 40   ? TileKind::CeilingFalling
            : c == 49 ? TileKind::CeilingRising
                      : TileKind::Solid);
      }
    }
    dyop::box2d::TileGround map(*ground, {columns, rows, 0.5f, b2Vec2(-5, -1)});
    if (const dyop::box2d::GridError e = map.set_cells(cells); e != dyop::box2d::GridError::None) {
      std::fprintf(stderr, "tile map: %s\n", dyop::box2d::describe(e));
      return 1;
    }

    // A crate and a ball on the high flat (its top is y = 4), frictionless, passing through each
    // other (one collision group), pushed toward the ramp.
    b2PolygonShape crate;
    crate.SetAsBox(0.3f, 0.3f);
    b2CircleShape ball;
    ball.m_radius = 0.3f;
    const b2Shape* shapes[2] = {&crate, &ball};
    b2Body* bodies[2];
    for (int k = 0; k < 2; ++k) {
      b2BodyDef body_def;
      body_def.type = b2_dynamicBody;
      body_def.position.Set(-2, 4.3f);
      body_def.linearVelocity.Set(2, 0);
      bodies[k] = world.CreateBody(&body_def);
      b2FixtureDef fixture_def;
      fixture_def.shape = shapes[k];
      fixture_def.density = 1;
      fixture_def.friction = 0;
      fixture_def.filter.groupIndex = -1;
      bodies[k]->CreateFixture(&fixture_def);
    }
    // The ramp runs from x = 0 down to its foot at x = 8; a body counts as settled on the low flat
    // 1 m past the foot, and the flat ends at the 45° ramp, x = 50.
    const float slope = std::atan2(1.0f, 2.0f);
    float at_foot[2] = {0, 0}, vertical[2] = {0, 0}, on_flat[2] = {0, 0};
    for (int step = 0; step < 240; ++step) {
      world.Step(1.0f / 60, 8, 3);
      for (int k = 0; k < 2; ++k) {
        const b2Vec2 p = bodies[k]->GetPosition(), v = bodies[k]->GetLinearVelocity();
        if (p.x < 8) at_foot[k] = v.Length();  // the last speed on the ramp
        if (p.x > 9 && p.x < 48) {
          vertical[k] = std::fmax(vertical[k], std::fabs(v.y));
          on_flat[k] = v.x;
        }
      }
    }
    for (int k = 0; k < 2; ++k) {
      std::printf(
          "%s: %.2f m/s down the ramp at its foot, at least %.2f of it along the flat; on the "
          "flat %.2f m/s, largest vertical speed %.3f m/s\n",
          k == 0 ? "crate" : "ball", at_foot[k], at_foot[k] * std::cos(slope), on_flat[k],
          vertical[k]);
      // Down the ramp and over its foot without a ghost collision: the flat keeps at least what
      // the turn onto it leaves (99 %), and nothing throws the body up.
      if (!(on_flat[k] >= 0.99f * at_foot[k] * std::cos(slope) && vertical[k] <= 0.01f)) ok = false;
    }
    // A cell made a slope between steps: its chunk is built again.
    const auto start = std::chrono::steady_clock::now();
    map.set_cell(60, 2, TileKind::GentleFloorRisingLow);
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    std::printf("cell (60, 2) made a 1:2 slope in %.3f ms; %zu fixtures\n", ms,
                map.fixtures().size());
  }
  dyop::box2d::uninstall();
  return ok ? 0 : 1;
}
