// `Query::internal_edges` with the exact methods (`dyop`, `sat`): the
// depth along the directions a triangulated body's outline allows, on cases worked by hand.
//
// The ground is the top row of a triangulated strip whose top is y = 0: cell [1, 2] × [-1, 0]
// split along its diagonal, upper-left triangle A = (1,0) (1,-1) (2,0). Its edge 0 (x = 1,
// shared with the cell on the left) and edge 1 (the diagonal) are internal; edge 2 is the top.
// Its vertices 0 and 2 lie on the flat top, each touching the top edge: flat vertices.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <limits>
#include <vector>

#include "dyop/method.hpp"
#include "exact_reference/exact_reference.hpp"
#include "workloads/raw_pair.hpp"
#include "support/make_triangle.hpp"
#include "support/result_checks.hpp"
#include "support/scalars.hpp"

namespace dyop {
namespace {

using test_support::tol;
using test_support::tri;

constexpr std::uint8_t ground_edges = 0b011;     // A's edges 0 and 1
constexpr std::uint8_t ground_vertices = 0b101;  // A's vertices 0 and 2

template <class T>
Triangle<T> ground() {
  return tri<T>(1, 0, 1, -1, 2, 0);
}

template <class T>
Query<T> query(Level level, std::uint8_t edges, std::uint8_t vertices) {
  Query<T> q;
  q.level = level;
  q.internal_edges = {edges, vertices};
  return q;
}

template <class T>
class InternalEdgeMasks : public ::testing::Test {};
TYPED_TEST_SUITE(InternalEdgeMasks, test_support::Scalars, test_support::ScalarNames);

// Both exact methods, same answer.
template <class T, class Check>
void for_exact_methods(const Check& check) {
  for (const Method m : {Method::Dyop, Method::Sat}) {
    SCOPED_TRACE(name(m));
    EXPECT_TRUE(info(m).internal_edges());
    check(m);
  }
}

template <class T>
void expect_up(const Result<T>& r, T depth) {
  EXPECT_EQ(r.status, Status::Penetrating);
  EXPECT_NEAR(r.depth, depth, tol<T>());
  EXPECT_NEAR(r.normal.x(), 0, tol<T>());
  EXPECT_NEAR(r.normal.y(), 1, tol<T>());
}

// B's corner (1.02, -0.05) just past the junction x = 1, 0.05 under the top: unrestricted, the
// least axis is the internal edge x = 1 (0.02: B pushed back, the ghost collision); B's own side
// x = 1.02 gives 0.02 too, but its deepest vertex of A is the flat vertex (1,0). Allowed: the
// top, 0.05, up.
TYPED_TEST(InternalEdgeMasks, VertexOfBAgainstAFlatJunction) {
  using T = TypeParam;
  const auto a = ground<T>();
  const auto b = tri<T>(T(1.02), T(-0.05), T(1.02), 1, 0, 1);
  for_exact_methods<T>([&](Method m) {
    const Result<T> plain = penetrate(m, a, b, query<T>(Level::Contact, 0, 0));
    EXPECT_NEAR(plain.depth, T(0.02), 10 * tol<T>());
    EXPECT_NEAR(plain.normal.x(), -1, tol<T>());
    const Result<T> r =
        penetrate(m, a, b, query<T>(Level::Manifold, ground_edges, ground_vertices));
    expect_up(r, T(0.05));
    EXPECT_EQ(r.feature_a.type, Feature::Type::Edge);
    EXPECT_EQ(r.feature_a.index, 2);
    EXPECT_TRUE(r.manifold.reference_is_a);
    EXPECT_EQ(r.manifold.reference_edge, 2);
    // B's corner itself, 0.05 under the top, and where B's slanted edge crosses x = 1.
    ASSERT_EQ(r.manifold.point_count, 2);
    EXPECT_NEAR(std::min(r.manifold.points[0].separation, r.manifold.points[1].separation),
                T(-0.05), 10 * tol<T>());
    // Without the flat vertices B's side face wins (0.02, B pushed back): both masks matter.
    const Result<T> edges_only = penetrate(m, a, b, query<T>(Level::Depth, ground_edges, 0));
    EXPECT_NEAR(edges_only.normal.x(), -1, tol<T>());
  });
}

// B = (0.5,-0.6) (1.5,-0.6) (1,0.5) straddles the internal edge x = 1, 0.6 deep. Unrestricted:
// 0.5 along -x (the internal edge). B's faces: its bottom reaches A's flat vertex (1,0); its
// sides give 0.621 and 1.117. Allowed least: the top, 0.6.
TYPED_TEST(InternalEdgeMasks, TriangleOfBStraddlingAnInternalEdge) {
  using T = TypeParam;
  const auto a = ground<T>();
  const auto b = tri<T>(T(0.5), T(-0.6), T(1.5), T(-0.6), 1, T(0.5));
  for_exact_methods<T>([&](Method m) {
    const Result<T> plain = penetrate(m, a, b, query<T>(Level::Depth, 0, 0));
    EXPECT_NEAR(plain.depth, T(0.5), 10 * tol<T>());
    const Result<T> r =
        penetrate(m, a, b, query<T>(Level::Manifold, ground_edges, ground_vertices));
    expect_up(r, T(0.6));
    EXPECT_TRUE(r.manifold.reference_is_a);
    EXPECT_EQ(r.manifold.reference_edge, 2);
  });
}

// B = (1.1,-0.5) (1.3,-0.5) (1.2,-0.3), deep inside, every edge of B internal to its body: only
// A's top is allowed. Unrestricted: 0.3 along -x (x = 1); the diagonal gives 0.354; the top 0.5.
TYPED_TEST(InternalEdgeMasks, DeepPenetrationWhereOnlyTheOutlineIsAllowed) {
  using T = TypeParam;
  const auto a = ground<T>();
  const auto b = tri<T>(T(1.1), T(-0.5), T(1.3), T(-0.5), T(1.2), T(-0.3));
  for_exact_methods<T>([&](Method m) {
    const Result<T> plain = penetrate(m, a, b, query<T>(Level::Depth, 0, 0));
    EXPECT_NEAR(plain.depth, T(0.3), 10 * tol<T>());
    const Result<T> r =
        penetrate(m, a, b, query<T>(Level::Manifold, ground_edges | 0b111000, ground_vertices));
    expect_up(r, T(0.5));
    EXPECT_EQ(r.manifold.reference_edge, 2);
    EXPECT_EQ(r.manifold.point_count, 2);
  });
}

// The lower-right triangle of the cell, C = (1,-1) (2,-1) (2,0), touches the top only at its
// apex (2,0), where both its edges are internal (edge 1 at x = 2, edge 2 the diagonal); its only
// outline edge is the bottom, y = -1. B, a box's triangle resting on the top across the apex
// 0.01 deep, reaches the bottom nowhere: the bottom is allowed by the masks but is no way out,
// and the pair gives no contact (the top triangles carry it). Unrestricted: 0.01 up.
TYPED_TEST(InternalEdgeMasks, AnOutlineEdgeTheOtherTriangleDoesNotReachIsNoAxis) {
  using T = TypeParam;
  const auto c = tri<T>(1, -1, 2, -1, 2, 0);
  const auto b = tri<T>(T(1.7), T(-0.01), T(2.3), T(-0.01), T(2.3), T(0.5));
  for_exact_methods<T>([&](Method m) {
    const Result<T> plain = penetrate(m, c, b, query<T>(Level::Depth, 0, 0));
    EXPECT_NEAR(plain.depth, T(0.01), 10 * tol<T>());
    const Result<T> r = penetrate(m, c, b, query<T>(Level::Manifold, 0b110, 0b111));
    EXPECT_EQ(r.status, Status::Penetrating);
    EXPECT_LT(r.depth, T(0.5));  // never the 1.01 m push through the bottom
    EXPECT_EQ(r.manifold.point_count, 0);
  });
}

// The depth against the exact rational reference: in each constructed case above, the least
// exact overlap over the edges the rule may use there (listed by hand from the cases' comments).
TYPED_TEST(InternalEdgeMasks, DepthIsTheLeastExactOverlapAlongTheUsableEdges) {
  using T = TypeParam;
  struct Usable {
    bool of_a;
    int edge;
  };
  struct Case {
    const char* what;
    workloads::RawPair pair;
    std::uint8_t edges;
    std::uint8_t vertices;
    std::vector<Usable> usable;
  };
  const std::array<Vec2<double>, 3> ground_pts = {{{1, 0}, {1, -1}, {2, 0}}};
  const Case cases[] = {
      {"vertex past a flat junction",
       {ground_pts, {{{1.02, -0.05}, {1.02, 1}, {0, 1}}}},
       ground_edges,
       ground_vertices,
       {{true, 2}}},
      {"straddling an internal edge",
       {ground_pts, {{{0.5, -0.6}, {1.5, -0.6}, {1, 0.5}}}},
       ground_edges,
       ground_vertices,
       {{true, 2}, {false, 1}, {false, 2}}},
      {"deep, only the outline",
       {ground_pts, {{{1.1, -0.5}, {1.3, -0.5}, {1.2, -0.3}}}},
       ground_edges | 0b111000,
       ground_vertices,
       {{true, 2}}},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.what);
    double exact = std::numeric_limits<double>::infinity();
    for (const Usable& u : c.usable) {
      exact = std::min(exact, workloads::exact_edge_overlap(c.pair, u.of_a, u.edge));
    }
    const auto built = workloads::build<T>(c.pair);
    ASSERT_TRUE(built.a.ok() && built.b.ok());
    for_exact_methods<T>([&](Method m) {
      const Result<T> r = penetrate(m, built.a.triangle, built.b.triangle,
                                    query<T>(Level::Manifold, c.edges, c.vertices));
      EXPECT_NEAR(double(r.depth), exact, 10 * double(tol<T>()));
    });
  }
}

// Apart by 0.05 along the internal edge only (B left of x = 1, level with the top): the status
// is decided over all axes, and a manifold is empty beyond the margin.
TYPED_TEST(InternalEdgeMasks, SeparatedAlongAnInternalEdgeStaysApart) {
  using T = TypeParam;
  const auto a = ground<T>();
  const auto b = tri<T>(T(0.95), T(-0.5), T(0.95), T(0.5), 0, T(0.5));
  for_exact_methods<T>([&](Method m) {
    Query<T> q = query<T>(Level::Manifold, ground_edges, ground_vertices);
    q.margin = T(0.02);
    const Result<T> r = penetrate(m, a, b, q);
    EXPECT_EQ(r.status, Status::Separated);
    EXPECT_EQ(r.manifold.point_count, 0);
  });
}

// Every axis of both triangles internal: the status and depth are the unrestricted answer, and
// no contact comes from this pair.
TYPED_TEST(InternalEdgeMasks, NoAllowedAxisGivesNoContact) {
  using T = TypeParam;
  const auto a = ground<T>();
  const auto b = tri<T>(T(1.1), T(-0.5), T(1.3), T(-0.5), T(1.2), T(-0.3));
  for_exact_methods<T>([&](Method m) {
    const Result<T> plain = penetrate(m, a, b, query<T>(Level::Manifold, 0, 0));
    const Result<T> r = penetrate(m, a, b, query<T>(Level::Manifold, 0b111111, 0));
    EXPECT_EQ(r.status, plain.status);
    EXPECT_EQ(r.depth, plain.depth);
    EXPECT_EQ(r.manifold.point_count, 0);
  });
}

// Masks given in the caller's order also for clockwise input: A given clockwise is the same
// triangle with edges renumbered (caller edge 2 = (1,0)->(2,0)... here: (1,0) (2,0) (1,-1), whose
// edges 0 top, 1 diagonal, 2 internal x = 1; vertices 0 and 1 flat).
TYPED_TEST(InternalEdgeMasks, MasksAreInTheCallersOrder) {
  using T = TypeParam;
  const auto a = tri<T>(1, 0, 2, 0, 1, -1);
  const auto b = tri<T>(T(1.02), T(-0.05), T(1.02), 1, 0, 1);
  for_exact_methods<T>([&](Method m) {
    const Result<T> r = penetrate(m, a, b, query<T>(Level::Contact, 0b110, 0b011));
    expect_up(r, T(0.05));
    EXPECT_EQ(r.feature_a.index, 0);
  });
}

// Methods without the rule answer as if every axis were allowed.
TEST(InternalEdgeMasksRegistry, OnlyTheExactMethodsHonourIt) {
  for (const MethodInfo& row : method_table) {
    EXPECT_EQ(row.internal_edges(), row.method == Method::Dyop || row.method == Method::Sat)
        << row.name;
  }
}

}  // namespace
}  // namespace dyop
