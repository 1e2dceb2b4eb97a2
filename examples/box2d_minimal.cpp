// The smallest Box2D program whose triangle contacts go through DyOP-PD: a ground made of
// triangles, a triangle dropped on it, its resting height printed after 3 s.
#include <box2d/box2d.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include <dyop/box2d.hpp>

namespace {

// A triangle fixture, or a message naming what is wrong with the points.
bool add_triangle(b2Body* body, b2Vec2 p0, b2Vec2 p1, b2Vec2 p2, float density) {
  const dyop::box2d::TriangleShape t = dyop::box2d::make_triangle(p0, p1, p2);
  if (!t.ok()) {
    std::fprintf(stderr, "triangle: %s\n", t.message);
    return false;
  }
  body->CreateFixture(&t.shape, density);
  return true;
}

}  // namespace

int main() {
  // Line 1 of 2 is the include above; line 2 registers the plug-in before any contact exists.
  const dyop::box2d::InstallResult installed = dyop::box2d::install(dyop::box2d::Backend::Dyop);
  if (!installed.ok()) {
    std::fprintf(stderr, "install: %s\n", installed.message);
    return EXIT_FAILURE;
  }

  // The rest is an ordinary Box2D program.
  b2World world(b2Vec2(0.0f, -10.0f));
  b2BodyDef ground_def;
  b2Body* ground = world.CreateBody(&ground_def);
  bool ok = true;
  for (float x = -5.0f; x < 5.0f; x += 1.0f) {  // top at y = 0, two triangles per metre
    ok = ok && add_triangle(ground, b2Vec2(x, -1.0f), b2Vec2(x + 1, -1.0f), b2Vec2(x + 1, 0.0f), 0);
    ok = ok && add_triangle(ground, b2Vec2(x, -1.0f), b2Vec2(x + 1, 0.0f), b2Vec2(x, 0.0f), 0);
  }
  b2BodyDef body_def;
  body_def.type = b2_dynamicBody;
  body_def.position.Set(0.3f, 2.0f);
  b2Body* body = world.CreateBody(&body_def);
  ok = ok && add_triangle(body, b2Vec2(-0.5f, 0.0f), b2Vec2(0.5f, 0.0f), b2Vec2(0.0f, 0.8f), 1);
  if (!ok) return EXIT_FAILURE;

  for (int i = 0; i < 180; ++i) world.Step(1.0f / 60.0f, 8, 3);

  // At rest the base (the body's origin) sits the two skins (2 × b2_polygonRadius) above the
  // ground, less the b2_linearSlop of overlap Box2D allows: 1.5 cm.
  const float height = body->GetPosition().y;
  const float expected = 2 * b2_polygonRadius - b2_linearSlop;
  const dyop::box2d::Stats stats = dyop::box2d::stats();
  std::printf(
      "resting height %.4f m (expected %.4f m); %llu triangle pairs through %s, %llu "
      "manifolds\n",
      height, expected,
      static_cast<unsigned long long>(stats.triangles(dyop::box2d::Backend::Dyop)),
      dyop::box2d::name(dyop::box2d::Backend::Dyop),
      static_cast<unsigned long long>(stats.manifolds));
  return std::abs(height - expected) <= 0.1f * b2_linearSlop ? EXIT_SUCCESS : EXIT_FAILURE;
}
