// Many worlds: a world's answer depends on nothing but that world. Final-state hashes pinned per
// scene and runner (in the style of Box2D v3's determinism test), the same worlds on 1 to 8
// threads at once and in a pool of workers, episodes of a reset loop (each world deleted without
// destroying its bodies, the next built at the addresses it freed) against the same episode run
// alone, resident memory over 10,000 episodes, and the counters summed over threads. Run under
// ThreadSanitizer in CI (scripts/tsan.sh).
//
// The pinned hashes are for x86-64 with glibc (Box2D 2.4.1 from Debian turns bodies with
// sinf/cosf): on another platform, or after a change that is meant to change the worlds, print
// new ones with `DYOP_PRINT_HASHES=1 build/bin/many_worlds_test --gtest_filter='*Pinned*'`.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <unistd.h>
#include <vector>

#include "dyop/box2d.hpp"
#include "scenes/scene.hpp"
#include "scenes/scene_world.hpp"
#include "scenes/world.hpp"

namespace dyop::box2d {
namespace {

using scenes::Runner;

// 1.5 s of each scene: the pyramid settles, the rain lands, the slide's bodies cross junctions.
constexpr int kSteps = 90;
constexpr std::uint64_t kSeed = 0;

// Scenes whose worlds differ in kind: a resting structure, concave bodies of many triangles, a
// crowd landing in a triangulated bin, sliders over internal edges.
constexpr std::array<const char*, 4> kScenes = {"pyramid", "stack-concave", "rain", "slide"};

// Box2D's own contact (nothing installed), then every backend in registry order.
std::vector<Runner> all_runners() {
  std::vector<Runner> runners = {std::nullopt};
  for (const Backend b : all_backends) runners.emplace_back(b);
  return runners;
}

struct Pinned {
  const char* scene;
  const char* runner;
  std::uint64_t hash;
};

// Final state after kSteps from kSeed, with the plug-in installed with the default Config
// (recycling on: `Config::recycle_distance`; `box2d` equals Box2D's own, `sat` equals `dyop`:
// both pairs are bit-identical by design).
constexpr Pinned kPinned[] = {
    {"pyramid", "box2d-own", 0x34e1c5357f7bf0a3ull},
    {"stack-concave", "box2d-own", 0x8e0497e295cce22bull},
    {"rain", "box2d-own", 0xdc370bde4e27e896ull},
    {"slide", "box2d-own", 0x689616c76edd9520ull},
    {"pyramid", "dyop", 0x3245848e0ce34c79ull},
    {"stack-concave", "dyop", 0x7bf5752a4027f260ull},
    {"rain", "dyop", 0xf743365352488b64ull},
    {"slide", "dyop", 0xaec100bac04c5a22ull},
    {"pyramid", "dyop-fast", 0x2c15c4fe8423d128ull},
    {"stack-concave", "dyop-fast", 0x0825367dab77ebb5ull},
    {"rain", "dyop-fast", 0x63a996cd6c8c6551ull},
    {"slide", "dyop-fast", 0x87e0a517c358b254ull},
    {"pyramid", "lin-canny", 0x6f630c27d4d572efull},
    {"stack-concave", "lin-canny", 0xc1f16aa41b0ea187ull},
    {"rain", "lin-canny", 0x0e92c9cbd96bd5c7ull},
    {"slide", "lin-canny", 0x612c449bd2429892ull},
    {"pyramid", "sat", 0x3245848e0ce34c79ull},
    {"stack-concave", "sat", 0x7bf5752a4027f260ull},
    {"rain", "sat", 0xf743365352488b64ull},
    {"slide", "sat", 0xaec100bac04c5a22ull},
    {"pyramid", "epa", 0xb9808758ef5030b8ull},
    {"stack-concave", "epa", 0x9009435c217ffd13ull},
    {"rain", "epa", 0x26677e751a2a4a58ull},
    {"slide", "epa", 0xff97f6e5bacdd500ull},
    {"pyramid", "box2d", 0x34e1c5357f7bf0a3ull},
    {"stack-concave", "box2d", 0x8e0497e295cce22bull},
    {"rain", "box2d", 0xdc370bde4e27e896ull},
    {"slide", "box2d", 0x689616c76edd9520ull},
};

std::uint64_t pinned(const char* scene, const Runner& runner) {
  for (const Pinned& p : kPinned) {
    if (std::string(p.scene) == scene && std::string(p.runner) == scenes::name(runner)) {
      return p.hash;
    }
  }
  ADD_FAILURE() << "no pinned hash for " << scene << " under " << scenes::name(runner);
  return 0;
}

// Installs `runner` for the lifetime of the object (or leaves Box2D's own contact), before any
// thread starts and after every thread joined: the one rule of the plug-in's threading.
class Installed {
 public:
  explicit Installed(const Runner& runner) {
    EXPECT_TRUE((runner ? install(*runner) : uninstall()).ok());
  }
  ~Installed() { uninstall(); }
  Installed(const Installed&) = delete;
  Installed& operator=(const Installed&) = delete;
};

std::string hex(std::uint64_t h) {
  char text[19];
  std::snprintf(text, sizeof text, "0x%016llx", static_cast<unsigned long long>(h));
  return text;
}

TEST(ManyWorlds, EachSceneAloneEndsAtItsPinnedHash) {
  const bool print = std::getenv("DYOP_PRINT_HASHES") != nullptr;
  for (const Runner& runner : all_runners()) {
    const Installed installed(runner);
    for (const char* scene : kScenes) {
      const std::uint64_t h = scenes::run_scene_world(scene, kSeed, kSteps);
      if (print) {
        std::printf("    {\"%s\", \"%s\", %sull},\n", scene, scenes::name(runner), hex(h).c_str());
      } else {
        EXPECT_EQ(hex(h), hex(pinned(scene, runner))) << scene << " under " << scenes::name(runner);
      }
    }
  }
}

// The scene a thread or a world of a pool runs: every scene of kScenes, round robin.
const char* scene_of(int i) { return kScenes[static_cast<std::size_t>(i) % kScenes.size()]; }

TEST(ManyWorlds, WorldsOnOneToEightThreadsEndAtThePinnedHashes) {
  for (const Runner& runner : all_runners()) {
    const Installed installed(runner);
    for (const int n : {1, 2, 4, 8}) {
      std::vector<std::uint64_t> hashes(static_cast<std::size_t>(n));
      std::vector<std::thread> threads;
      for (int i = 0; i < n; ++i) {
        threads.emplace_back([i, &hashes] {
          hashes[static_cast<std::size_t>(i)] = scenes::run_scene_world(scene_of(i), kSeed, kSteps);
        });
      }
      for (std::thread& t : threads) t.join();
      for (int i = 0; i < n; ++i) {
        EXPECT_EQ(hex(hashes[static_cast<std::size_t>(i)]), hex(pinned(scene_of(i), runner)))
            << n << " threads, world " << i << " (" << scene_of(i) << ") under "
            << scenes::name(runner);
      }
    }
  }
}

// An environment pool: 8 worlds, 3 workers, each step of each world taken by whichever worker is
// free (the mutex hands a world from one thread to the next, as a pool's queue does).
TEST(ManyWorlds, WorldsSteppedByWhicheverWorkerIsFreeEndAtThePinnedHashes) {
  constexpr int kWorlds = 8;
  constexpr int kWorkers = 3;
  for (const Backend backend : {Backend::Dyop, Backend::Sat}) {
    const Installed installed(backend);
    std::vector<std::unique_ptr<scenes::SceneWorld>> worlds;
    for (int i = 0; i < kWorlds; ++i) {
      worlds.push_back(std::make_unique<scenes::SceneWorld>(scene_of(i), kSeed));
    }
    std::mutex queue_lock;
    std::vector<int> queue;  // worlds waiting for their next step, one entry per step left
    for (int s = 0; s < kSteps; ++s) {
      for (int i = 0; i < kWorlds; ++i) queue.push_back(i);
    }
    std::vector<bool> busy(kWorlds, false);
    auto work = [&] {
      for (;;) {
        int world = -1;
        {
          const std::lock_guard<std::mutex> hold(queue_lock);
          if (queue.empty()) return;
          for (std::size_t k = 0; k < queue.size(); ++k) {  // the first world not being stepped
            if (!busy[static_cast<std::size_t>(queue[k])]) {
              world = queue[k];
              queue.erase(queue.begin() + static_cast<std::ptrdiff_t>(k));
              busy[static_cast<std::size_t>(world)] = true;
              break;
            }
          }
        }
        if (world < 0) {
          std::this_thread::yield();
          continue;
        }
        worlds[static_cast<std::size_t>(world)]->step();
        const std::lock_guard<std::mutex> hold(queue_lock);
        busy[static_cast<std::size_t>(world)] = false;
      }
    };
    std::vector<std::thread> workers;
    for (int w = 0; w < kWorkers; ++w) workers.emplace_back(work);
    for (std::thread& t : workers) t.join();
    for (int i = 0; i < kWorlds; ++i) {
      EXPECT_EQ(hex(worlds[static_cast<std::size_t>(i)]->hash()), hex(pinned(scene_of(i), backend)))
          << "world " << i << " (" << scene_of(i) << ") under " << name(backend);
    }
  }
}

// --- Reset loop -----------------------------------------------------------------------------

constexpr int kEpisodeCells = 24;   // ground cells of 1 m, two triangles each
constexpr int kEpisodeBoxes = 40;   // split boxes dropped on the ground
constexpr int kEpisodeSteps = 240;  // 4 s: they land and settle
constexpr int kEpisodes = 12;

// The ground's top height at cell corner i in episode `terrain`: flat stretches and slopes that
// differ between terrains (so their flat and closed vertices differ), always 48 triangles.
float corner_height(int terrain, int i) {
  if (terrain < 0) return 0.0f;  // the same flat terrain every episode
  return 0.25f * static_cast<float>((terrain * 7 + i * 3 + (i / 4) * terrain) % 4);
}

// One episode's world, as a reset loop builds it: `new`, a static ground of one body (the cells,
// then an end cap, the same in every episode, created last), the boxes. Returns the bodies in
// creation order for hashing.
b2World* build_episode(int terrain, std::vector<b2Body*>& bodies) {
  auto* world = new b2World(b2Vec2(0.0f, -10.0f));
  world->SetAllowSleeping(false);
  b2BodyDef ground_def;
  b2Body* ground = world->CreateBody(&ground_def);
  bodies.push_back(ground);
  const float x0 = -0.5f * kEpisodeCells;
  for (int i = 0; i < kEpisodeCells; ++i) {
    const float xa = x0 + static_cast<float>(i);
    const float xb = xa + 1.0f;
    const float ya = corner_height(terrain, i);
    const float yb = corner_height(terrain, i + 1);
    scenes::add_triangle(ground, {xa, -1.0f}, {xb, -1.0f}, {xb, yb});
    scenes::add_triangle(ground, {xa, -1.0f}, {xb, yb}, {xa, ya});
  }
  const float end = -x0;
  scenes::add_triangle(ground, {end, -1.0f}, {end + 1.0f, -1.0f}, {end, 2.0f});  // the end cap
  for (int k = 0; k < kEpisodeBoxes; ++k) {
    b2BodyDef def;
    def.type = b2_dynamicBody;
    def.position.Set(x0 + 1.0f + static_cast<float>(k % 10) * 2.2f,
                     2.0f + static_cast<float>(k / 10) * 1.2f);
    def.angle = 0.1f * static_cast<float>(k % 5);
    b2Body* box = world->CreateBody(&def);
    scenes::add_triangle(box, {-0.4f, -0.4f}, {0.4f, -0.4f}, {0.4f, 0.4f});
    scenes::add_triangle(box, {-0.4f, -0.4f}, {0.4f, 0.4f}, {-0.4f, 0.4f});
    bodies.push_back(box);
  }
  return world;
}

// Runs one episode and deletes its world without destroying its bodies (Box2D frees everything,
// and no contact is destroyed).
std::uint64_t run_episode(int terrain) {
  std::vector<b2Body*> bodies;
  b2World* world = build_episode(terrain, bodies);
  for (int s = 0; s < kEpisodeSteps; ++s) world->Step(scenes::time_step, 8, 3);
  const std::uint64_t h = scenes::state_hash(bodies);
  delete world;
  return h;
}

// Each episode of a loop ends as the same episode run alone on a freshly installed plug-in.
void expect_episodes_as_alone(Backend backend, const Config& config, bool same_terrain) {
  const auto terrain = [&](int e) { return same_terrain ? -1 : e; };
  ASSERT_TRUE(install(backend, config).ok());
  std::vector<std::uint64_t> looped;
  for (int e = 0; e < kEpisodes; ++e) looped.push_back(run_episode(terrain(e)));
  int differing = 0;
  for (int e = 0; e < kEpisodes; ++e) {
    uninstall();
    ASSERT_TRUE(install(backend, config).ok());
    const std::uint64_t alone = run_episode(terrain(e));
    differing += alone != looped[static_cast<std::size_t>(e)];
    EXPECT_EQ(hex(looped[static_cast<std::size_t>(e)]), hex(alone))
        << "episode " << e << " under " << name(backend);
  }
  std::printf("%s: %d of %d episodes differ from the same episode alone\n", name(backend),
              differing, kEpisodes);
  uninstall();
}

// The other backends keep no masks, but a world's answer must not depend on the worlds before it
// under any of them either.
TEST(ManyWorlds, ResetLoopEpisodesUnderEveryBackendEndAsTheSameEpisodeAlone) {
  for (const Backend b : all_backends) {
    if (b != Backend::Dyop) expect_episodes_as_alone(b, Config{}, false);
  }
}

TEST(ManyWorlds, ResetLoopEpisodesOnOtherTerrainsEndAsTheSameEpisodeAlone) {
  expect_episodes_as_alone(Backend::Dyop, Config{}, false);
}

TEST(ManyWorlds, ResetLoopEpisodesOnTheSameTerrainEndAsTheSameEpisodeAlone) {
  expect_episodes_as_alone(Backend::Dyop, Config{}, true);
}

TEST(ManyWorlds, ResetLoopWithoutTheInternalEdgeRuleEndsAsAlone) {
  Config off;
  off.internal_edges = false;
  expect_episodes_as_alone(Backend::Dyop, off, false);
}

// Resident memory (bytes), from /proc/self/statm.
long resident_bytes() {
  std::ifstream statm("/proc/self/statm");
  long pages = 0;
  long resident = 0;
  statm >> pages >> resident;
  return resident * sysconf(_SC_PAGESIZE);
}

// A small episode: a ground of 8 triangles, 4 split boxes, 10 steps, deleted without destroying
// its bodies.
void small_episode(int e) {
  auto* world = new b2World(b2Vec2(0.0f, -10.0f));
  b2BodyDef ground_def;
  b2Body* ground = world->CreateBody(&ground_def);
  for (int i = 0; i < 4; ++i) {
    const float x = static_cast<float>(i) - 2.0f;
    scenes::add_triangle(ground, {x, -1.0f}, {x + 1.0f, -1.0f}, {x + 1.0f, 0.0f});
    scenes::add_triangle(ground, {x, -1.0f}, {x + 1.0f, 0.0f}, {x, 0.0f});
  }
  for (int k = 0; k < 4; ++k) {
    b2BodyDef def;
    def.type = b2_dynamicBody;
    def.position.Set(-1.5f + static_cast<float>(k), 0.45f + 0.01f * static_cast<float>(e % 7));
    b2Body* box = world->CreateBody(&def);
    scenes::add_triangle(box, {-0.4f, -0.4f}, {0.4f, -0.4f}, {0.4f, 0.4f});
    scenes::add_triangle(box, {-0.4f, -0.4f}, {0.4f, 0.4f}, {-0.4f, 0.4f});
  }
  for (int s = 0; s < 10; ++s) world->Step(scenes::time_step, 8, 3);
  delete world;
}

// Nothing is kept for a dead world: after a warm-up (the allocator's and the plug-in's per-thread
// buffers at their size), 10,000 more episodes leave the resident size where it was, within what
// the C library's allocator may keep for reuse. Excluded from the sanitizer runs, whose
// allocators hold freed memory back on purpose.
TEST(ManyWorlds, ResidentMemoryStaysFlatOverTenThousandEpisodes) {
  constexpr int kWarmUp = 200;
  constexpr int kEpisodesMore = 10000;
  // Why 2 MiB: one episode's world is about 100 KiB (Box2D's 100 KiB stack allocator and its
  // block chunks); anything kept per dead world would be at least tens of bytes × 10,000, and a
  // leak of one world's contacts alone would pass 2 MiB within a few hundred episodes.
  constexpr long kAllowedGrowth = 2 << 20;
  ASSERT_TRUE(install(Backend::Dyop).ok());
  for (int e = 0; e < kWarmUp; ++e) small_episode(e);
  const long before = resident_bytes();
  for (int e = 0; e < kEpisodesMore; ++e) small_episode(e);
  const long after = resident_bytes();
  std::printf("resident after %d episodes: %.2f MiB; after %d more: %.2f MiB\n", kWarmUp,
              before / 1048576.0, kEpisodesMore, after / 1048576.0);
  RecordProperty("resident_before_bytes", std::to_string(before));
  RecordProperty("resident_after_bytes", std::to_string(after));
  EXPECT_LE(after - before, kAllowedGrowth);
  uninstall();
}

// --- Counters -------------------------------------------------------------------------------

TEST(ManyWorlds, StatsSumTheCountsOfEveryThread) {
  const Installed installed(Backend::Dyop);
  std::vector<Stats> alone;
  for (int i = 0; i < 4; ++i) {
    reset_stats();
    scenes::run_scene_world(scene_of(i), kSeed, kSteps);
    alone.push_back(stats());
  }
  reset_stats();
  std::vector<std::thread> threads;
  for (int i = 0; i < 4; ++i) {
    threads.emplace_back([i] { scenes::run_scene_world(scene_of(i), kSeed, kSteps); });
  }
  for (std::thread& t : threads) t.join();  // the threads have ended: their counts stay
  const Stats together = stats();
  Stats sum;
  for (const Stats& s : alone) {
    sum.manifolds += s.manifolds;
    sum.internal_edge_pairs += s.internal_edge_pairs;
    sum.triangle_pairs[static_cast<int>(Backend::Dyop)] += s.triangles(Backend::Dyop);
  }
  EXPECT_GT(sum.triangles(Backend::Dyop), 0u);
  EXPECT_EQ(together.triangles(Backend::Dyop), sum.triangles(Backend::Dyop));
  EXPECT_EQ(together.manifolds, sum.manifolds);
  EXPECT_EQ(together.internal_edge_pairs, sum.internal_edge_pairs);
}

}  // namespace
}  // namespace dyop::box2d
