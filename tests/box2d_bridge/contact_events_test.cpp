// What a contact listener and `b2Contact::IsTouching` report under the internal-edge rule. A pair
// the rule answers with no contact (a box on a triangulated ground touching a triangle only at a
// closed vertex) is not touching: no `BeginContact`, no `PreSolve`, though its shapes overlap
// within their skins; the body's other pairs carry it, so it keeps a touching contact every step.
// Sensors never reach the plug-in (Box2D tests their overlap itself) and report every overlap.
#include <gtest/gtest.h>

#include <box2d/box2d.h>

#include <map>

#include "dyop/box2d.hpp"
#include "support/worlds.hpp"

namespace dyop::box2d::testing {
namespace {

// Begin, end and pre-solve calls per ground fixture, and per sensor.
struct ListenerEvents : b2ContactListener {
  std::map<const b2Fixture*, int> begun, ended, presolved, sensor_begun;

  static const b2Fixture* ground_side(const b2Contact* c) {
    const b2Fixture* a = c->GetFixtureA();
    return a->GetBody()->GetType() == b2_staticBody ? a : c->GetFixtureB();
  }
  static bool sensor(const b2Contact* c) {
    return c->GetFixtureA()->IsSensor() || c->GetFixtureB()->IsSensor();
  }
  void BeginContact(b2Contact* c) override { ++(sensor(c) ? sensor_begun : begun)[ground_side(c)]; }
  void EndContact(b2Contact* c) override {
    if (!sensor(c)) ++ended[ground_side(c)];
  }
  void PreSolve(b2Contact* c, const b2Manifold*) override { ++presolved[ground_side(c)]; }
};

// The triangle of `add_triangle_ground`'s cell [x, x + 1] whose only point on the top is its
// corner (x + 1, 0): a box resting over that corner touches it there alone.
const b2Fixture* corner_triangle(b2Body* ground, float x) {
  for (const b2Fixture* f = ground->GetFixtureList(); f != nullptr; f = f->GetNext()) {
    const auto& p = *static_cast<const b2PolygonShape*>(f->GetShape());
    b2Vec2 lo = p.m_vertices[0];
    int on_top = 0;
    for (int i = 0; i < p.m_count; ++i) {
      lo = b2Min(lo, p.m_vertices[i]);
      on_top += p.m_vertices[i].y == 0.0f;
    }
    if (lo.x == x && on_top == 1) return f;
  }
  return nullptr;
}

// A 1 m frictionless `SetAsBox` box resting over the ground's vertex (0, 0), pushed at `speed`,
// with a sensor 0.1 m larger on it when `with_sensor`; 240 steps.
struct EventRecord {
  ListenerEvents events;
  const b2Fixture* corner = nullptr;
  int steps_untouched = 0;  // steps after which none of the box's own pairs was touching
  bool corner_touching = false;
  bool corner_overlaps = false;  // the shapes within their skins (b2TestOverlap)
};

void record_events(EventRecord& out, float speed, bool with_sensor) {
  World world;
  world->SetContactListener(&out.events);
  b2Body* ground = add_triangle_ground(world, 20.0f);
  out.corner = corner_triangle(ground, -1.0f);
  ASSERT_NE(out.corner, nullptr);
  b2Body* box = add_body(world, b2_dynamicBody, b2Vec2(0.0f, 0.5f));
  const b2Fixture* solid = add_box(box, 0.5f, 0.5f, kIce);
  if (with_sensor) add_box(box, 0.6f, 0.6f, kIce, b2Vec2(0, 0), true);
  box->SetLinearVelocity(b2Vec2(speed, 0));
  for (int i = 0; i < 240; ++i) {
    world.step();
    bool touching = false;
    for (b2ContactEdge* e = box->GetContactList(); e != nullptr; e = e->next) {
      touching = touching || (e->contact->IsTouching() && !ListenerEvents::sensor(e->contact));
    }
    out.steps_untouched += !touching;
  }
  for (b2ContactEdge* e = box->GetContactList(); e != nullptr; e = e->next) {
    if (ListenerEvents::ground_side(e->contact) != out.corner || ListenerEvents::sensor(e->contact))
      continue;
    out.corner_touching = e->contact->IsTouching();
  }
  out.corner_overlaps = b2TestOverlap(out.corner->GetShape(), 0, solid->GetShape(), 0,
                                      ground->GetTransform(), box->GetTransform());
}

class ContactEvents : public ::testing::Test {
 protected:
  void TearDown() override { uninstall(); }
};

TEST_F(ContactEvents, APairTheRuleAnswersWithNoContactIsNotTouchingAndNeverBegins) {
  // Box2D's own contact touches the corner triangle at its top vertex.
  uninstall();
  EventRecord own;
  record_events(own, 0, false);
  EXPECT_TRUE(own.corner_touching);
  EXPECT_EQ(own.events.begun.count(own.corner), 1u);

  // The plug-in's rule closes that vertex (both its edges are internal): no contact.
  ASSERT_TRUE(install(Backend::Dyop).ok());
  EventRecord plugin;
  record_events(plugin, 0, false);
  EXPECT_TRUE(plugin.corner_overlaps);   // the shapes are within their skins...
  EXPECT_FALSE(plugin.corner_touching);  // ...but the pair is not touching
  EXPECT_EQ(plugin.events.begun.count(plugin.corner), 0u);
  EXPECT_EQ(plugin.events.presolved.count(plugin.corner), 0u);
  EXPECT_EQ(plugin.steps_untouched, 0);
}

TEST_F(ContactEvents, ABodyGlidingOverTriangulatedGroundKeepsATouchingContactEveryStep) {
  ASSERT_TRUE(install(Backend::Dyop).ok());
  EventRecord glide;
  record_events(glide, 3, false);
  EXPECT_EQ(glide.steps_untouched, 0);
  // Every contact begun has ended but the ones touching at the end, each fixture once: fewer
  // than under Box2D's own contact, which also begins on the closed corners.
  int begun = 0, ended = 0;
  for (const auto& [fixture, n] : glide.events.begun) {
    EXPECT_EQ(n, 1);
    begun += n;
  }
  for (const auto& [fixture, n] : glide.events.ended) ended += n;
  EXPECT_LE(begun - ended, 2);
  uninstall();
  EventRecord own;
  record_events(own, 3, false);
  EXPECT_GT(own.events.begun.size(), glide.events.begun.size());
}

TEST_F(ContactEvents, SensorsBeginOnEveryOverlapWhateverTheRuleAnswers) {
  ASSERT_TRUE(install(Backend::Dyop).ok());
  EventRecord plugin;
  record_events(plugin, 0, true);
  EXPECT_EQ(plugin.events.sensor_begun.count(plugin.corner), 1u);
  EXPECT_EQ(plugin.events.begun.count(plugin.corner), 0u);
  uninstall();
  EventRecord own;
  record_events(own, 0, true);
  // The same triangles, Box2D's own contact or the plug-in's.
  EXPECT_EQ(own.events.sensor_begun.size(), plugin.events.sensor_begun.size());
}

}  // namespace
}  // namespace dyop::box2d::testing
