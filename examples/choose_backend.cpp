// Guide, step 7: choosing a backend and a `Config`. The same world — a ground of triangles, a
// crate, a ball and a box of two triangles pushed along it at 4 m/s, and a pile of 60 triangles
// dropped away from them — stepped under every backend with its default `Config`, then under `Dyop`
// with `Config::off()` and with Box2D's own contact. Prints, for each, whether the pushed bodies
// glide and the narrow phase's time (`b2Profile::collide`, summed; the machine's noise included).
// Exits non-zero unless the pushed bodies glide under `Dyop` and `Sat` with their defaults.
#include <box2d/box2d.h>

#include <cstdio>
#include <cstdlib>
#include <optional>
#include <vector>

#include <dyop/box2d.hpp>

#include "glide.hpp"
#include "triangle_ground.hpp"

namespace {

// The world under the contact installed now; true when the pushed bodies glide.
bool run(const char* title) {
  b2World world(b2Vec2(0, -10));
  b2BodyDef def;
  b2Body* ground = world.CreateBody(&def);
  example::add_triangle_ground(ground, -20, 25, 0.5f);  // 0.5 m cells of two triangles each
  def.type = b2_dynamicBody;
  for (int k = 0; k < 60; ++k) {  // the pile, dropped at x = -15, away from the pushed bodies
    def.position.Set(-16.5f + 0.6f * static_cast<float>(k % 6),
                     1 + 0.6f * static_cast<float>(k / 6));
    def.angle = 0.7f * static_cast<float>(k);
    example::add_triangle(world.CreateBody(&def), {-0.25f, -0.2f}, {0.25f, -0.2f}, {0, 0.25f}, 1);
  }
  std::vector<example::Pushed> bodies = example::push_all(world, b2Vec2(0, 0), 4);
  const example::Timing t = example::step_and_watch(world, bodies, 5);
  bool all = true;
  for (const example::Pushed& p : bodies) all = all && p.glided();
  std::printf("%-22s %-26s narrow phase %6.1f ms, step %6.1f ms\n", title,
              all ? "every pushed body glides;" : "ghost collisions (trips);", t.collide, t.step);
  return all;
}

}  // namespace

int main() {
  bool exact_glide = true;
  for (dyop::box2d::Backend b : dyop::box2d::all_backends) {
    if (!dyop::box2d::install(b).ok()) return EXIT_FAILURE;
    const bool glided = run(dyop::box2d::name(b));
    if (b == dyop::box2d::Backend::Dyop || b == dyop::box2d::Backend::Sat) {
      exact_glide = exact_glide && glided;
    }
  }
  dyop::box2d::install(dyop::box2d::Backend::Dyop, dyop::box2d::Config::off());
  run("dyop, Config::off()");
  dyop::box2d::uninstall();
  run("Box2D's own contact");
  return exact_glide ? EXIT_SUCCESS : EXIT_FAILURE;
}
