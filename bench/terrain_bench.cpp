// build/bin/dyop_terrain_bench: what editing a chunked terrain (`dyop::box2d::OutlineTerrain`)
// costs on the 300 m level with caves of `dyop compare --section grounds`, with the plug-in
// installed: building it, its memory per chunk, then craters dug one by one along its top under a
// crowd resting on it: the wall time of each edit call (GEOS, fixtures destroyed and created,
// edge data), and of the step after it against the steps before it. Then the streaming: a camera
// window swept along the level, the chunks loaded and unloaded as it goes.
//
//     build/bin/dyop_terrain_bench [craters] [radius]     (defaults: 60 craters of radius 1 m)
#include <box2d/box2d.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

#include "dyop/box2d.hpp"
#include "dyop/box2d_terrain.hpp"
#include "level_outline.hpp"  // examples/

namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point t) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t).count();
}

// This thread's CPU time (ms): beside the wall time, it tells a call that was slow from one that
// was preempted on a machine shared with other jobs.
double cpu_ms() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return 1e3 * static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_nsec);
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n == 0 ? 0 : n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

double quantile(std::vector<double> v, double q) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0 : v[static_cast<std::size_t>(q * static_cast<double>(v.size() - 1))];
}

// The top of the ground at `x` (a ray cast down from above the level's hills).
class FirstHit : public b2RayCastCallback {
 public:
  float ReportFixture(b2Fixture*, const b2Vec2& p, const b2Vec2&, float fraction) override {
    hit = p;
    return fraction;
  }
  b2Vec2 hit{0, -1e9f};
};

float surface(b2World& world, float x) {
  FirstHit ray;
  world.RayCast(&ray, b2Vec2(x, 10), b2Vec2(x, -25));
  return ray.hit.y;
}

// Bytes of Box2D's share of a loaded chunk: its body, and per triangle its fixture, shape, proxy
// and tree leaf (with an inner node amortised per leaf).
std::size_t box2d_bytes(int bodies, int fixtures) {
  constexpr std::size_t per_proxy = sizeof(b2FixtureProxy) + 2 * sizeof(b2TreeNode);
  return static_cast<std::size_t>(bodies) * sizeof(b2Body) +
         static_cast<std::size_t>(fixtures) *
             (sizeof(b2Fixture) + sizeof(b2PolygonShape) + per_proxy);
}

// The 300 m level in `world` as a terrain, timed; its figures printed when `print`.
void build(b2World& world, dyop::box2d::OutlineTerrain& terrain, bool print) {
  const auto start = Clock::now();
  const dyop::box2d::TerrainResult built = terrain.set_outline(level_outline());
  const double build_ms = ms_since(start);
  if (!built.ok()) {
    std::fprintf(stderr, "outline refused: %s\n", built.message);
    std::exit(1);
  }
  (void)world;
  if (!print) return;
  const int chunks = terrain.chunk_count();
  const int fixtures = static_cast<int>(terrain.fixtures().size());
  const std::size_t own = terrain.bytes();
  const std::size_t box2d = box2d_bytes(chunks, fixtures);
  std::printf("300 m level with caves: %d chunks of 16 m, %d triangles, built in %.1f ms\n", chunks,
              fixtures, build_ms);
  std::printf(
      "memory per chunk: %.1f kB (Box2D's body, fixtures and proxies %.1f kB, the terrain's "
      "outline and triangle lists %.1f kB)\n",
      static_cast<double>(own + box2d) / chunks / 1024, static_cast<double>(box2d) / chunks / 1024,
      static_cast<double>(own) / chunks / 1024);
}

// Craters dug at random along the top under a crowd of boxes and balls resting on it, 1.5 m
// apart, in a world where bodies sleep (as in a game) or not (every resting contact collided).
void craters_under_a_crowd(bool sleeping, int craters, float radius) {
  b2World world(b2Vec2(0, -10));
  world.SetAllowSleeping(sleeping);
  dyop::box2d::OutlineTerrain terrain(world);
  build(world, terrain, sleeping);
  for (float x = 2; x < 290; x += 1.5f) {
    b2BodyDef def;
    def.type = b2_dynamicBody;
    def.position.Set(x, surface(world, x) + 0.6f);
    b2Body* body = world.CreateBody(&def);
    b2PolygonShape box;
    box.SetAsBox(0.3f, 0.3f);
    b2CircleShape ball;
    ball.m_radius = 0.3f;
    b2FixtureDef fixture;
    fixture.shape = static_cast<int>(x) % 2 ? static_cast<const b2Shape*>(&box) : &ball;
    fixture.density = 1;
    fixture.friction = 0.6f;
    body->CreateFixture(&fixture);
  }
  const auto step = [&] {
    const auto t = Clock::now();
    world.Step(1.0f / 60, 8, 3);
    return ms_since(t);
  };
  for (int i = 0; i < 180; ++i) step();
  std::mt19937 random(63);
  std::uniform_real_distribution<float> along(5, 285);
  std::vector<double> edits, edits_cpu, before, after, ratios;
  int destroyed = 0, created = 0, kept = 0;
  for (int k = 0; k < craters; ++k) {
    std::vector<double> plain;
    for (int i = 0; i < 5; ++i) plain.push_back(step());
    const float x = along(random);
    const b2Vec2 centre(x, surface(world, x));
    const auto start = Clock::now();
    const double cpu_start = cpu_ms();
    const dyop::box2d::TerrainResult r = terrain.remove(centre, radius);
    edits_cpu.push_back(cpu_ms() - cpu_start);
    edits.push_back(ms_since(start));
    if (!r.ok()) {
      std::fprintf(stderr, "crater refused: %s\n", r.message);
      std::exit(1);
    }
    destroyed += r.destroyed;
    created += r.created;
    kept += r.kept;
    const double next = step();
    before.push_back(median(plain));
    after.push_back(next);
    ratios.push_back(next / median(plain));
  }
  std::printf("%d craters of radius %.2f m dug at random along the top, %zu bodies resting (%s):\n",
              craters, radius, world.GetBodyCount() - terrain.bodies().size(),
              sleeping ? "sleeping allowed" : "sleeping off");
  std::printf(
      "  edit call: median %.3f ms, 90th percentile %.3f ms, largest %.3f ms (CPU time: median "
      "%.3f ms, largest %.3f ms; per crater: %.1f triangles destroyed, %.1f created, %.1f kept)\n",
      median(edits), quantile(edits, 0.9), quantile(edits, 1.0), median(edits_cpu),
      quantile(edits_cpu, 1.0), static_cast<double>(destroyed) / craters,
      static_cast<double>(created) / craters, static_cast<double>(kept) / craters);
  std::printf(
      "  step: %.3f ms before an edit (median of the 5 before each), %.3f ms after it; ratio "
      "median %.2f, 90th percentile %.2f, largest %.2f\n",
      median(before), median(after), median(ratios), quantile(ratios, 0.9), quantile(ratios, 1.0));
}

// A 40 m camera window with a 4 m margin swept along the level, 0.5 m a step.
void streaming() {
  b2World world(b2Vec2(0, -10));
  dyop::box2d::OutlineTerrain terrain(world);
  build(world, terrain, false);
  std::vector<double> loads;
  int most = 0;
  for (float x = 0; x < 260; x += 0.5f) {
    b2AABB camera;
    camera.lowerBound.Set(x - 4, -25);
    camera.upperBound.Set(x + 44, 10);
    const auto start = Clock::now();
    terrain.load(camera);
    loads.push_back(ms_since(start));
    most = std::max(most, terrain.loaded_chunks());
  }
  std::printf(
      "streaming a 48 m window: at most %d of %d chunks loaded; load call median %.3f ms, "
      "largest %.3f ms\n",
      most, terrain.chunk_count(), median(loads), quantile(loads, 1.0));
}

}  // namespace

int main(int argc, char** argv) {
  const int craters = argc > 1 ? std::max(1, std::atoi(argv[1])) : 60;
  const float radius = argc > 2 ? static_cast<float>(std::atof(argv[2])) : 1.0f;
  if (!dyop::box2d::install(dyop::box2d::Backend::Dyop).ok()) return 1;
  craters_under_a_crowd(true, craters, radius);
  craters_under_a_crowd(false, craters, radius);
  streaming();
  dyop::box2d::uninstall();
  return 0;
}
