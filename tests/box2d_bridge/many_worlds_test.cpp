// Many worlds: a world's answer depends on nothing but that world. Final-state hashes pinned per
// world and contact (in the style of Box2D v3's determinism test), the same worlds on 1 to 8
// threads at once and in a pool of workers, episodes of a reset loop (each world deleted without
// destroying its bodies, the next built at the addresses it freed) against the same episode run
// alone, resident memory over 10,000 episodes, and the counters summed over threads. Run under
// ThreadSanitizer in CI (scripts/tsan.sh).
//
// The pinned hashes are for x86-64 with glibc (Box2D 2.4.1 from Debian turns bodies with
// sinf/cosf): on another platform, or after a change that is meant to change the worlds, print
// new ones with
// `DYOP_PRINT_HASHES=1 build/bin/box2d_bridge_tests --gtest_filter='ManyWorlds.*Pinned*'`.
// They depend on the Box2D release: the same under 2.4.1 and 2.4.2 (built from its tag, with
// asserts or without), whose worlds differ only where b2PolygonShape::Set does, and
// `make_triangle` builds 2.4.1's shapes under both; the hexagons of `everyday`, built with
// Box2D's own Set, come out in the same order from both hulls. A release that gives other
// worlds gets a table of its own (`box2d_release`, dyop/box2d_release.hpp).
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <mutex>
#include <cmath>
#include <string>
#include <thread>
#include <unistd.h>
#include <vector>

#include "dyop/box2d.hpp"
#include "dyop/box2d_release.hpp"
#include "support/per_contact.hpp"
#include "support/worlds.hpp"

namespace dyop::box2d::testing {
namespace {

// 1.5 s of each world: the tower settles, the crowd lands, the sliders cross cell junctions.
constexpr int kSteps = 90;

// Worlds that differ in kind: a resting structure, concave bodies of many triangles, a crowd
// landing in a triangulated bin, sliders over internal edges, and the everyday shapes (`SetAsBox`
// boxes, hexagons, circles) landing on a tile map of `SetAsBox` tiles, and on a level made the way
// Box2D tells users to: a chain loop beside strips of two-sided edges across static bodies.
enum class Kind { Tower, Concave, Crowd, Sliders, Everyday, Levels };
constexpr std::array<Kind, 6> kKinds = {Kind::Tower,   Kind::Concave,  Kind::Crowd,
                                        Kind::Sliders, Kind::Everyday, Kind::Levels};

const char* kind_name(Kind kind) {
  switch (kind) {
    case Kind::Tower:
      return "tower";
    case Kind::Concave:
      return "concave";
    case Kind::Crowd:
      return "crowd";
    case Kind::Sliders:
      return "sliders";
    case Kind::Everyday:
      return "everyday";
    case Kind::Levels:
      return "levels";
  }
  return "?";
}

// 60 boxes, hexagons and circles dropped along [-9, 9] and pushed along +x.
void add_everyday_bodies(World& world) {
  for (int i = 0; i < 60; ++i) {
    const float size = 0.15f + 0.05f * static_cast<float>(i % 3);
    b2Body* body =
        add_body(world, b2_dynamicBody,
                 b2Vec2(-9.0f + 0.9f * static_cast<float>(i % 20), 0.5f + 0.9f * (i / 20)),
                 0.37f * static_cast<float>(i));
    b2PolygonShape polygon;
    b2CircleShape circle;
    if (i % 3 == 0) polygon.SetAsBox(size, 0.7f * size);
    if (i % 3 == 1) {
      b2Vec2 v[6];
      for (int k = 0; k < 6; ++k) {
        v[k].Set(size * std::cos(1.0471976f * k), size * std::sin(1.0471976f * k));
      }
      polygon.Set(v, 6);
    }
    circle.m_radius = size;
    const b2Shape& shape = i % 3 == 2 ? static_cast<const b2Shape&>(circle) : polygon;
    body->CreateFixture(&shape, 1.0f);
    body->SetLinearVelocity(b2Vec2(1.0f + 0.1f * static_cast<float>(i % 7), 0.0f));
  }
}

std::unique_ptr<World> build_world(Kind kind) {
  auto world = std::make_unique<World>();
  switch (kind) {
    case Kind::Tower: {  // 4 columns of 8 split boxes of 1 m on a triangle ground
      add_triangle_ground(*world, 6.0f);
      const float pitch = 1.0f + b2_polygonRadius;
      for (int column = 0; column < 4; ++column) {
        for (int level = 0; level < 8; ++level) {
          add_split_box(
              *world, b2Vec2(-3.3f + 2.2f * column, 0.5f + b2_polygonRadius + pitch * level), 0.5f);
        }
      }
      break;
    }
    case Kind::Concave:  // 12 L, U and star bodies (4 to 10 triangles) dropped into a bin
      worlds::add_triangle_bin(*world, 6.0f, 10.0f);
      for (int i = 0; i < 12; ++i) {
        const b2Vec2 at(-4.5f + 3.0f * static_cast<float>(i % 4), 2.0f + 3.0f * (i / 4));
        const float angle = 0.7f * static_cast<float>(i);
        if (i % 3 == 0) worlds::add_l_shape(*world, at, angle);
        if (i % 3 == 1) worlds::add_u_shape(*world, at, angle);
        if (i % 3 == 2) worlds::add_star(*world, at, angle);
      }
      break;
    case Kind::Crowd:  // 120 single triangles of three sizes falling into a bin
      worlds::add_triangle_bin(*world, 5.0f, 8.0f);
      for (int i = 0; i < 120; ++i) {
        const float size = 0.2f + 0.15f * static_cast<float>(i % 3);
        b2Body* body =
            add_body(*world, b2_dynamicBody,
                     b2Vec2(-4.5f + 0.9f * static_cast<float>(i % 11), 1.5f + 0.9f * (i / 11)),
                     0.37f * static_cast<float>(i));
        add_triangle(body, b2Vec2(-size, -size), b2Vec2(size, -size), b2Vec2(0.0f, size));
      }
      break;
    case Kind::Sliders: {  // boxes and L bodies launched along a ground of 0.5 m triangle cells
      b2Body* ground = add_body(*world, b2_staticBody, b2Vec2(0.0f, 0.0f));
      worlds::add_triangle_block(ground, -10.0f, -1.0f, 30.0f, 0.0f, 0.5f);
      for (int k = 0; k < 6; ++k) {
        const b2Vec2 at(-8.0f + 2.5f * static_cast<float>(k), 0.6f + b2_polygonRadius);
        b2Body* body = k % 2 == 0 ? add_split_box(*world, at, 0.5f)
                                  : worlds::add_l_shape(*world, at - b2Vec2(0.0f, 0.5f), 0.0f);
        body->SetLinearVelocity(b2Vec2(3.0f + static_cast<float>(k), 0.0f));
      }
      break;
    }
    case Kind::Everyday: {  // 60 boxes, hexagons and circles on 0.5 m SetAsBox tiles, pushed
      b2Body* ground = add_body(*world, b2_staticBody, b2Vec2(0.0f, 0.0f));
      for (int i = 0; i < 40; ++i) {
        b2PolygonShape tile;
        tile.SetAsBox(0.25f, 0.25f, b2Vec2(-10.0f + 0.5f * static_cast<float>(i), -0.25f), 0.0f);
        ground->CreateFixture(&tile, 0.0f);
      }
      add_everyday_bodies(*world);
      break;
    }
    case Kind::Levels: {  // the same bodies on a chain loop and two strips of two-sided edges
      b2Body* chain_body = add_body(*world, b2_staticBody, b2Vec2(0.0f, 0.0f));
      const b2Vec2 block[] = {{-10, -1}, {-3, -1}, {-3, 0}, {-10, 0}};
      b2ChainShape loop;
      loop.CreateLoop(block, 4);
      chain_body->CreateFixture(&loop, 0.0f);
      for (int strip = 0; strip < 2; ++strip) {  // each on a static body of its own, end to end
        b2Body* edges = add_body(*world, b2_staticBody, b2Vec2(0.0f, 0.0f));
        for (int i = 0; i < 12; ++i) {
          const float x = -3.0f + 3.0f * static_cast<float>(strip) + 0.25f * static_cast<float>(i);
          b2EdgeShape e;
          e.SetTwoSided(b2Vec2(x, 0.0f), b2Vec2(x + 0.25f, 0.0f));
          edges->CreateFixture(&e, 0.0f);
        }
      }
      add_everyday_bodies(*world);
      break;
    }
  }
  return world;
}

// Builds `kind`'s world, steps it kSteps times and returns its final state hash.
std::uint64_t run_world(Kind kind) {
  const std::unique_ptr<World> world = build_world(kind);
  for (int s = 0; s < kSteps; ++s) world->step();
  return worlds::state_hash(*world);
}

struct Pinned {
  const char* world;
  const char* contact;
  std::uint64_t hash;
};

// Final state after kSteps, with the plug-in installed with the default Config (recycling on:
// `Config::recycle_distance`; `box2d` equals Box2D's own, `sat` equals `dyop`: both pairs are
// bit-identical by design).
constexpr Pinned kPinned[] = {
    {"tower", "box2d_own", 0x116509f75a54d450ull},
    {"concave", "box2d_own", 0x376ffe6557c4182full},
    {"crowd", "box2d_own", 0x911c6e8d2744e1d9ull},
    {"sliders", "box2d_own", 0xa2bf4c96b3d39b70ull},
    {"tower", "via_plugin_dyop", 0xb276095b891e2e85ull},
    {"concave", "via_plugin_dyop", 0xc1817e9d898d87e0ull},
    {"crowd", "via_plugin_dyop", 0x67eaaa3e5179d0edull},
    {"sliders", "via_plugin_dyop", 0x3e791cdf7fa2d237ull},
    {"tower", "via_plugin_dyop_fast", 0x0bacff12591f3457ull},
    {"concave", "via_plugin_dyop_fast", 0x5bef761421c82d9eull},
    {"crowd", "via_plugin_dyop_fast", 0x73bc7debfada6a43ull},
    {"sliders", "via_plugin_dyop_fast", 0x0c575594080cd99full},
    {"tower", "via_plugin_lin_canny", 0xf3c8adc5b315d092ull},
    {"concave", "via_plugin_lin_canny", 0x13896d152f1755b2ull},
    {"crowd", "via_plugin_lin_canny", 0xe0114387a41de5b6ull},
    {"sliders", "via_plugin_lin_canny", 0xc34b732e4b52ebb5ull},
    {"tower", "via_plugin_sat", 0xb276095b891e2e85ull},
    {"concave", "via_plugin_sat", 0xc1817e9d898d87e0ull},
    {"crowd", "via_plugin_sat", 0x67eaaa3e5179d0edull},
    {"sliders", "via_plugin_sat", 0x3e791cdf7fa2d237ull},
    {"tower", "via_plugin_epa", 0x1af6acda68c9cbddull},
    {"concave", "via_plugin_epa", 0x99ed38b3ee0bbb6eull},
    {"crowd", "via_plugin_epa", 0xbd5987e901a44340ull},
    {"sliders", "via_plugin_epa", 0x31809af75802ba85ull},
    {"tower", "via_plugin_box2d", 0x116509f75a54d450ull},
    {"concave", "via_plugin_box2d", 0x376ffe6557c4182full},
    {"crowd", "via_plugin_box2d", 0x911c6e8d2744e1d9ull},
    {"sliders", "via_plugin_box2d", 0xa2bf4c96b3d39b70ull},
    // No triangle in it: every backend but `box2d` answers its pairs with the exact solver. Moved
    // when the polygon pairs' reference face became the least overlap's, A's only within
    // rounding (Box2D's 0.1·linearSlop hysteresis left the depth the solver reads up to 0.5 mm too
    // deep: polygon_manifold_test).
    {"everyday", "box2d_own", 0xe23dd46f35c42a68ull},
    {"everyday", "via_plugin_dyop", 0x68fdd57b7c6a1e39ull},
    {"everyday", "via_plugin_dyop_fast", 0x68fdd57b7c6a1e39ull},
    {"everyday", "via_plugin_lin_canny", 0x68fdd57b7c6a1e39ull},
    {"everyday", "via_plugin_sat", 0x68fdd57b7c6a1e39ull},
    {"everyday", "via_plugin_epa", 0x68fdd57b7c6a1e39ull},
    {"everyday", "via_plugin_box2d", 0xe23dd46f35c42a68ull},
    // No triangle either; its chain and edge pairs are the exact solver's under every backend but
    // `box2d` (`Config::edges_and_chains`).
    {"levels", "box2d_own", 0xdb23f966650dc68full},
    {"levels", "via_plugin_dyop", 0x30c16b6efe2bdfb0ull},
    {"levels", "via_plugin_dyop_fast", 0x30c16b6efe2bdfb0ull},
    {"levels", "via_plugin_lin_canny", 0x30c16b6efe2bdfb0ull},
    {"levels", "via_plugin_sat", 0x30c16b6efe2bdfb0ull},
    {"levels", "via_plugin_epa", 0x30c16b6efe2bdfb0ull},
    {"levels", "via_plugin_box2d", 0xdb23f966650dc68full},
};

std::uint64_t pinned(Kind kind, const Contact& contact) {
  for (const Pinned& p : kPinned) {
    if (std::string(p.world) == kind_name(kind) && p.contact == contact_name(contact)) {
      return p.hash;
    }
  }
  ADD_FAILURE() << "no pinned hash for " << kind_name(kind) << " under " << contact_name(contact);
  return 0;
}

// Installs `contact` for the lifetime of the object (or leaves Box2D's own contact), before any
// thread starts and after every thread joined: the one rule of the plug-in's threading.
class Installed {
 public:
  explicit Installed(const Contact& contact) {
    EXPECT_TRUE((contact ? install(*contact) : uninstall()).ok());
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
  for (const Contact& contact : kAllContacts) {
    const Installed installed(contact);
    for (const Kind kind : kKinds) {
      const std::uint64_t h = run_world(kind);
      if (print) {
        std::printf("    {\"%s\", \"%s\", %sull},\n", kind_name(kind),
                    contact_name(contact).c_str(), hex(h).c_str());
      } else {
        EXPECT_EQ(hex(h), hex(pinned(kind, contact)))
            << kind_name(kind) << " under " << contact_name(contact) << ", Box2D "
            << name(box2d_release);
      }
    }
  }
}

// The world a thread or a member of a pool runs: every kind of kKinds, round robin.
Kind kind_of(int i) { return kKinds[static_cast<std::size_t>(i) % kKinds.size()]; }

TEST(ManyWorlds, WorldsOnOneToEightThreadsEndAtThePinnedHashes) {
  for (const Contact& contact : kAllContacts) {
    const Installed installed(contact);
    for (const int n : {1, 2, 4, 8}) {
      std::vector<std::uint64_t> hashes(static_cast<std::size_t>(n));
      std::vector<std::thread> threads;
      for (int i = 0; i < n; ++i) {
        threads.emplace_back(
            [i, &hashes] { hashes[static_cast<std::size_t>(i)] = run_world(kind_of(i)); });
      }
      for (std::thread& t : threads) t.join();
      for (int i = 0; i < n; ++i) {
        EXPECT_EQ(hex(hashes[static_cast<std::size_t>(i)]), hex(pinned(kind_of(i), contact)))
            << n << " threads, world " << i << " (" << kind_name(kind_of(i)) << ") under "
            << contact_name(contact) << ", Box2D " << name(box2d_release);
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
    std::vector<std::unique_ptr<World>> pool;
    for (int i = 0; i < kWorlds; ++i) pool.push_back(build_world(kind_of(i)));
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
        pool[static_cast<std::size_t>(world)]->step();
        const std::lock_guard<std::mutex> hold(queue_lock);
        busy[static_cast<std::size_t>(world)] = false;
      }
    };
    std::vector<std::thread> workers;
    for (int w = 0; w < kWorkers; ++w) workers.emplace_back(work);
    for (std::thread& t : workers) t.join();
    for (int i = 0; i < kWorlds; ++i) {
      EXPECT_EQ(hex(worlds::state_hash(*pool[static_cast<std::size_t>(i)])),
                hex(pinned(kind_of(i), backend)))
          << "world " << i << " (" << kind_name(kind_of(i)) << ") under " << name(backend)
          << ", Box2D " << name(box2d_release);
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
    add_triangle(ground, {xa, -1.0f}, {xb, -1.0f}, {xb, yb});
    add_triangle(ground, {xa, -1.0f}, {xb, yb}, {xa, ya});
  }
  const float end = -x0;
  add_triangle(ground, {end, -1.0f}, {end + 1.0f, -1.0f}, {end, 2.0f});  // the end cap
  for (int k = 0; k < kEpisodeBoxes; ++k) {
    b2BodyDef def;
    def.type = b2_dynamicBody;
    def.position.Set(x0 + 1.0f + static_cast<float>(k % 10) * 2.2f,
                     2.0f + static_cast<float>(k / 10) * 1.2f);
    def.angle = 0.1f * static_cast<float>(k % 5);
    b2Body* box = world->CreateBody(&def);
    add_triangle(box, {-0.4f, -0.4f}, {0.4f, -0.4f}, {0.4f, 0.4f});
    add_triangle(box, {-0.4f, -0.4f}, {0.4f, 0.4f}, {-0.4f, 0.4f});
    bodies.push_back(box);
  }
  return world;
}

// Runs one episode and deletes its world without destroying its bodies (Box2D frees everything,
// and no contact is destroyed).
std::uint64_t run_episode(int terrain) {
  std::vector<b2Body*> bodies;
  b2World* world = build_episode(terrain, bodies);
  for (int s = 0; s < kEpisodeSteps; ++s) world->Step(worlds::time_step, 8, 3);
  const std::uint64_t h = worlds::state_hash(bodies);
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
    add_triangle(ground, {x, -1.0f}, {x + 1.0f, -1.0f}, {x + 1.0f, 0.0f});
    add_triangle(ground, {x, -1.0f}, {x + 1.0f, 0.0f}, {x, 0.0f});
  }
  for (int k = 0; k < 4; ++k) {
    b2BodyDef def;
    def.type = b2_dynamicBody;
    def.position.Set(-1.5f + static_cast<float>(k), 0.45f + 0.01f * static_cast<float>(e % 7));
    b2Body* box = world->CreateBody(&def);
    add_triangle(box, {-0.4f, -0.4f}, {0.4f, -0.4f}, {0.4f, 0.4f});
    add_triangle(box, {-0.4f, -0.4f}, {0.4f, 0.4f}, {-0.4f, 0.4f});
  }
  for (int s = 0; s < 10; ++s) world->Step(worlds::time_step, 8, 3);
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
    run_world(kind_of(i));
    alone.push_back(stats());
  }
  reset_stats();
  std::vector<std::thread> threads;
  for (int i = 0; i < 4; ++i) {
    threads.emplace_back([i] { run_world(kind_of(i)); });
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
}  // namespace dyop::box2d::testing
