// Guide, step 4: a one-way platform, Box2D's classic pattern, under the plug-in. A platform of
// eight `SetAsBox` tiles hangs at y = 3; a crate jumps up through it from below, lands on it, and
// slides along it over the tiles' seams. A contact listener's `PreSolve` disables the platform's
// contacts while the crate is not above it, reading the manifold the plug-in made as it would
// Box2D's own
// (`GetWorldManifold`). Exits non-zero unless the crate passes through from below and then rests
// on top, gliding.
#include <box2d/box2d.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include <dyop/box2d.hpp>

#include "glide.hpp"

namespace {

constexpr float kTop = 3;  // the platform's top (m)

// Lets bodies through the platform from below: a contact with it is enabled only while each of
// its manifold points lies on the platform's top, not below it (Box2D re-enables every contact
// before each step's PreSolve, so the test runs every step).
class OneWay : public b2ContactListener {
 public:
  explicit OneWay(const b2Body* platform) : platform_(platform) {}

  void PreSolve(b2Contact* contact, const b2Manifold*) override {
    if (contact->GetFixtureA()->GetBody() != platform_ &&
        contact->GetFixtureB()->GetBody() != platform_) {
      return;
    }
    b2WorldManifold wm;
    contact->GetWorldManifold(&wm);
    // A point lies midway between the two surfaces: on a resting body, within the skins of the
    // top. Lower than that, the body is still coming up through the platform.
    for (int i = 0; i < contact->GetManifold()->pointCount; ++i) {
      if (wm.points[i].y < kTop - 3 * b2_linearSlop) contact->SetEnabled(false);
    }
  }

 private:
  const b2Body* platform_;
};

}  // namespace

int main() {
  if (!dyop::box2d::install(dyop::box2d::Backend::Dyop).ok()) return EXIT_FAILURE;
  bool passed = false, rests = false, glides = false;
  {
    b2World world(b2Vec2(0, -10));
    b2BodyDef def;
    def.position.Set(0, kTop - 0.25f);
    b2Body* platform = world.CreateBody(&def);
    for (int i = 0; i < 8; ++i) {
      b2PolygonShape tile;
      tile.SetAsBox(0.25f, 0.25f, b2Vec2(0.25f + 0.5f * static_cast<float>(i), 0), 0);
      platform->CreateFixture(&tile, 0);
    }
    OneWay one_way(platform);
    world.SetContactListener(&one_way);

    // A jump from under the platform: up 4 m, and to the right.
    b2Body* crate = example::add_crate(world, b2Vec2(0.4f, 1), 0.2f, b2Vec2(0.8f, 9));

    float lowest_below = 10, vertical_after_landing = 0;
    for (int step = 0; step < 180; ++step) {
      world.Step(1.0f / 60, 8, 3);
      const float bottom = crate->GetPosition().y - 0.2f;
      lowest_below = std::fmin(lowest_below, bottom);
      if (step >= 120) {  // landed by then: gliding along the tiles
        vertical_after_landing =
            std::fmax(vertical_after_landing, std::fabs(crate->GetLinearVelocity().y));
      }
    }
    const float bottom = crate->GetPosition().y - 0.2f;
    passed = lowest_below < kTop - 1;
    rests = std::fabs(bottom - kTop) < 2 * b2_polygonRadius;
    glides = vertical_after_landing < 0.05f && crate->GetPosition().x > 2.5f;
    std::printf(
        "the crate started below the platform (bottom at %.2f m), now rests at %.3f m "
        "(the top: %.1f m), x = %.2f m; vertical speed after landing %.3f m/s\n",
        lowest_below, bottom, kTop, crate->GetPosition().x, vertical_after_landing);
  }
  dyop::box2d::uninstall();
  const bool ok = passed && rests && glides;
  std::printf("%s\n", ok ? "passed through from below, landed, glides" : "FAILED");
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
