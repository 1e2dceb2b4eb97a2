// A level from its outline: 300 m of ground whose top runs flat for 40 m and then over hills, with
// caves under it and an overhang at its end, given as the rings a Box2D user would feed
// `b2ChainShape`, triangulated by `dyop::box2d::add_outline` with its edge data fixed. Prints what
// was built and how long it took, then pushes a crate and a ball along the flat stretch at 4 m/s
// with the plug-in installed: their largest vertical speed (0 m/s: a glide, no ghost collision on
// the triangles' seams) and how far they went.
#include <box2d/box2d.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

#include <dyop/box2d.hpp>
#include <dyop/box2d_outline.hpp>

#include "level_outline.hpp"

int main() {
  if (!dyop::box2d::install(dyop::box2d::Backend::Dyop).ok()) return 1;
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
      return 1;
    }
    std::printf("outline of %zu rings: %d vertices kept, %zu triangles, built in %.1f ms\n",
                rings.size(), r.vertices, r.mesh.fixtures.size(), ms);

    b2Body* bodies[2];
    for (int k = 0; k < 2; ++k) {
      b2BodyDef def;
      def.type = b2_dynamicBody;
      def.position.Set(2, 0.305f);
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
    for (int step = 0; step < 360; ++step) {
      world.Step(1.0f / 60, 8, 3);
      for (int k = 0; k < 2; ++k) {
        vertical[k] = std::fmax(vertical[k], std::fabs(bodies[k]->GetLinearVelocity().y));
      }
    }
    for (int k = 0; k < 2; ++k) {
      std::printf("%s: largest vertical speed %.3f m/s, travelled %.2f m of %.2f\n",
                  k == 0 ? "crate" : "ball", vertical[k], bodies[k]->GetPosition().x - 2, 4 * 6.0);
    }
  }
  dyop::box2d::uninstall();
  return 0;
}
