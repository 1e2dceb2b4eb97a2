// A level streamed around its camera (`dyop::box2d::OutlineTerrain::load`): the 300 m level of
// `outline_ground.cpp` in 16 m chunks, only those within a 40 m camera window and 8 m of margin
// loaded as a ball rolls along it. A crater is dug far ahead while its chunk is unloaded; it is
// there when the camera arrives, and the ball drops into it. Prints, every 2 s, the chunks,
// fixtures and broad-phase proxies loaded against the whole level's.
#include <box2d/box2d.h>

#include <cstdio>

#include <dyop/box2d.hpp>
#include <dyop/box2d_terrain.hpp>

#include "level_outline.hpp"

int main() {
  if (!dyop::box2d::install(dyop::box2d::Backend::Dyop).ok()) return 1;
  bool ok = false;
  {
    b2World world(b2Vec2(0, -10));
    dyop::box2d::OutlineTerrain terrain(world);
    if (!terrain.set_outline(level_outline()).ok()) return 1;
    const int all_chunks = terrain.chunk_count();
    const int all_triangles = terrain.triangle_count();

    b2BodyDef def;
    def.type = b2_dynamicBody;
    def.position.Set(2, 0.5f);
    b2Body* ball = world.CreateBody(&def);
    b2CircleShape circle;
    circle.m_radius = 0.5f;
    ball->CreateFixture(&circle, 1.0f);

    const auto camera_at = [](float x) {
      b2AABB camera;  // 40 m by 30 m around x, and 8 m of margin
      camera.lowerBound.Set(x - 20 - 8, -25);
      camera.upperBound.Set(x + 20 + 8, 10);
      return camera;
    };
    terrain.load(camera_at(ball->GetPosition().x));
    // A crater 2 m across at x = 36 m, in a chunk not loaded yet.
    const dyop::box2d::TerrainResult dug = terrain.remove(b2Vec2(36, 0), 1.0f);
    std::printf("crater dug while unloaded: %d chunk(s) changed, %d fixtures created\n", dug.chunks,
                dug.created);
    int most_loaded = 0;
    for (int step = 1; step <= 600; ++step) {
      ball->SetAngularVelocity(-8);  // rolling along +x at about 4 m/s until it meets the crater
      world.Step(1.0f / 60, 8, 3);
      terrain.load(camera_at(ball->GetPosition().x));
      most_loaded = std::max(most_loaded, terrain.loaded_chunks());
      if (step % 120 == 0) {
        const b2Vec2 p = ball->GetPosition();
        std::printf(
            "t = %4.1f s: ball at (%6.2f, %6.2f); loaded %d of %d chunks, %zu of %d "
            "triangles, %d proxies\n",
            step / 60.0, p.x, p.y, terrain.loaded_chunks(), all_chunks, terrain.fixtures().size(),
            all_triangles, world.GetProxyCount());
      }
    }
    // The crater dug while unloaded stopped the ball (it rests in it), and the world held a few
    // chunks at a time (the camera spans 5 columns of 3), never the level.
    const b2Vec2 end = ball->GetPosition();
    ok = std::fabs(end.x - 36) < 1.5f && end.y < 0 && most_loaded <= all_chunks / 3;
    std::printf("ball ends at (%.2f, %.2f); at most %d of %d chunks loaded\n", end.x, end.y,
                most_loaded, all_chunks);
  }
  dyop::box2d::uninstall();
  return ok ? 0 : 1;
}
