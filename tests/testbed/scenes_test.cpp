// Every headless scene under every backend, briefly: it builds what the issue asks for, runs
// without NaN, and every triangle pair is answered by the backend itself.
#include <box2d/box2d.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>
#include <string>
#include <tuple>
#include <vector>

#include "dyop/sat.hpp"
#include "scenes/contact_probe.hpp"
#include "scenes/scene.hpp"
#include "scenes/world_scene.hpp"

namespace dyop::scenes {
namespace {

constexpr int kMotionSteps = 30;  // half a second: everything is built and in motion

using Case = std::tuple<std::string, box2d::Backend>;

class EveryScene : public ::testing::TestWithParam<Case> {};

TEST_P(EveryScene, RunsWithoutNaNAndWithoutFallbacks) {
  const auto& [name, backend] = GetParam();
  const SceneMetrics m = run_scene(name, backend, kMotionSteps, 7);
  EXPECT_EQ(m.scene, name);
  EXPECT_EQ(m.runner, Runner{backend});
  EXPECT_EQ(m.steps, kMotionSteps);
  EXPECT_FALSE(m.nan_detected);
  EXPECT_TRUE(all_finite(m));
  EXPECT_GE(m.narrowphase_ns_per_pair, 0);
  EXPECT_GE(m.pd_error_max, m.pd_error_mean);
  EXPECT_LE(m.triangle_pairs, m.contact_updates);
  if (name == "paper") {
    EXPECT_FALSE(m.fallbacks.has_value());
    EXPECT_EQ(m.bodies, 10);
    EXPECT_GT(m.triangle_pairs, 0u);
  } else {
    ASSERT_TRUE(m.fallbacks.has_value());
    EXPECT_EQ(*m.fallbacks, 0u) << "pairs answered by Box2D instead of " << scenes::name(m.runner);
    ASSERT_TRUE(m.plugin_evaluations.has_value());
    EXPECT_LE(m.triangle_pairs, *m.plugin_evaluations);
  }
  EXPECT_FALSE(box2d::installed().has_value()) << "the scene left its backend installed";
}

std::string case_name(const ::testing::TestParamInfo<Case>& info) {
  std::string n = std::get<0>(info.param) + "_" + box2d::name(std::get<1>(info.param));
  for (char& c : n) c = c == '-' ? '_' : c;
  return n;
}

std::vector<Case> every_case() {
  std::vector<Case> cases;
  for (const SceneInfo& s : scene_catalog()) {
    for (box2d::Backend b : box2d::all_backends) cases.emplace_back(s.name, b);
  }
  return cases;
}

INSTANTIATE_TEST_SUITE_P(Catalogue, EveryScene, ::testing::ValuesIn(every_case()), case_name);

TEST(Catalogue, HasEveryScene) {
  for (const char* name :
       {"paper", "pyramid", "pyramid-rows", "stack", "stack-concave", "rain", "tumbler", "slivers",
        "slivers-far", "mixed", "slide", "tiles", "tile-map"}) {
    EXPECT_NE(find_scene(name), nullptr) << name;
  }
  EXPECT_EQ(find_scene("nope"), nullptr);
  EXPECT_THROW(make_scene("nope", box2d::Backend::Dyop, 0), std::invalid_argument);
  for (box2d::Backend b : box2d::all_backends) {
    EXPECT_EQ(box2d::parse_backend(box2d::name(b)), b);
  }
  EXPECT_FALSE(box2d::parse_backend("dyop-paper").has_value());
}

// The sizes the issue asks for, counted in the built worlds.
struct Census {
  int dynamic_bodies = 0;
  int dynamic_triangles = 0;
  int static_triangles = 0;
  int kinematic_triangles = 0;
  int other_fixtures = 0;  // circles, edges, boxes
};

Census census(const std::string& name) {
  const std::unique_ptr<Scene> scene = make_scene(name, box2d::Backend::Dyop, 0);
  const auto& world = dynamic_cast<const WorldScene&>(*scene).world();
  Census c;
  for (const b2Body* b : world.bodies()) {
    c.dynamic_bodies += b->GetType() == b2_dynamicBody;
    for (const b2Fixture* f = b->GetFixtureList(); f != nullptr; f = f->GetNext()) {
      if (!is_triangle(f)) {
        ++c.other_fixtures;
      } else if (b->GetType() == b2_dynamicBody) {
        ++c.dynamic_triangles;
      } else if (b->GetType() == b2_kinematicBody) {
        ++c.kinematic_triangles;
      } else {
        ++c.static_triangles;
      }
    }
  }
  return c;
}

TEST(Catalogue, ScenesHaveTheSizesAsked) {
  const Census pyramid = census("pyramid");
  EXPECT_GE(pyramid.dynamic_bodies, 55);
  EXPECT_EQ(pyramid.dynamic_triangles, 2 * pyramid.dynamic_bodies);  // boxes of two triangles
  EXPECT_GT(pyramid.static_triangles, 0);
  EXPECT_EQ(pyramid.other_fixtures, 0);  // every contact goes through the plug-in

  const Census rows = census("pyramid-rows");
  EXPECT_GE(rows.dynamic_bodies, 55);
  EXPECT_EQ(rows.dynamic_triangles, rows.dynamic_bodies);
  EXPECT_EQ(rows.other_fixtures, 0);

  const Census stack = census("stack");
  EXPECT_GE(stack.dynamic_bodies, 10);
  EXPECT_EQ(stack.dynamic_triangles, 2 * stack.dynamic_bodies);
  EXPECT_EQ(stack.other_fixtures, 0);

  const Census concave = census("stack-concave");
  EXPECT_GE(concave.dynamic_triangles, 4 * concave.dynamic_bodies);  // L 4, U 6, star 10
  EXPECT_EQ(concave.other_fixtures, 0);

  const Census rain = census("rain");
  EXPECT_GE(rain.dynamic_triangles, 500);
  EXPECT_GT(rain.static_triangles, 0);
  EXPECT_EQ(rain.other_fixtures, 0);

  const Census tumbler = census("tumbler");
  EXPECT_GE(tumbler.dynamic_triangles, 300);
  EXPECT_GT(tumbler.kinematic_triangles, 0);
  EXPECT_EQ(tumbler.other_fixtures, 0);

  const Census slivers = census("slivers");
  const Census far = census("slivers-far");
  EXPECT_EQ(slivers.dynamic_triangles, far.dynamic_triangles);
  EXPECT_EQ(slivers.other_fixtures, 0);

  const Census mixed = census("mixed");
  EXPECT_GT(mixed.dynamic_triangles, 0);
  EXPECT_GT(mixed.other_fixtures, 0);
}

TEST(Catalogue, SliversFarIsTheSameSceneTenKilometresAway) {
  std::vector<b2Vec2> near_positions;
  std::vector<float> near_angles;
  {  // one Box2D scene at a time: this one goes before the far one is built
    const std::unique_ptr<Scene> near = make_scene("slivers", box2d::Backend::Dyop, 3);
    for (const b2Body* b : dynamic_cast<const WorldScene&>(*near).world().bodies()) {
      near_positions.push_back(b->GetPosition());
      near_angles.push_back(b->GetAngle());
    }
  }
  const std::unique_ptr<Scene> far = make_scene("slivers-far", box2d::Backend::Dyop, 3);
  const std::vector<b2Body*>& far_bodies = dynamic_cast<const WorldScene&>(*far).world().bodies();
  ASSERT_EQ(far_bodies.size(), near_positions.size());
  for (std::size_t i = 0; i < far_bodies.size(); ++i) {
    const b2Vec2 p = far_bodies[i]->GetPosition();
    const double dx = double(p.x) - near_positions[i].x, dy = double(p.y) - near_positions[i].y;
    EXPECT_NEAR(std::hypot(dx, dy), 10000.0, 0.01) << "body " << i;
    EXPECT_EQ(far_bodies[i]->GetAngle(), near_angles[i]);
  }
}

// The probe's count of the contacts Collide updates agrees with the plug-in's own count, step by
// step, where nothing moves fast enough for Box2D's time-of-impact sub-steps.
TEST(ContactProbe, CountsExactlyWhatCollideUpdates) {
  const std::unique_ptr<Scene> scene = make_scene("pyramid", box2d::Backend::Dyop, 0);
  scene->step();  // step 1 makes the contacts inside Step: not measured
  for (int i = 0; i < 20; ++i) {
    const SceneMetrics before = scene->metrics();
    scene->step();
    const SceneMetrics after = scene->metrics();
    EXPECT_EQ(after.triangle_pairs - before.triangle_pairs,
              *after.plugin_evaluations - *before.plugin_evaluations)
        << "step " << i + 2;
  }
}

// Box2D's rule as `collide_action` reads it holds child by child: a box on a chain meets three of
// its children (fat boxes overlapping); moved one metre along it, its fat box leaves the first
// child's and still overlaps the two others': that contact alone is said to end, and the next
// step ends it and keeps the two others.
TEST(ContactProbe, CollideActionJudgesEachChildOfAChain) {
  b2World world(b2Vec2(0.0f, -10.0f));
  b2BodyDef ground_def;
  b2Body* ground = world.CreateBody(&ground_def);
  std::vector<b2Vec2> points;  // child i runs from x = i - 20 to i - 19
  for (int i = 0; i <= 40; ++i) points.emplace_back(static_cast<float>(i) - 20.0f, 0.0f);
  b2ChainShape chain;
  chain.CreateChain(points.data(), static_cast<int32>(points.size()), points.front() - b2Vec2(1, 0),
                    points.back() + b2Vec2(1, 0));
  ground->CreateFixture(&chain, 0.0f);
  b2BodyDef box_def;
  box_def.type = b2_dynamicBody;
  box_def.position.Set(5.5f, 0.45f);
  b2Body* box = world.CreateBody(&box_def);
  b2PolygonShape square;
  square.SetAsBox(0.5f, 0.5f);
  box->CreateFixture(&square, 1.0f);
  world.Step(1.0f / 60.0f, 8, 3);  // the contacts are made
  auto children = [&] {
    std::vector<std::pair<int32, const b2Contact*>> out;
    for (const b2Contact* c = world.GetContactList(); c != nullptr; c = c->GetNext()) {
      const bool a_is_ground = c->GetFixtureA() == ground->GetFixtureList();
      out.emplace_back(a_is_ground ? c->GetChildIndexA() : c->GetChildIndexB(), c);
    }
    std::sort(out.begin(), out.end());
    return out;
  };
  const auto before = children();
  ASSERT_EQ(before.size(), 3u);
  EXPECT_EQ(before[0].first, 24);
  EXPECT_EQ(before[2].first, 26);

  box->SetTransform(b2Vec2(6.5f, 0.45f), 0.0f);
  for (const auto& [child, contact] : before) {
    EXPECT_EQ(collide_action(world, *contact),
              child == 24 ? CollideAction::Destroy : CollideAction::Update)
        << "child " << child;
  }
  world.Step(1.0f / 60.0f, 8, 3);
  std::vector<int32> after;
  for (const auto& [child, contact] : children()) after.push_back(child);
  EXPECT_EQ(std::count(after.begin(), after.end(), 24), 0);
  EXPECT_EQ(std::count(after.begin(), after.end(), 25), 1);
  EXPECT_EQ(std::count(after.begin(), after.end(), 26), 1);
}

// Box2D's rule as `toi_swept` reads it: a box on the ground is swept for a time of impact; a box
// stacked on it is not, until it is a bullet; a sensor never is; nor is anything asleep.
TEST(ContactProbe, ToiSweptIsAnAwakeBodyAgainstStaticGroundOrABullet) {
  b2World world(b2Vec2(0.0f, -10.0f));
  b2BodyDef ground_def;
  b2Body* ground = world.CreateBody(&ground_def);
  b2PolygonShape slab;
  slab.SetAsBox(5.0f, 0.5f);
  ground->CreateFixture(&slab, 0.0f);
  b2PolygonShape square;
  square.SetAsBox(0.5f, 0.5f);
  auto box_at = [&](float y) {
    b2BodyDef def;
    def.type = b2_dynamicBody;
    def.position.Set(0.0f, y);
    b2Body* body = world.CreateBody(&def);
    body->CreateFixture(&square, 1.0f);
    return body;
  };
  b2Body* low = box_at(1.0f);
  b2Body* high = box_at(2.0f);
  b2FixtureDef sensor_def;
  sensor_def.shape = &square;
  sensor_def.isSensor = true;
  ground->CreateFixture(&sensor_def);  // overlaps the low box
  world.Step(1.0f / 60.0f, 8, 3);      // the contacts are made
  auto swept = [&](const b2Body* x, const b2Body* y, bool sensor) {
    for (const b2Contact* c = world.GetContactList(); c != nullptr; c = c->GetNext()) {
      const b2Fixture* fa = c->GetFixtureA();
      const b2Fixture* fb = c->GetFixtureB();
      const bool bodies =
          (fa->GetBody() == x && fb->GetBody() == y) || (fa->GetBody() == y && fb->GetBody() == x);
      if (bodies && (fa->IsSensor() || fb->IsSensor()) == sensor) return toi_swept(*c);
    }
    ADD_FAILURE() << "no such contact";
    return false;
  };
  EXPECT_TRUE(swept(ground, low, false));
  EXPECT_FALSE(swept(low, high, false)) << "two dynamic bodies, neither a bullet";
  EXPECT_FALSE(swept(ground, low, true)) << "a sensor";
  high->SetBullet(true);
  EXPECT_TRUE(swept(low, high, false));
  low->SetAwake(false);
  high->SetAwake(false);
  EXPECT_FALSE(swept(ground, low, false)) << "asleep";
}

// The probe's exact reference skips the distance search of pairs apart well beyond the tally's
// band: what it hands the tally is the full answer's separation wherever the tally reads its value
// (in contact, or apart within the band), and beyond the band a value above the band and at most
// the distance (but for rounding), from which the tally counts the same.
TEST(ContactProbe, SeparationAsTalliedIsTheFullAnswerWhereverTheTallyReadsIt) {
  std::mt19937 rng(2026);
  std::uniform_real_distribution<double> u(-1, 1);
  int in_contact = 0, apart_within = 0, apart_beyond = 0;
  for (int i = 0; i < 4000; ++i) {
    const auto a = Triangle<double>::make({u(rng), u(rng)}, {u(rng), u(rng)}, {u(rng), u(rng)});
    const Vec2<double> shift(1.5 * u(rng), 1.5 * u(rng));
    const auto b = Triangle<double>::make(Vec2<double>(u(rng), u(rng)) + shift,
                                          Vec2<double>(u(rng), u(rng)) + shift,
                                          Vec2<double>(u(rng), u(rng)) + shift);
    if (!a.ok() || !b.ok()) continue;
    const double band = i % 2 == 0 ? 0.0 : 0.2;
    const double full = sat(a.triangle, b.triangle).separation;
    const double fast = separation_as_tallied(a.triangle, b.triangle, band);
    if (full <= band) {
      EXPECT_EQ(fast, full) << "pair " << i;
      (full <= 0 ? in_contact : apart_within) += 1;
    } else {
      EXPECT_GT(fast, band) << "pair " << i;
      EXPECT_LE(fast, full * (1 + 1e-12)) << "pair " << i << ": a gap, at most the distance";
      ++apart_beyond;
    }
  }
  EXPECT_GT(in_contact, 100);
  EXPECT_GT(apart_within, 100);
  EXPECT_GT(apart_beyond, 100);
}

}  // namespace
}  // namespace dyop::scenes
