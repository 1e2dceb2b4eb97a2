// What the plug-in gives over a chain: one level built two ways from the same outline — Box2D's
// remedy for ghost collisions, a one-sided `b2ChainShape` loop under Box2D's own contact, and the
// outline triangulated by `dyop::box2d::add_outline` with its defaults under the plug-in — and the
// same bodies on each: everyday bodies pushed along the top,
// boxes started half inside the ground, boxes thrown at it fast, and a crowd dropped on it for the
// narrow phase and the step in wall time. Prints Markdown tables (docs/box2d-plugin.md, "Against a
// chain").
#include <box2d/box2d.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <vector>

#include <dyop/box2d.hpp>
#include <dyop/box2d_outline.hpp>

namespace {

constexpr float kLength = 60;      // metres of ground top
constexpr float kSpacing = 0.25f;  // a vertex every 25 cm along the top, as a tile editor samples
constexpr float kDt = 1.0f / 60;

enum class Ground { Chain, Triangles };
const char* name(Ground g) {
  return g == Ground::Chain ? "`b2ChainShape`, Box2D's own contact" : "`add_outline`, the plug-in";
}

// The ground's outline, counter-clockwise (a chain's solid side): the bottom, then the flat top
// from x = kLength back to 0.
std::vector<b2Vec2> outline() {
  std::vector<b2Vec2> ring = {{0, -10}, {kLength, -10}};
  const int n = static_cast<int>(kLength / kSpacing);
  for (int i = n; i >= 0; --i) ring.push_back({kSpacing * static_cast<float>(i), 0});
  return ring;
}

// A world with the ground built the `g` way, the plug-in installed for `Triangles` only.
struct Level {
  b2World world{b2Vec2(0, -10)};
  b2Body* ground = nullptr;
  int proxies = 0;        // broad-phase proxies of the ground (a chain has one per edge)
  std::size_t bytes = 0;  // the ground's memory, counted below

  explicit Level(Ground g) {
    if (g == Ground::Triangles) {
      dyop::box2d::install(dyop::box2d::Backend::Dyop);
    } else {
      dyop::box2d::uninstall();
    }
    b2BodyDef def;
    ground = world.CreateBody(&def);
    const std::vector<b2Vec2> ring = outline();
    // Per fixture: the fixture, its shape, and per child its proxy and its two tree nodes (a leaf
    // and, amortised, an inner node).
    const std::size_t per_proxy = sizeof(b2FixtureProxy) + 2 * sizeof(b2TreeNode);
    if (g == Ground::Chain) {
      b2ChainShape chain;
      chain.CreateLoop(ring.data(), static_cast<int>(ring.size()));
      ground->CreateFixture(&chain, 0);
      proxies = chain.GetChildCount();
      bytes = sizeof(b2Fixture) + sizeof(b2ChainShape) + ring.size() * sizeof(b2Vec2) +
              static_cast<std::size_t>(proxies) * per_proxy;
    } else {
      const dyop::box2d::OutlineResult r = dyop::box2d::add_outline(*ground, {ring});
      if (!r.ok()) std::fprintf(stderr, "outline: %s\n", r.message);
      proxies = static_cast<int>(r.mesh.fixtures.size());
      bytes = static_cast<std::size_t>(proxies) *
              (sizeof(b2Fixture) + sizeof(b2PolygonShape) + per_proxy);
    }
  }
};

// A dynamic body at `at` with one fixture of `shape` (frictionless), or, for nullptr, a box of
// two triangle fixtures of half-size 0.3 m.
b2Body* add_body(b2World& world, const b2Shape* shape, const b2Vec2& at, float friction = 0) {
  b2BodyDef def;
  def.type = b2_dynamicBody;
  def.position = at;
  b2Body* body = world.CreateBody(&def);
  b2FixtureDef fixture;
  fixture.density = 1;
  fixture.friction = friction;
  if (shape) {
    fixture.shape = shape;
    body->CreateFixture(&fixture);
    return body;
  }
  const b2Vec2 corners[4] = {{-0.3f, -0.3f}, {0.3f, -0.3f}, {0.3f, 0.3f}, {-0.3f, 0.3f}};
  const int halves[2][3] = {{0, 1, 2}, {0, 2, 3}};
  for (const auto& t : halves) {
    b2PolygonShape triangle;
    const b2Vec2 v[3] = {corners[t[0]], corners[t[1]], corners[t[2]]};
    triangle.Set(v, 3);
    fixture.shape = &triangle;
    body->CreateFixture(&fixture);
  }
  return body;
}

struct Shapes {
  b2PolygonShape box;
  b2PolygonShape hexagon;
  b2CircleShape ball;
  Shapes() {
    box.SetAsBox(0.25f, 0.3f);
    b2Vec2 v[6];
    for (int i = 0; i < 6; ++i) {
      const float a = static_cast<float>(i) * b2_pi / 3;
      v[i] = {0.3f * std::cos(a), 0.3f * std::sin(a)};
    }
    hexagon.Set(v, 6);
    ball.m_radius = 0.3f;
  }
  // Everyday bodies and their names; nullptr: a box of two triangles.
  std::vector<std::pair<const char*, const b2Shape*>> all() const {
    return {{"`SetAsBox` box", &box},
            {"hexagon", &hexagon},
            {"ball", &ball},
            {"box of 2 triangles", nullptr}};
  }
};

// The height at which `shape`'s lowest point rests on y = 0 (nullptr: the box of triangles).
float resting_height(const b2Shape* shape) {
  if (!shape) return 0.3f;
  b2AABB box;
  shape->ComputeAABB(&box, b2Transform(b2Vec2(0, 0), b2Rot(0)), 0);
  return -box.lowerBound.y;
}

void glide_table(const Shapes& shapes) {
  std::printf("\n| body, pushed at 4 m/s for 4 s | %s | %s |\n|---|---|---|\n", name(Ground::Chain),
              name(Ground::Triangles));
  for (const auto& [label, shape] : shapes.all()) {
    std::printf("| %s |", label);
    for (const Ground g : {Ground::Chain, Ground::Triangles}) {
      Level level(g);
      b2Body* body = add_body(level.world, shape, {2, resting_height(shape) + 0.005f});
      body->SetLinearVelocity({4, 0});
      float vertical = 0;
      for (int i = 0; i < 240; ++i) {
        level.world.Step(kDt, 8, 3);
        if (i > 0) vertical = std::max(vertical, std::abs(body->GetLinearVelocity().y));
      }
      std::printf(" %.3f m/s, %.1f %% of the glide |", vertical,
                  100 * (body->GetPosition().x - 2) / 16);
    }
    std::printf("\n");
  }
}

// How many of `bodies` ended on the ground's right side (centre above the top) after `steps`.
int above(const std::vector<b2Body*>& bodies) {
  return static_cast<int>(std::count_if(bodies.begin(), bodies.end(),
                                        [](const b2Body* b) { return b->GetPosition().y > 0; }));
}

void placement_table(const Shapes& shapes) {
  std::printf("\n| boxes (`SetAsBox` 0.25 × 0.3 m) | %s | %s |\n|---|---|---|\n",
              name(Ground::Chain), name(Ground::Triangles));
  struct Trial {
    const char* label;
    float y;      // centre's start height (0.3: resting)
    float speed;  // downward (m/s)
  };
  const Trial trials[] = {{"started 0.1 m inside (centre 0.2 m above the top)", 0.2f, 0},
                          {"started 0.25 m inside", 0.05f, 0},
                          {"started 0.4 m inside (centre under the top)", -0.1f, 0},
                          {"thrown down at 30 m/s from 5 m", 5, 30},
                          {"thrown down at 100 m/s from 5 m", 5, 100},
                          {"thrown down at 300 m/s from 5 m", 5, 300}};
  for (const Trial& t : trials) {
    std::printf("| %s |", t.label);
    for (const Ground g : {Ground::Chain, Ground::Triangles}) {
      Level level(g);
      std::vector<b2Body*> bodies;
      for (int k = 0; k < 20; ++k) {
        b2Body* b =
            add_body(level.world, &shapes.box, {2.5f + 2.7f * static_cast<float>(k), t.y}, 0.6f);
        b->SetLinearVelocity({0, -t.speed});
        bodies.push_back(b);
      }
      for (int i = 0; i < 180; ++i) level.world.Step(kDt, 8, 3);
      std::printf(" %d of 20 on top |", above(bodies));
    }
    std::printf("\n");
  }
}

// Median of `runs` alternating runs of a crowd dropped on each ground: narrow phase
// (`b2Profile::collide`) and step, milliseconds summed over the run.
void timing_table(const Shapes& shapes) {
  const int runs = 5;
  std::vector<double> collide[2], step[2];
  for (int run = 0; run < runs; ++run) {
    for (const Ground g : {Ground::Chain, Ground::Triangles}) {
      Level level(g);
      const auto all = shapes.all();
      for (int k = 0; k < 240; ++k) {
        const b2Shape* shape = all[static_cast<std::size_t>(k) % all.size()].second;
        add_body(level.world, shape,
                 {1 + 0.85f * static_cast<float>(k % 68), 1 + 0.9f * static_cast<float>(k / 68)},
                 0.6f);
      }
      double c = 0, s = 0;
      for (int i = 0; i < 360; ++i) {
        level.world.Step(kDt, 8, 3);
        c += level.world.GetProfile().collide;
        s += level.world.GetProfile().step;
      }
      collide[static_cast<int>(g)].push_back(c);
      step[static_cast<int>(g)].push_back(s);
    }
  }
  const auto median = [](std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
  };
  std::printf(
      "\n| 240 bodies dropped, 360 steps, median of %d alternating runs | %s | %s | ratio |\n"
      "|---|--:|--:|--:|\n",
      runs, name(Ground::Chain), name(Ground::Triangles));
  const double c0 = median(collide[0]), c1 = median(collide[1]);
  const double s0 = median(step[0]), s1 = median(step[1]);
  std::printf("| narrow phase (ms) | %.1f | %.1f | %.2f× |\n", c0, c1, c1 / c0);
  std::printf("| step (ms) | %.1f | %.1f | %.2f× |\n", s0, s1, s1 / s0);
}

void size_table() {
  std::printf("\n| the ground, %.0f m of top | %s | %s |\n|---|--:|--:|\n", kLength,
              name(Ground::Chain), name(Ground::Triangles));
  const Level chain(Ground::Chain);
  const Level triangles(Ground::Triangles);
  std::printf("| broad-phase proxies per metre | %.1f | %.1f |\n", chain.proxies / kLength,
              triangles.proxies / kLength);
  std::printf("| bytes per metre (fixtures, shapes, proxies, tree nodes) | %.0f | %.0f |\n",
              static_cast<double>(chain.bytes) / kLength,
              static_cast<double>(triangles.bytes) / kLength);
}

}  // namespace

int main() {
  const Shapes shapes;
  std::printf("A %.0f m flat ground, a vertex every %.2f m, frictionless bodies unless said.\n",
              kLength, kSpacing);
  glide_table(shapes);
  placement_table(shapes);
  size_table();
  timing_table(shapes);
  dyop::box2d::uninstall();
  return 0;
}
