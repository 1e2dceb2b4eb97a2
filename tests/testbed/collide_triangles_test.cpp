// collide_triangles: Box2D's own answer (b2CollidePolygons, then b2Distance when apart) under the
// library's conventions, as `dyop pairs --method box2d` prints it.
#include <gtest/gtest.h>

#include <iostream>

#include "box2d_reference/collide_triangles.hpp"
#include "dyop/box2d.hpp"
#include "dyop/sat.hpp"
#include "workloads/random.hpp"

namespace dyop::box2d::testing {
namespace {

using V = Vec2<float>;

Triangle<float> triangle(V p0, V p1, V p2) {
  const TriangleOrError<float> t = Triangle<float>::make(p0, p1, p2);
  EXPECT_TRUE(t.ok());
  return t.triangle;
}

// Float arithmetic on coordinates of a few metres: a few ulps of the result.
constexpr float kTolerance = 1e-5f;

TEST(CollideTriangles, PenetratingPairGivesDepthAndNormalFromAToB) {
  const Triangle<float> a = triangle(V(0, 0), V(2, 0), V(0, 2));
  // B's lowest vertex 0.1 into A's hypotenuse, B above-right of A: normal (1, 1)/√2.
  const float inside = 0.1f * std::sqrt(2.0f);
  const V tip(1.0f - 0.5f * inside, 1.0f - 0.5f * inside);
  const Triangle<float> b = triangle(tip, tip + V(2, 1), tip + V(1, 2));
  const Result<float> r = collide_triangles(a, b);
  ASSERT_EQ(r.status, Status::Penetrating);
  EXPECT_NEAR(r.depth, 0.1f, kTolerance);
  EXPECT_NEAR(r.separation, -0.1f, kTolerance);
  EXPECT_NEAR(r.normal.x(), std::sqrt(0.5f), kTolerance);
  EXPECT_NEAR(r.normal.y(), std::sqrt(0.5f), kTolerance);
  EXPECT_LE((r.witness_a - r.witness_b - r.depth * r.normal).norm(), kTolerance);
  EXPECT_LE((r.witness_b - tip).norm(), kTolerance) << "B's deepest vertex";

  // Swapped, the reference face becomes B's in Box2D's terms: the normal still points A to B.
  const Result<float> s = collide_triangles(b, a);
  ASSERT_EQ(s.status, Status::Penetrating);
  EXPECT_NEAR(s.depth, 0.1f, kTolerance);
  EXPECT_NEAR(s.normal.x(), -std::sqrt(0.5f), kTolerance);
  EXPECT_NEAR(s.normal.y(), -std::sqrt(0.5f), kTolerance);
  EXPECT_LE((s.witness_a - s.witness_b - s.depth * s.normal).norm(), kTolerance);
}

TEST(CollideTriangles, SeparatedPairGivesBox2DsGjkDistance) {
  const Triangle<float> a = triangle(V(0, 0), V(1, 0), V(0, 1));
  const Triangle<float> b = triangle(V(1.0f, 0.5f), V(2.0f, 0.5f), V(1.0f, 1.5f));
  const Result<float> r = collide_triangles(a, b);
  ASSERT_EQ(r.status, Status::Separated);
  // B's vertex (1, 0.5) against A's edge on x + y = 1 (its foot (0.75, 0.25) is on the edge).
  const float expected = 0.5f / std::sqrt(2.0f);
  EXPECT_NEAR(r.separation, expected, kTolerance);
  EXPECT_EQ(r.depth, 0.0f);
  EXPECT_NEAR(r.normal.x(), std::sqrt(0.5f), kTolerance);
  EXPECT_NEAR(r.normal.y(), std::sqrt(0.5f), kTolerance);
  EXPECT_NEAR((r.witness_b - r.witness_a).norm(), expected, kTolerance);
  EXPECT_GT(r.iterations, 0);
}

TEST(CollideTriangles, AgreesWithSatOnRandomPairsUpToBox2DsOwnChoices) {
  // Triangles of size ~1 in a 3 m square: overlapping about a third of the time.
  workloads::Random rng(11);
  // A point in the square of half side `half`, its draws in order (a call's arguments are not).
  auto point = [&](double half) {
    const float x = rng.uniformf(-half, half);
    const float y = rng.uniformf(-half, half);
    return V(x, y);
  };
  auto triangle = [&](const V& centre) {
    const V p = centre + point(0.7);
    const V q = centre + point(0.7);
    const V r = centre + point(0.7);
    return Triangle<float>::make(p, q, r);
  };
  int penetrating = 0;
  int separated = 0;
  float worst_distance = 0;
  float worst_depth = 0;
  for (int pair = 0; pair < 5000; ++pair) {
    const V ca = point(1.5);
    const V cb = point(1.5);
    const auto a = triangle(ca);
    const auto b = triangle(cb);
    if (!a.ok() || !b.ok()) continue;
    const Result<float> box2d = collide_triangles(a.triangle, b.triangle);
    const Result<float> exact = sat(a.triangle, b.triangle);
    // Near touching, rounding decides the status: not compared.
    if (std::abs(exact.separation) < 1e-4f) continue;
    ASSERT_EQ(box2d.status, exact.status) << "pair " << pair;
    if (exact.status == Status::Separated) {
      ++separated;
      worst_distance = std::max(worst_distance, std::abs(box2d.separation - exact.separation));
    } else {
      ++penetrating;
      worst_depth = std::max(worst_depth, std::abs(box2d.depth - exact.depth));
    }
  }
  std::cout << "box2d vs sat (float): " << separated << " separated pairs, max |Δdistance| "
            << worst_distance << "; " << penetrating << " penetrating, max |Δdepth| " << worst_depth
            << "\n";
  EXPECT_LE(worst_distance, kTolerance);
  // Box2D keeps A's face while B's is better by less than its k_tol, so its depth may exceed the
  // minimum by that much; otherwise both take the same face.
  EXPECT_LE(worst_depth, face_hysteresis);
}

}  // namespace
}  // namespace dyop::box2d::testing
