// Guide, step 5: contact events and sensors under the internal-edge rule. A crate with a foot
// sensor glides over a ground of triangles at 3 m/s. Where the rule answers "no contact" for a
// touching pair (the crate over a triangle's closed vertex), Box2D is told nothing: that pair is
// not touching, and no BeginContact, PreSolve or EndContact comes for it; the crate's other pairs
// carry it. Sensors are Box2D's own overlap test and see every triangle. Prints the events under
// Box2D's own contact and under the plug-in; exits non-zero unless, under the plug-in, the crate
// has a touching contact after every step and its sensor begins on every triangle it overlaps.
#include <box2d/box2d.h>

#include <cstdio>
#include <cstdlib>

#include <dyop/box2d.hpp>

#include "glide.hpp"
#include "triangle_ground.hpp"

namespace {

struct Counts : b2ContactListener {
  int begins = 0, ends = 0, sensor_begins = 0;
  static bool sensor(const b2Contact* c) {
    return c->GetFixtureA()->IsSensor() || c->GetFixtureB()->IsSensor();
  }
  void BeginContact(b2Contact* c) override { ++(sensor(c) ? sensor_begins : begins); }
  void EndContact(b2Contact* c) override { ends += !sensor(c); }
};

// A common "is it on the ground?" test: any of the body's solid contacts touching.
bool grounded(const b2Body* body) {
  for (const b2ContactEdge* e = body->GetContactList(); e != nullptr; e = e->next) {
    if (e->contact->IsTouching() && !Counts::sensor(e->contact)) return true;
  }
  return false;
}

// Returns true when the crate was grounded after every step.
bool run(const char* title, Counts& counts) {
  b2World world(b2Vec2(0, -10));
  world.SetContactListener(&counts);
  b2BodyDef def;
  b2Body* ground = world.CreateBody(&def);
  example::add_triangle_ground(ground, -2, 20, 1);  // 1 m cells, two triangles each, top at y = 0
  b2Body* crate = example::add_crate(world, b2Vec2(0, 0.5f), 0.5f, b2Vec2(3, 0));
  b2PolygonShape foot;  // a sensor under the crate's bottom
  foot.SetAsBox(0.45f, 0.05f, b2Vec2(0, -0.5f), 0);
  b2FixtureDef sensor;
  sensor.shape = &foot;
  sensor.isSensor = true;
  crate->CreateFixture(&sensor);

  int airborne = 0;
  for (int i = 0; i < 300; ++i) {
    world.Step(1.0f / 60, 8, 3);
    airborne += !grounded(crate);
  }
  std::printf(
      "%s: %d BeginContact, %d EndContact, %d sensor BeginContact; steps not grounded: "
      "%d\n",
      title, counts.begins, counts.ends, counts.sensor_begins, airborne);
  return airborne == 0;
}

}  // namespace

int main() {
  Counts own;
  run("Box2D's own contact", own);
  if (!dyop::box2d::install(dyop::box2d::Backend::Dyop).ok()) return EXIT_FAILURE;
  Counts plugin;
  const bool grounded_throughout = run("the plug-in installed", plugin);
  dyop::box2d::uninstall();
  // Fewer solid contacts begin (none on the closed vertices), the sensor sees the same triangles.
  const bool sensors_unchanged = plugin.sensor_begins == own.sensor_begins;
  const bool ok = grounded_throughout && sensors_unchanged && plugin.begins < own.begins;
  std::printf("%s\n", ok ? "grounded throughout; sensors as under Box2D's own contact" : "FAILED");
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
