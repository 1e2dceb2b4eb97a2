// A world of circles, boxes, a pentagon, edges and triangles: the plug-in answers every polygon
// pair, polygon–circle pair and edge pair exactly as its single-pair entry points do
// (`collide_polygons`, `collide_polygon_and_circle`, `collide_edge_and_polygon`,
// `collide_edge_and_circle`: the exact solver, or Box2D's own functions under `Backend::Box2D`),
// and leaves circle–circle pairs to Box2D's own contact.
#include <gtest/gtest.h>

#include <cstring>
#include <iostream>
#include <vector>

#include "dyop/box2d.hpp"
#include "support/worlds.hpp"

namespace dyop::box2d::testing {
namespace {

bool is_triangle(const b2Fixture* f) {
  return f->GetType() == b2Shape::e_polygon &&
         static_cast<const b2PolygonShape*>(f->GetShape())->m_count == 3;
}

bool same(const b2Manifold& x, const b2Manifold& y) {
  if (x.pointCount != y.pointCount) return false;
  if (x.pointCount == 0) return true;
  if (x.type != y.type || !(x.localNormal == y.localNormal) || !(x.localPoint == y.localPoint)) {
    return false;
  }
  for (int i = 0; i < x.pointCount; ++i) {
    if (!(x.points[i].localPoint == y.points[i].localPoint) ||
        x.points[i].id.key != y.points[i].id.key) {
      return false;
    }
  }
  return true;
}

// Checks every manifold right after Box2D evaluated it (PreSolve runs then, with the transforms
// Evaluate saw): every pair the plug-in takes must be its single-pair entry points' answer, bit
// for bit (triangle pairs but for Lin–Canny's, which starts from the contact's own cache).
class Checker : public b2ContactListener {
 public:
  Checker(Backend backend, const Config& config) : backend_(backend), config_(config) {}

  void PreSolve(b2Contact* contact, const b2Manifold*) override {
    const b2Fixture* fa = contact->GetFixtureA();
    const b2Fixture* fb = contact->GetFixtureB();
    b2Manifold expected;
    if (fa->GetType() == b2Shape::e_polygon && fb->GetType() == b2Shape::e_circle) {
      ++circle_pairs;
      collide_polygon_and_circle(
          &expected, backend_, *static_cast<const b2PolygonShape*>(fa->GetShape()),
          fa->GetBody()->GetTransform(), *static_cast<const b2CircleShape*>(fb->GetShape()),
          fb->GetBody()->GetTransform(), nullptr, config_);
      ++own_evaluations;
      own_manifolds += expected.pointCount > 0;
      if (!same(*contact->GetManifold(), expected)) ++mismatches;
      return;
    }
    if (fa->GetType() == b2Shape::e_edge) {
      ++edge_pairs;
      const auto& edge = *static_cast<const b2EdgeShape*>(fa->GetShape());
      const b2Transform& xa = fa->GetBody()->GetTransform();
      const b2Transform& xb = fb->GetBody()->GetTransform();
      if (fb->GetType() == b2Shape::e_circle) {
        collide_edge_and_circle(&expected, backend_, edge, xa,
                                *static_cast<const b2CircleShape*>(fb->GetShape()), xb, nullptr,
                                config_);
      } else {
        collide_edge_and_polygon(&expected, backend_, edge, xa,
                                 *static_cast<const b2PolygonShape*>(fb->GetShape()), xb, nullptr,
                                 config_);
      }
      ++own_evaluations;
      own_manifolds += expected.pointCount > 0;
      if (!same(*contact->GetManifold(), expected)) ++mismatches;
      return;
    }
    if (fa->GetType() != b2Shape::e_polygon || fb->GetType() != b2Shape::e_polygon) {
      ++other_pairs;  // circles with circles: Box2D's own contact class
      return;
    }
    const auto* a = static_cast<const b2PolygonShape*>(fa->GetShape());
    const auto* b = static_cast<const b2PolygonShape*>(fb->GetShape());
    const b2Transform& xa = fa->GetBody()->GetTransform();
    const b2Transform& xb = fb->GetBody()->GetTransform();
    const bool triangles = is_triangle(fa) && is_triangle(fb);
    triangle_pairs += triangles;
    polygon_pairs += !triangles;
    // Lin–Canny starts from the contact's own cache, which this check cannot share.
    if (triangles && backend_ == Backend::LinCanny) return;
    collide_polygons(&expected, backend_, *a, xa, *b, xb, nullptr, config_);
    ++(triangles ? own_triangle_evaluations : own_evaluations);  // counted in stats() too: the
    own_manifolds += expected.pointCount > 0;                    // test takes them out again
    if (!same(*contact->GetManifold(), expected)) ++mismatches;
  }

  int triangle_pairs = 0;
  int polygon_pairs = 0;
  int circle_pairs = 0;
  int edge_pairs = 0;
  int other_pairs = 0;
  int mismatches = 0;
  std::uint64_t own_triangle_evaluations = 0;
  std::uint64_t own_evaluations = 0;
  std::uint64_t own_manifolds = 0;

 private:
  Backend backend_;
  Config config_;
};

// Edges for ground, a static box, and dynamic circles, boxes, a pentagon and triangles dropped
// in a heap, so that every kind of pair touches.
std::vector<b2Body*> build_mixed_world(World& world) {
  b2Body* ground = add_body(world, b2_staticBody, b2Vec2(0.0f, 0.0f));
  b2EdgeShape edge;
  edge.SetTwoSided(b2Vec2(-12.0f, 0.0f), b2Vec2(12.0f, 0.0f));
  ground->CreateFixture(&edge, 0.0f);
  edge.SetTwoSided(b2Vec2(-12.0f, 0.0f), b2Vec2(-14.0f, 8.0f));
  ground->CreateFixture(&edge, 0.0f);
  edge.SetTwoSided(b2Vec2(12.0f, 0.0f), b2Vec2(14.0f, 8.0f));
  ground->CreateFixture(&edge, 0.0f);
  b2PolygonShape block;
  block.SetAsBox(1.0f, 0.5f, b2Vec2(4.0f, 0.5f), 0.0f);
  ground->CreateFixture(&block, 0.0f);

  std::vector<b2Body*> bodies;
  for (int i = 0; i < 40; ++i) {
    const b2Vec2 p(-6.0f + 1.5f * (i % 9), 2.0f + 1.5f * (i / 9));
    b2Body* body = add_body(world, b2_dynamicBody, p, 0.3f * i);
    switch (i % 4) {
      case 0: {
        b2CircleShape circle;
        circle.m_radius = 0.4f;
        body->CreateFixture(&circle, 1.0f);
        break;
      }
      case 1: {
        b2PolygonShape box;
        box.SetAsBox(0.5f, 0.3f);
        body->CreateFixture(&box, 1.0f);
        break;
      }
      case 2:
        add_triangle(body, b2Vec2(-0.5f, -0.3f), b2Vec2(0.5f, -0.3f), b2Vec2(0.0f, 0.5f));
        break;
      default: {
        if (i % 8 == 3) {
          b2PolygonShape pentagon;
          b2Vec2 v[5];
          for (int k = 0; k < 5; ++k)
            v[k].Set(0.5f * std::cos(1.2566f * k), 0.5f * std::sin(1.2566f * k));
          pentagon.Set(v, 5);
          body->CreateFixture(&pentagon, 1.0f);
        } else {
          add_triangle(body, b2Vec2(-0.4f, -0.4f), b2Vec2(0.4f, -0.4f), b2Vec2(0.4f, 0.4f));
          add_triangle(body, b2Vec2(-0.4f, -0.4f), b2Vec2(0.4f, 0.4f), b2Vec2(-0.4f, 0.4f));
        }
      }
    }
    bodies.push_back(body);
  }
  return bodies;
}

class MixedWorld : public ::testing::TestWithParam<Backend> {
 protected:
  // The checker recomputes triangle pairs with `collide_polygons`, which does not know the
  // bodies' internal edges (the split boxes' diagonals): the rule is off here, and tested in
  // internal_edges_in_worlds_test. It computes every manifold afresh: recycling is off here too,
  // and tested in recycling_test.
  void SetUp() override {
    config.internal_edges = false;
    config.recycle_distance = 0;
    ASSERT_TRUE(install(GetParam(), config).ok());
  }
  Config config;
  void TearDown() override { EXPECT_TRUE(uninstall().ok()); }
};

TEST_P(MixedWorld, EveryPairIsTheSinglePairEntryPointsAnswer) {
  Checker checker(GetParam(), config);
  {
    World world;
    world->SetContactListener(&checker);
    build_mixed_world(world);
    for (int i = 0; i < 4 * kStepsPerSecond; ++i) world.step();
  }
  const Stats s = stats();
  const std::uint64_t triangle_pairs = s.triangles(GetParam()) - checker.own_triangle_evaluations;
  const std::uint64_t manifolds = s.manifolds - checker.own_manifolds;
  const std::uint64_t beyond =
      s.polygon_pairs + s.circle_pairs + s.edge_pairs - checker.own_evaluations;
  std::cout << name(GetParam()) << ": touching triangle pairs " << checker.triangle_pairs
            << ", other polygon pairs " << checker.polygon_pairs << ", polygon-circle pairs "
            << checker.circle_pairs << ", edge pairs " << checker.edge_pairs
            << ", circle-circle pairs " << checker.other_pairs << "; stats: triangle pairs "
            << triangle_pairs << ", other pairs " << beyond << ", manifolds " << manifolds
            << ", fallbacks " << s.fallbacks << "\n";
  EXPECT_EQ(checker.mismatches, 0);
  EXPECT_GT(checker.triangle_pairs, 0);
  EXPECT_GT(checker.polygon_pairs, 0);
  EXPECT_GT(checker.circle_pairs, 0);
  EXPECT_GT(checker.edge_pairs, 0);
  EXPECT_GT(checker.other_pairs, 0);
  // The exact solver answered the pairs beyond triangles, but under Box2D's own backend.
  EXPECT_EQ(s.exact_pairs == 0, GetParam() == Backend::Box2D);
  // Every pair the plug-in evaluated went where it belongs, and was counted there.
  // Counted where they belong: every touching pair was evaluated (and more, in the broad phase's
  // overlapping pairs that do not touch), and every touching triangle pair had a manifold.
  EXPECT_GE(triangle_pairs, static_cast<std::uint64_t>(checker.triangle_pairs));
  const int beyond_touching = checker.polygon_pairs + checker.circle_pairs + checker.edge_pairs;
  EXPECT_GE(beyond, static_cast<std::uint64_t>(beyond_touching));
  EXPECT_EQ(manifolds, static_cast<std::uint64_t>(checker.triangle_pairs + beyond_touching));
  EXPECT_EQ(s.fallbacks, 0u);
  for (Backend other : all_backends) {
    if (other != GetParam()) {
      EXPECT_EQ(s.triangles(other), 0u) << name(other);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(EveryBackend, MixedWorld, ::testing::ValuesIn(all_backends),
                         [](const auto& info) {
                           std::string n = name(info.param);
                           std::replace(n.begin(), n.end(), '-', '_');
                           return n;
                         });

// The final state of every body after 4 s of the mixed world.
std::vector<b2Transform> run_mixed_world() {
  World world;
  const std::vector<b2Body*> bodies = build_mixed_world(world);
  for (int i = 0; i < 4 * kStepsPerSecond; ++i) world.step();
  std::vector<b2Transform> out;
  for (const b2Body* b : bodies) out.push_back(b->GetTransform());
  return out;
}

TEST(MixedWorldThroughThePlugIn, Box2DBackendIsBitIdenticalToBox2DsOwnContact) {
  ASSERT_FALSE(installed().has_value());
  const std::vector<b2Transform> own = run_mixed_world();
  ASSERT_TRUE(install(Backend::Box2D).ok());
  const std::vector<b2Transform> plugged = run_mixed_world();
  const Stats s = stats();
  EXPECT_TRUE(uninstall().ok());
  EXPECT_GT(s.triangles(Backend::Box2D), 0u);
  ASSERT_EQ(own.size(), plugged.size());
  for (std::size_t i = 0; i < own.size(); ++i) {
    EXPECT_EQ(std::memcmp(&own[i], &plugged[i], sizeof(b2Transform)), 0) << "body " << i;
  }
}

}  // namespace
}  // namespace dyop::box2d::testing
