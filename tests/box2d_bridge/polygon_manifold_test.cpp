// The manifolds of polygon pairs beyond two triangles, read as Box2D's solver reads them (each
// point's separation from the reference face, `b2PositionSolverManifold`), are the exact depth of
// the placed shapes within the float bound of the exact solver; and a tower of `SetAsBox` boxes
// stands as still as under Box2D's own contact, though the reference face now follows the least
// overlap (two faces tied within rounding keep theirs, so the points keep their names).
#include <gtest/gtest.h>

#include <box2d/box2d.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "dyop/box2d.hpp"
#include "dyop/convex_pair.hpp"

namespace dyop::box2d::testing {
namespace {

// The float bound of the exact solver on pairs, relative to the pair's size
// (`workloads::exact_bound`).
constexpr double kFloatBound = 1e-5;

// The deepest of the manifold's points as Box2D's position solver reads them: its distance from
// the reference face along the face's normal (the skins left out), in double.
double solver_separation(const b2Manifold& m, const b2Transform& xa, const b2Transform& xb) {
  const bool face_a = m.type == b2Manifold::e_faceA;
  const b2Transform& ref = face_a ? xa : xb;
  const b2Transform& inc = face_a ? xb : xa;
  const b2Vec2 normal = b2Mul(ref.q, m.localNormal);
  const b2Vec2 plane = b2Mul(ref, m.localPoint);
  double deepest = HUGE_VAL;
  for (int i = 0; i < m.pointCount; ++i) {
    const b2Vec2 p = b2Mul(inc, m.points[i].localPoint);
    deepest = std::min(deepest, double(normal.x) * (double(p.x) - plane.x) +
                                    double(normal.y) * (double(p.y) - plane.y));
  }
  return deepest;
}

Polygon<double> placed(const b2PolygonShape& s, const b2Transform& xf) {
  Vec2<double> v[b2_maxPolygonVertices];
  for (int i = 0; i < s.m_count; ++i) {
    const b2Vec2 p = b2Mul(xf, s.m_vertices[i]);
    v[i] = Vec2<double>(p.x, p.y);
  }
  return Polygon<double>::make(v, s.m_count).polygon;
}

b2PolygonShape regular(int n, float r) {
  b2Vec2 v[b2_maxPolygonVertices];
  for (int i = 0; i < n; ++i) {
    const float a = 2 * b2_pi * static_cast<float>(i) / static_cast<float>(n);
    v[i] = b2Vec2(r * std::cos(a), r * std::sin(a));
  }
  b2PolygonShape p;
  p.Set(v, n);
  return p;
}

// Random overlapping poses of a box against a box and of a hexagon against a box, 0.2 m and 1 m
// across: the deepest separation the solver reads against the exact depth (double, on the float
// shapes as placed). Box2D's own reads up to its hysteresis (0.1·linearSlop) too deep.
TEST(PolygonManifolds, TheDepthTheSolverReadsIsExactWithinTheFloatBound) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(-1, 1);
  for (const float size : {0.2f, 1.0f}) {
    b2PolygonShape box;
    box.SetAsBox(0.5f * size, 0.5f * size);
    b2PolygonShape small_box;
    small_box.SetAsBox(0.4f * size, 0.3f * size);
    b2PolygonShape hexagon = regular(6, 0.5f * size);
    for (const b2PolygonShape* a : {&box, &hexagon}) {
      double worst = 0;
      double worst_own = 0;
      int pairs = 0;
      for (int t = 0; t < 20000; ++t) {
        const b2Transform xa(b2Vec2(u(rng), u(rng)), b2Rot(b2_pi * u(rng)));
        const b2Transform xb(xa.p + size * b2Vec2(u(rng), u(rng)), b2Rot(b2_pi * u(rng)));
        b2Manifold m;
        b2Manifold own;
        collide_polygons(&m, Backend::Dyop, *a, xa, small_box, xb);
        b2CollidePolygons(&own, a, xa, &small_box, xb);
        const Result<double> exact = collide(placed(*a, xa), placed(small_box, xb));
        if (!(exact.separation < 0) || m.pointCount == 0) continue;
        ++pairs;
        worst = std::max(worst, std::abs(solver_separation(m, xa, xb) - exact.separation) / size);
        if (own.pointCount > 0) {
          worst_own = std::max(worst_own,
                               std::abs(solver_separation(own, xa, xb) - exact.separation) / size);
        }
      }
      std::printf(
          "%d-gon on a box, %.1f m: %d pairs, largest error / size %.3g (Box2D's own %.3g)\n",
          a->m_count, size, pairs, worst, worst_own);
      EXPECT_GT(pairs, 5000);
      EXPECT_LE(worst, kFloatBound) << a->m_count << "-gon, " << size << " m";
      EXPECT_GT(worst_own, 10 * kFloatBound);  // the hysteresis this removes
    }
  }
}

// How far the boxes of a tower drift sideways and turn in 10 s (metres plus radians, largest).
float tower_drift(int boxes) {
  b2World world(b2Vec2(0, -10));
  b2BodyDef def;
  b2Body* ground = world.CreateBody(&def);
  b2PolygonShape floor;
  floor.SetAsBox(20, 0.5f, b2Vec2(0, -0.5f), 0);
  ground->CreateFixture(&floor, 0);
  std::vector<b2Body*> tower;
  b2PolygonShape box;
  box.SetAsBox(0.5f, 0.5f);
  b2FixtureDef fixture;
  fixture.shape = &box;
  fixture.density = 1;
  fixture.friction = 0.6f;
  def.type = b2_dynamicBody;
  for (int i = 0; i < boxes; ++i) {
    def.position.Set(0, 0.5f + static_cast<float>(i));
    tower.push_back(world.CreateBody(&def));
    tower.back()->CreateFixture(&fixture);
  }
  for (int s = 0; s < 600; ++s) world.Step(1.0f / 60, 8, 3);
  float drift = 0;
  for (const b2Body* b : tower) {
    drift = std::max(drift, std::abs(b->GetPosition().x) + std::abs(b->GetAngle()));
  }
  return drift;
}

TEST(PolygonManifolds, ATowerOfBoxesStandsAsUnderBox2DsOwnContact) {
  for (const int boxes : {10, 20}) {
    ASSERT_TRUE(uninstall().ok());
    const float own = tower_drift(boxes);
    ASSERT_TRUE(install(Backend::Dyop).ok());
    const float plugged = tower_drift(boxes);
    ASSERT_TRUE(uninstall().ok());
    std::printf("tower of %d boxes: drift %.5f (Box2D's own %.5f)\n", boxes, plugged, own);
    EXPECT_LE(plugged, 1.1f * own + 1e-3f) << boxes << " boxes";
  }
}

}  // namespace
}  // namespace dyop::box2d::testing
