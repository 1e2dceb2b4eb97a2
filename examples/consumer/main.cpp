// A Box2D program that uses DyOP-PD through its CMake package (or add_subdirectory): a triangle
// dropped on a triangle ground with the plug-in installed, and one query to the solver
// itself. Prints what it checks and exits non-zero when an answer is wrong.
#include <box2d/box2d.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

#include <dyop/box2d.hpp>
#include <dyop/dyop.hpp>
#include <dyop/version.hpp>

namespace {

// A body of one triangle fixture (density 1 when dynamic), or nullptr with the reason printed.
b2Body* triangle_body(b2World& world, b2BodyType type, b2Vec2 position,
                      const std::array<b2Vec2, 3>& p) {
  const dyop::box2d::TriangleShape t = dyop::box2d::make_triangle(p[0], p[1], p[2]);
  if (!t.ok()) {
    std::fprintf(stderr, "triangle: %s\n", t.message);
    return nullptr;
  }
  b2BodyDef def;
  def.type = type;
  def.position = position;
  b2Body* body = world.CreateBody(&def);
  body->CreateFixture(&t.shape, type == b2_dynamicBody ? 1.0f : 0.0f);
  return body;
}

// The world: a triangle dropped on a triangle ground (its top edge at y = 0) ends at rest with its
// base on it, not in it and not above it (the two skins less Box2D's allowed overlap: 1.5 cm).
bool world_rests() {
  const dyop::box2d::InstallResult installed = dyop::box2d::install(dyop::box2d::Backend::Dyop);
  if (!installed.ok()) {
    std::fprintf(stderr, "install: %s\n", installed.message);
    return false;
  }
  b2World world(b2Vec2(0.0f, -10.0f));
  const b2Body* ground =
      triangle_body(world, b2_staticBody, b2Vec2(0.0f, 0.0f),
                    {b2Vec2(-5.0f, -2.0f), b2Vec2(5.0f, 0.0f), b2Vec2(-5.0f, 0.0f)});
  const b2Body* body = triangle_body(world, b2_dynamicBody, b2Vec2(0.3f, 0.5f),
                                     {b2Vec2(-0.5f, 0.0f), b2Vec2(0.5f, 0.0f), b2Vec2(0.0f, 0.8f)});
  if (ground == nullptr || body == nullptr) return false;
  for (int i = 0; i < 120; ++i) world.Step(1.0f / 60.0f, 8, 3);

  // Box2D's own contact would rest the same: the manifolds counted prove the plug-in made them.
  const float height = body->GetPosition().y;
  const std::uint64_t manifolds = dyop::box2d::stats().manifolds;
  const bool rests = height > 0.0f && height < 0.04f && manifolds > 0;
  std::printf(
      "world: triangle at rest %.4f m above the triangle ground, %llu manifolds from the "
      "plug-in: %s\n",
      height, static_cast<unsigned long long>(manifolds), rests ? "ok" : "WRONG");
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
