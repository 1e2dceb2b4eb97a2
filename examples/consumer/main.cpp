// A Box2D program that uses DyOP-PD through its CMake package (or add_subdirectory): a triangle
// dropped on a ground of triangles with the plug-in installed, and one query to the solver
// itself. Prints what it checks and exits non-zero when an answer is wrong.
#include <box2d/box2d.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include <dyop/box2d.hpp>
#include <dyop/dyop.hpp>
#include <dyop/version.hpp>

namespace {

bool add_triangle(b2Body* body, b2Vec2 p0, b2Vec2 p1, b2Vec2 p2, float density) {
  const dyop::box2d::TriangleShape t = dyop::box2d::make_triangle(p0, p1, p2);
  if (!t.ok()) {
    std::fprintf(stderr, "triangle: %s\n", t.message);
    return false;
  }
  body->CreateFixture(&t.shape, density);
  return true;
}

// The world: the dropped triangle's base ends at rest on the ground (top at y = 0), not in it and
// not above it (within a centimetre: the two skins less Box2D's allowed overlap are 1.5 cm).
bool world_rests() {
  const dyop::box2d::InstallResult installed = dyop::box2d::install(dyop::Method::Dyop);
  if (!installed.ok()) {
    std::fprintf(stderr, "install: %s\n", installed.message);
    return false;
  }
  b2World world(b2Vec2(0.0f, -10.0f));
  b2BodyDef ground_def;
  b2Body* ground = world.CreateBody(&ground_def);
  bool ok = true;
  for (float x = -3.0f; x < 3.0f; x += 1.0f) {
    ok = ok && add_triangle(ground, b2Vec2(x, -1.0f), b2Vec2(x + 1, -1.0f), b2Vec2(x + 1, 0.0f), 0);
    ok = ok && add_triangle(ground, b2Vec2(x, -1.0f), b2Vec2(x + 1, 0.0f), b2Vec2(x, 0.0f), 0);
  }
  b2BodyDef body_def;
  body_def.type = b2_dynamicBody;
  body_def.position.Set(0.3f, 0.5f);
  b2Body* body = world.CreateBody(&body_def);
  ok = ok && add_triangle(body, b2Vec2(-0.5f, 0.0f), b2Vec2(0.5f, 0.0f), b2Vec2(0.0f, 0.8f), 1);
  if (!ok) return false;
  for (int i = 0; i < 120; ++i) world.Step(1.0f / 60.0f, 8, 3);

  const float height = body->GetPosition().y;
  const bool rests = height > 0.0f && height < 0.04f;
  std::printf("world: triangle at rest %.4f m above the triangle ground: %s\n", height,
              rests ? "ok" : "WRONG");
  return rests;
}

// The solver: B's top edge is 0.25 inside A's base, so the depth is 0.25 along -y (A to B).
bool depth_is_known() {
  using V = dyop::Vec2<double>;
  const auto a = dyop::Triangle<double>::make(V(0, 0), V(4, 0), V(2, 3));
  const auto b = dyop::Triangle<double>::make(V(1.5, 0.25), V(2.5, 0.25), V(2, -2));
  if (!a.ok() || !b.ok()) return false;
  const dyop::Result<double> r = dyop::dyop(a.triangle, b.triangle);
  const bool right = r.status == dyop::Status::Penetrating && std::abs(r.depth - 0.25) < 1e-12 &&
                     std::abs(r.normal.y() + 1) < 1e-12;
  std::printf("solver: depth %.17g along (%g, %g): %s\n", r.depth, r.normal.x(), r.normal.y(),
              right ? "ok" : "WRONG");
  return right;
}

}  // namespace

int main() {
  std::printf("DyOP-PD %s (%d.%d.%d)\n", DYOP_VERSION_STRING, DYOP_VERSION_MAJOR,
              DYOP_VERSION_MINOR, DYOP_VERSION_PATCH);
  const bool world_ok = world_rests();
  const bool solver_ok = depth_is_known();
  return world_ok && solver_ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
