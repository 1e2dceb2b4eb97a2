#include "experiments/terrain_runs.hpp"

#include <algorithm>
#include <stdexcept>

#ifdef DYOP_WITH_OUTLINES
#include <box2d/box2d.h>
#include <time.h>

#include <chrono>
#include <cmath>
#include <memory>
#include <random>
#include <tuple>

#include "dyop/box2d_outline.hpp"
#include "dyop/box2d_terrain.hpp"
#include "experiments/everyday_bodies.hpp"
#include "experiments/ground_measures.hpp"
#include "level_outline.hpp"  // examples/: the 300 m level with caves
#include "scenes/installation.hpp"
#include "scenes/metrics.hpp"
#include "worlds/world.hpp"
#endif

namespace dyop::experiments {

int TerrainTiming::craters() const {
  return std::max(1, (crater_steps + crater_interval_steps - 1) / crater_interval_steps);
}

TerrainTiming terrain_timing(bool quick, std::optional<int> steps) {
  TerrainTiming t;
  t.crater_runs = quick ? 1 : 3;
  if (quick) t.stream_steps = 3840;  // 256 m
  if (steps) t.crater_steps = t.stream_steps = std::max(1, *steps);
  return t;
}

#ifdef DYOP_WITH_OUTLINES

namespace {

// Times `call()`: its wall time and this thread's CPU time (ms). The CPU time tells a slow call
// from one preempted on a machine shared with other jobs.
template <class Call>
std::pair<double, double> timed(Call&& call) {
  timespec cpu_start{}, cpu_end{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &cpu_start);
  const auto start = std::chrono::steady_clock::now();
  call();
  const std::chrono::duration<double, std::milli> wall = std::chrono::steady_clock::now() - start;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &cpu_end);
  return {wall.count(), 1e3 * static_cast<double>(cpu_end.tv_sec - cpu_start.tv_sec) +
                            1e-6 * static_cast<double>(cpu_end.tv_nsec - cpu_start.tv_nsec)};
}

void set_filter(b2Body* body, uint16 category, uint16 mask, int16 group = 0) {
  for (b2Fixture* f = body->GetFixtureList(); f != nullptr; f = f->GetNext()) {
    b2Filter filter;
    filter.categoryBits = category;
    filter.maskBits = mask;
    filter.groupIndex = group;
    f->SetFilterData(filter);
  }
}

int fixture_count(const b2Body* body) {
  int n = 0;
  for (const b2Fixture* f = body->GetFixtureList(); f != nullptr; f = f->GetNext()) ++n;
  return n;
}

// A body of the everyday `shape` resting on a top whose height is `y` and slope `slope` at `x`,
// turned with it, 5 mm above it.
b2Body* add_on_top(worlds::World& world, const b2Shape* shape, float x, float y, float slope,
                   float friction) {
  b2Body* body = add_everyday_body(world, shape, {x, y}, friction);
  const float angle = std::atan(slope);
  const b2Vec2 up(-std::sin(angle), std::cos(angle));
  body->SetTransform(b2Vec2(x, y) + (resting_height(shape) + 0.005f) * up, angle);
  return body;
}

void throw_if_refused(const box2d::TerrainResult& r, const char* what) {
  if (!r.ok()) throw std::runtime_error(std::string("terrain: ") + what + " refused: " + r.message);
}

// ---- The crater scene.

// Collision categories: the ground's (Box2D's default), the resting crowd's, the pushed bodies'
// (they meet the ground alone).
constexpr uint16 kGround = 0x0001, kResting = 0x0002, kPushed = 0x0004;

constexpr float kFriction = 0.6f;
constexpr float kSpacing = 1.5f;        // m between resting bodies, from x = 2 m to 290 m
constexpr float kHalfWidth = 0.3f;      // m: every everyday body's half-width, at most
constexpr float kLevelSlope = 0.0524f;  // tan 3°: balls rest only where the top is this level
constexpr int kPushedBodies = 8;        // two of each kind, 36 m apart from x = 4 m
constexpr float kPushSpeed = 2;         // m/s along +x
constexpr float kPushGain = 10;         // 1/s: how fast the push brings a body to its speed
constexpr float kPushMost = 12;  // m/s²: 1.2 g, enough up the level's 19° hills against friction
constexpr int kSettleSteps = 60;
constexpr float kRadii[] = {1, 1.5f, 2};  // m, in turn
constexpr float kRimGap = 0.5f;  // m between a crater's rim and the side of its body, beside it
constexpr float kAhead = 3;      // m ahead of a pushed body
constexpr float kBottom = -20;   // m: the level's bottom
constexpr float kFellIn = 0.2f;  // m below its resting height: a body in a crater
constexpr float kRayTop = 10, kRayBottom = -25;  // m: above the level's hills, below its bottom

// The first static fixture met by a ray down through x: the top of the ground.
class TopOfGround : public b2RayCastCallback {
 public:
  float ReportFixture(b2Fixture* f, const b2Vec2& p, const b2Vec2&, float fraction) override {
    if (f->GetBody()->GetType() != b2_staticBody) return -1;  // a body of the crowd: passed
    hit = p;
    return fraction;
  }
  b2Vec2 hit{0, kRayBottom};
};

float top_at(b2World& world, float x) {
  TopOfGround ray;
  world.RayCast(&ray, b2Vec2(x, kRayTop), b2Vec2(x, kRayBottom));
  return ray.hit.y;
}

box2d::TerrainOptions crater_terrain_options() {
  box2d::TerrainOptions o;
  o.fixture.friction = kFriction;
  return o;
}

struct PlannedCrater {
  float x = 0;
  float radius = 0;
  const char* placement = "";
};

class CraterScene {
 public:
  CraterScene(const TerrainTiming& timing, std::uint64_t seed)
      : terrain(world.get(), crater_terrain_options()) {
    throw_if_refused(terrain.set_outline(level_outline()), "the level was");
    triangles = terrain.triangle_count();
    const EverydayShapes shapes;
    const auto kinds = shapes.all();
    std::size_t next = 0;
    const auto slope_at = [&](float x) {
      return (top_at(world.get(), x + 0.25f) - top_at(world.get(), x - 0.25f)) / 0.5f;
    };
    for (float x = 2; x <= 290; x += kSpacing) {
      std::size_t k = next++ % kinds.size();
      const float slope = slope_at(x);
      if (kinds[k].second == &shapes.ball && std::abs(slope) > kLevelSlope)
        k = (k + 1) % kinds.size();
      b2Body* b = add_on_top(world, kinds[k].second, x, top_at(world.get(), x), slope, kFriction);
      set_filter(b, kResting, kGround | kResting);
      crowd.push_back(b);
    }
    resting = static_cast<int>(crowd.size());
    for (int j = 0; j < kPushedBodies; ++j) {
      const float x = 4 + 36 * static_cast<float>(j);
      const b2Shape* shape = kinds[static_cast<std::size_t>(j) % kinds.size()].second;
      b2Body* b = add_on_top(world, shape, x, top_at(world.get(), x), slope_at(x), kFriction);
      set_filter(b, kPushed, kGround);
      crowd.push_back(b);
    }
    plan(timing, seed);
    still.assign(crowd.size(), 0);
    for (int i = 0; i < kSettleSteps; ++i) {
      world.step();
      note_stillness();
    }
    for (const b2Body* b : crowd) rest_y.push_back(b->GetPosition().y);
  }

  // After a step: how long each body has been still.
  void note_stillness() {
    for (std::size_t i = 0; i < crowd.size(); ++i) {
      still[i] = crowd[i]->GetLinearVelocity().Length() <= resting_speed ? still[i] + 1 : 0;
    }
  }

  // True when `body` rests: not pushed, and still for `resting_steps` steps.
  bool rests(std::size_t body) const {
    return static_cast<int>(body) < resting && still[body] >= resting_steps;
  }

  // Pushes the pushed bodies towards their speed along +x, for the next step.
  void push() {
    for (std::size_t i = static_cast<std::size_t>(resting); i < crowd.size(); ++i) {
      b2Body* b = crowd[i];
      const float a =
          std::clamp(kPushGain * (kPushSpeed - b->GetLinearVelocity().x), -kPushMost, kPushMost);
      b->ApplyForceToCenter(b2Vec2(b->GetMass() * a, 0), true);
    }
  }

  // The crater planned before `step`, if any.
  const PlannedCrater* crater_at(int step) const {
    if (step % crater_interval_steps != 0) return nullptr;
    const std::size_t k = static_cast<std::size_t>(step / crater_interval_steps);
    return k < planned.size() ? &planned[k] : nullptr;
  }

  // Where `c` is dug: on the top at its x as it is now.
  b2Vec2 centre_of(const PlannedCrater& c) { return {c.x, top_at(world.get(), c.x)}; }

  worlds::World world;            // the testbed's: sleeping off
  box2d::OutlineTerrain terrain;  // destroyed before the world, as it must be
  std::vector<b2Body*> crowd;     // resting bodies, then the pushed ones
  int resting = 0;
  int triangles = 0;
  std::vector<float> rest_y;  // each body's height after settling
  std::vector<int> still;     // steps each body has been still for, up to now
  std::vector<PlannedCrater> planned;

 private:
  // The craters, from the bodies' places and the seed alone, so that the ground changes alike
  // whatever answers the contacts (a recording's two sides make the same fixtures).
  void plan(const TerrainTiming& timing, std::uint64_t seed) {
    std::mt19937_64 random(seed);
    std::vector<float> targets;  // resting bodies away from the level's ends
    for (int i = 0; i < resting; ++i) {
      const float x = crowd[static_cast<std::size_t>(i)]->GetPosition().x;
      if (x >= 6 && x <= 286) targets.push_back(x);
    }
    for (int k = 0; k < timing.craters(); ++k) {
      PlannedCrater c;
      c.radius = kRadii[k % 3];
      if (k % 4 == 3) {
        const std::size_t j = static_cast<std::size_t>(resting) + random() % kPushedBodies;
        const float seconds = static_cast<float>(k * crater_interval_steps) * worlds::time_step;
        c.x = crowd[j]->GetPosition().x + kPushSpeed * seconds + kAhead;
        c.placement = "ahead";
      } else {
        const float x = targets[random() % targets.size()];
        const bool under = k % 2 == 0;
        const float side = random() % 2 ? 1.0f : -1.0f;
        c.x = under ? x : x + side * (kHalfWidth + kRimGap + c.radius);
        c.placement = under ? "under" : "beside";
      }
      planned.push_back(c);
    }
  }
};

bool touches_another_body(const b2Body* body) {
  for (const b2ContactEdge* e = body->GetContactList(); e != nullptr; e = e->next) {
    if (e->contact->IsTouching() && e->other->GetType() == b2_dynamicBody) return true;
  }
  return false;
}

// The largest overlap of the skins of a dynamic body and a static one in the world (m).
double deepest_ground_overlap(b2World& world) {
  double deepest = 0;
  for (b2Contact* c = world.GetContactList(); c != nullptr; c = c->GetNext()) {
    const b2Fixture* a = c->GetFixtureA();
    const b2Fixture* b = c->GetFixtureB();
    if (!c->IsTouching() ||
        (a->GetBody()->GetType() == b2_staticBody) == (b->GetBody()->GetType() == b2_staticBody)) {
      continue;
    }
    b2WorldManifold m;
    m.Initialize(c->GetManifold(), a->GetBody()->GetTransform(), a->GetShape()->m_radius,
                 b->GetBody()->GetTransform(), b->GetShape()->m_radius);
    for (int i = 0; i < c->GetManifold()->pointCount; ++i) {
      deepest = std::max(deepest, -double{m.separations[i]});
    }
  }
  return deepest;
}

// A body followed after an edit, until the next.
struct Followed {
  std::size_t body;
  bool far;
  bool struck = false;  // touched another body: its speed is not the ground's alone
  double vertical = 0;
};

void close_edit(TerrainEdit& e, const std::vector<Followed>& followed) {
  for (const Followed& f : followed) {
    if (f.struck) continue;
    if (f.far) {
      ++e.far_bodies;
      e.far_vertical_speed = std::max(e.far_vertical_speed, f.vertical);
    } else {
      ++e.near_bodies;
      e.near_vertical_speed = std::max(e.near_vertical_speed, f.vertical);
    }
  }
}

void crater_run(int run, const TerrainTiming& timing, std::uint64_t seed, TerrainCraters& out) {
  CraterScene scene(timing, seed);
  out.bodies = static_cast<int>(scene.crowd.size());
  out.pushed = kPushedBodies;
  out.chunks = scene.terrain.chunk_count();
  out.triangles = scene.triangles;
  std::vector<Followed> followed;
  for (int step = 0; step < timing.crater_steps; ++step) {
    scene.push();
    const PlannedCrater* crater = scene.crater_at(step);
    if (crater) {
      if (!followed.empty()) close_edit(out.edits.back(), followed);
      followed.clear();
      TerrainEdit e;
      e.run = run;
      e.step = step;
      e.centre = scene.centre_of(*crater);
      e.radius = crater->radius;
      e.placement = crater->placement;
      box2d::TerrainResult r;
      std::tie(e.edit_ms, e.edit_cpu_ms) =
          timed([&] { r = scene.terrain.remove(e.centre, e.radius); });
      throw_if_refused(r, "a crater was");
      e.destroyed = r.destroyed;
      e.created = r.created;
      e.kept = r.kept;
      for (std::size_t i = 0; i < scene.crowd.size(); ++i) {
        const b2Body* b = scene.crowd[i];
        if (!scene.rests(i)) continue;
        const double gap = std::abs(b->GetPosition().x - e.centre.x) - e.radius - kHalfWidth;
        if (gap >= 0) followed.push_back({i, gap >= far_from_edit});
      }
      out.edits.push_back(e);
    }
    const auto [wall, cpu] = timed([&] { scene.world.step(); });
    scene.note_stillness();
    if (crater) {
      out.edits.back().step_ms = wall;
      out.edits.back().step_cpu_ms = cpu;
    } else {
      out.plain_step_ms.push_back(wall);
      out.plain_step_cpu_ms.push_back(cpu);
    }
    for (Followed& f : followed) {
      const b2Body* b = scene.crowd[f.body];
      f.vertical = std::max(f.vertical, std::abs(double{b->GetLinearVelocity().y}));
      f.struck = f.struck || touches_another_body(b);
    }
    for (const b2Body* b : scene.crowd) {
      ++out.checks;
      out.inside += scene.terrain.solid(b->GetPosition());
    }
    out.deepest_overlap = std::max(out.deepest_overlap, deepest_ground_overlap(scene.world.get()));
  }
  if (!followed.empty()) close_edit(out.edits.back(), followed);
  for (std::size_t i = 0; i < scene.crowd.size(); ++i) {
    const float y = scene.crowd[i]->GetPosition().y;
    out.below += y < kBottom;
    out.fell_in += y < scene.rest_y[i] - kFellIn;
  }
}

// ---- The streamed slide.

// The kilometres: 1,024 m of ground 20 m deep, its top a vertex every 8 m. The flat one's top is
// y = 0, the side between two rows of chunks. The undulating one's segment i has the slope
// `slope_steps(i)` / 512, a triangle wave between ±8/512 (period 32 segments, 256 m), from
// y = -0.5 m at x = 0. Why these numbers: its vertices' heights are multiples of 1/64 m and its top
// meets every cell side (x a multiple of 2 m) on the terrain's 1/256 m grid, so rounding to the
// grid bends it nowhere else; a turn of 1/512 at a vertex is 8 mm/s across the ground at 4 m/s.
constexpr float kSegment = 8;
constexpr int kSegments = 128;  // 1,024 m: 64 chunks across
constexpr float kSlopeStep = 1.0f / 512;
constexpr float kUndulatingStart = -0.5f;
constexpr float kStreamDepth = 20;
constexpr float kStreamStart = 4;  // m: the bodies' start, on the first (level) segment
constexpr float kGlideSpeed = 4;   // m/s
constexpr float kGravity = 10;     // m/s², the testbed's worlds'
// The camera: a 24 × 16 m view centred on the body, the loaded region 10 m beyond it.
constexpr float kViewHalfWidth = 12, kViewHalfHeight = 8, kMargin = 10;

int slope_steps(bool undulating, int segment) {
  const int p = segment % 32;
  return !undulating ? 0 : p <= 8 ? p : p <= 24 ? 16 - p : p - 32;
}

float stream_slope(bool undulating, float x) {
  const int segment = std::clamp(static_cast<int>(std::floor(x / kSegment)), 0, kSegments - 1);
  return kSlopeStep * static_cast<float>(slope_steps(undulating, segment));
}

float start_height(bool undulating) { return undulating ? kUndulatingStart : 0; }

std::vector<std::vector<b2Vec2>> stream_rings(bool undulating) {
  std::vector<float> heights = {start_height(undulating)};
  for (int i = 0; i < kSegments; ++i) {
    heights.push_back(heights.back() +
                      kSegment * kSlopeStep * static_cast<float>(slope_steps(undulating, i)));
  }
  std::vector<b2Vec2> ring;  // counter-clockwise: the top from the far end back, then the bottom
  for (int i = kSegments; i >= 0; --i) {
    ring.push_back({kSegment * static_cast<float>(i), heights[static_cast<std::size_t>(i)]});
  }
  const float length = kSegment * kSegments;
  ring.push_back({0, -kStreamDepth});
  ring.push_back({length, -kStreamDepth});
  return {ring};
}

b2AABB camera_region(const b2Vec2& centre) {
  const b2Vec2 half(kViewHalfWidth + kMargin, kViewHalfHeight + kMargin);
  b2AABB region;
  region.lowerBound = centre - half;
  region.upperBound = centre + half;
  return region;
}

double box2d_terrain_bytes(double bodies, double fixtures) {
  return bodies * static_cast<double>(sizeof(b2Body)) +
         fixtures * fixtures_bytes<b2PolygonShape>(1);
}

// The same outline as a chain loop and through `add_outline`, each whole in a world of its own.
void other_grounds(const std::vector<std::vector<b2Vec2>>& rings, TerrainStream& out) {
  {
    worlds::World world;
    b2Body* ground = worlds::add_body(world, b2_staticBody, b2Vec2(0, 0));
    TerrainMemory m{"b2ChainShape loop", 1, 0, 0, static_cast<double>(sizeof(b2Body)), 0, 0};
    for (const std::vector<b2Vec2>& loop : chain_loops_of(rings)) {
      b2ChainShape chain;
      chain.CreateLoop(loop.data(), static_cast<int>(loop.size()));
      ground->CreateFixture(&chain, 0);
      m.fixtures += 1;
      m.proxies += chain.GetChildCount();
      m.box2d_bytes += chain_bytes(chain);
    }
    out.memory.push_back(m);
  }
  worlds::World world;
  b2Body* ground = worlds::add_body(world, b2_staticBody, b2Vec2(0, 0));
  const box2d::OutlineResult r = box2d::add_outline(*ground, rings);
  if (!r.ok()) throw std::runtime_error(std::string("terrain: add_outline refused: ") + r.message);
  const double n = static_cast<double>(r.mesh.fixtures.size());
  out.memory.push_back({"add_outline", 1, n, n, box2d_terrain_bytes(1, n), 0, 0});
}

// The streamed slides' counts, over every body's run and step.
struct StreamTally {
  std::int64_t samples = 0;
  int loaded_max = 0, bodies_max = 0, fixtures_max = 0, proxies_max = 0;
  double loaded = 0, bodies = 0, fixtures = 0, proxies = 0, terrain_fixtures = 0;
  std::vector<double> loads;  // each `load` call's wall time (ms)
  TerrainMemory all{"OutlineTerrain, every chunk loaded", 0, 0, 0, 0, 0, 0};
  TerrainMemory most{"OutlineTerrain, streamed (largest)", 0, 0, 0, 0, 0, 0};
  int chunks = 0, triangles = 0;
  double own_bytes = 0;
};

// The everyday body `shape` alone on a kilometre (`rings`), the camera following it: its glide,
// and its world's counts into `tally`.
TerrainGlide slide_alone(bool undulating, const std::vector<std::vector<b2Vec2>>& rings,
                         const char* name, const b2Shape* shape, int steps, StreamTally& tally) {
  worlds::World world;
  box2d::OutlineTerrain terrain(world.get());
  throw_if_refused(terrain.set_outline(rings), "the kilometre was");
  tally.chunks = terrain.chunk_count();
  tally.triangles = terrain.triangle_count();
  tally.own_bytes = static_cast<double>(terrain.bytes());
  const double all = static_cast<double>(tally.triangles);
  tally.all = {
      tally.all.ground, double(tally.chunks), all, all, box2d_terrain_bytes(tally.chunks, all),
      tally.own_bytes,  double(tally.chunks)};
  b2Body* body = add_on_top(world, shape, kStreamStart, start_height(undulating), 0, 0);
  body->SetLinearVelocity(b2Vec2(kGlideSpeed, 0));
  const int body_fixtures = fixture_count(body);
  throw_if_refused(terrain.load(camera_region(body->GetPosition())), "a region was");
  int terrain_fixtures = static_cast<int>(terrain.fixtures().size());
  TerrainGlide glide{undulating ? "undulating" : "flat", name, 0, 0};
  for (int step = 0; step < steps; ++step) {
    // Gravity's pull along the top cancelled: a free glide keeps its speed up and down.
    float s = stream_slope(undulating, body->GetPosition().x);
    const b2Vec2 along = (1 / std::sqrt(1 + s * s)) * b2Vec2(1, s);
    body->ApplyForceToCenter(body->GetMass() * kGravity * along.y * along, true);
    world.step();
    box2d::TerrainResult r;
    tally.loads.push_back(
        timed([&] { r = terrain.load(camera_region(body->GetPosition())); }).first);
    throw_if_refused(r, "a region was");
    terrain_fixtures += r.created - r.destroyed;
    if (step > 0) {
      s = stream_slope(undulating, body->GetPosition().x);
      const b2Vec2 normal = (1 / std::sqrt(1 + s * s)) * b2Vec2(-s, 1);
      glide.max_off_ground_speed = std::max(
          glide.max_off_ground_speed, std::abs(double{b2Dot(body->GetLinearVelocity(), normal)}));
    }
    const int loaded = terrain.loaded_chunks();
    const int bodies = world->GetBodyCount();
    const int fixtures = terrain_fixtures + body_fixtures;
    const int proxies = world->GetProxyCount();
    tally.loaded_max = std::max(tally.loaded_max, loaded);
    tally.bodies_max = std::max(tally.bodies_max, bodies);
    tally.fixtures_max = std::max(tally.fixtures_max, fixtures);
    tally.proxies_max = std::max(tally.proxies_max, proxies);
    ++tally.samples;
    tally.loaded += loaded;
    tally.bodies += bodies;
    tally.fixtures += fixtures;
    tally.proxies += proxies;
    tally.terrain_fixtures += terrain_fixtures;
    const double bytes = box2d_terrain_bytes(loaded, terrain_fixtures);
    if (bytes > tally.most.box2d_bytes) {
      tally.most = {tally.most.ground,
                    double(loaded),
                    double(terrain_fixtures),
                    double(terrain_fixtures),
                    bytes,
                    tally.own_bytes,
                    double(loaded)};
    }
  }
  const double distance = kGlideSpeed * static_cast<double>(steps) * worlds::time_step;
  glide.travel = (body->GetPosition().x - kStreamStart) / distance;
  return glide;
}

}  // namespace

bool terrain_available() { return true; }

TerrainCraters run_terrain_craters(const TerrainTiming& timing, const box2d::Config& config,
                                   std::uint64_t seed) {
  const scenes::Installation installed(scenes::Runner{box2d::Backend::Dyop}, config);
  TerrainCraters out;
  out.steps = timing.crater_steps;
  out.runs = timing.crater_runs;
  for (int run = 0; run < timing.crater_runs; ++run) crater_run(run, timing, seed, out);
  return out;
}

LockstepRecording record_terrain_craters(const std::array<scenes::Runner, 2>& runners, int steps,
                                         const std::array<box2d::Config, 2>& configs,
                                         std::uint64_t seed) {
  TerrainTiming timing;
  timing.crater_steps = steps;
  return record_edited(terrain_recording_name, runners, steps, configs, [&](int) {
    auto scene = std::make_shared<CraterScene>(timing, seed);
    EditedWorld w;
    w.owner = scene;
    w.world = &scene->world;
    w.bodies = scene->terrain.bodies();
    w.bodies.insert(w.bodies.end(), scene->crowd.begin(), scene->crowd.end());
    CraterScene* s = scene.get();
    w.before_step = [s](int step) {
      s->push();
      const PlannedCrater* crater = s->crater_at(step);
      if (!crater) return false;
      throw_if_refused(s->terrain.remove(s->centre_of(*crater), crater->radius), "a crater was");
      return true;
    };
    return w;
  });
}

TerrainStream run_terrain_stream(const TerrainTiming& timing, const box2d::Config& config) {
  const scenes::Installation installed(scenes::Runner{box2d::Backend::Dyop}, config);
  TerrainStream out;
  out.length = kSegment * kSegments;
  out.steps = timing.stream_steps;
  out.distance = kGlideSpeed * static_cast<double>(out.steps) * worlds::time_step;
  const EverydayShapes shapes;
  StreamTally flat, tally;  // the undulating level's counts are the ones reported
  for (const bool undulating : {false, true}) {
    const std::vector<std::vector<b2Vec2>> rings = stream_rings(undulating);
    for (const auto& [name, shape] : shapes.all()) {
      out.glides.push_back(
          slide_alone(undulating, rings, name, shape, out.steps, undulating ? tally : flat));
    }
    if (!undulating) continue;
    out.boundary = boundary_length(rings);
    other_grounds(rings, out);
  }
  out.chunks = tally.chunks;
  out.triangles = tally.triangles;
  out.loaded_max = tally.loaded_max;
  out.bodies_max = tally.bodies_max;
  out.fixtures_max = tally.fixtures_max;
  out.proxies_max = tally.proxies_max;
  const double samples = std::max<double>(1, static_cast<double>(tally.samples));
  out.loaded_mean = tally.loaded / samples;
  out.bodies_mean = tally.bodies / samples;
  out.fixtures_mean = tally.fixtures / samples;
  out.proxies_mean = tally.proxies / samples;
  out.load_calls = static_cast<std::int64_t>(tally.loads.size());
  out.load_ms_median = scenes::median(tally.loads);
  out.load_ms_max = *std::max_element(tally.loads.begin(), tally.loads.end());
  const double mean_fixtures = tally.terrain_fixtures / samples;
  out.memory.push_back(tally.all);
  out.memory.push_back({"OutlineTerrain, streamed (mean)", out.loaded_mean, mean_fixtures,
                        mean_fixtures, box2d_terrain_bytes(out.loaded_mean, mean_fixtures),
                        tally.own_bytes, out.loaded_mean});
  out.memory.push_back(tally.most);
  return out;
}

#else  // built without GEOS: no terrain

bool terrain_available() { return false; }

namespace {
[[noreturn]] void no_terrain() {
  throw std::runtime_error("terrain: built without dyop::box2d_outlines (GEOS)");
}
}  // namespace

TerrainCraters run_terrain_craters(const TerrainTiming&, const box2d::Config&, std::uint64_t) {
  no_terrain();
}

LockstepRecording record_terrain_craters(const std::array<scenes::Runner, 2>&, int,
                                         const std::array<box2d::Config, 2>&, std::uint64_t) {
  no_terrain();
}

TerrainStream run_terrain_stream(const TerrainTiming&, const box2d::Config&) { no_terrain(); }

#endif

}  // namespace dyop::experiments
