// The internal-edge rule in the solver (`Query::internal_edges`), in one place: the depth along
// the directions a triangulated body's outline allows, with the exact methods (`dyop`, `sat`), on
// cases worked by hand; and the rule's kernel (`allowed_axes`): the axes it lets answer are the
// ones the rule's definition names, axis by axis, and its vector form gives its generic form's
// bits. (The masks a set of triangles gets, and the rule in worlds: tests/box2d_bridge/.)
//
// The hand-worked ground is the top row of a triangulated strip whose top is y = 0: cell
// [1, 2] × [-1, 0] split along its diagonal, upper-left triangle A = (1,0) (1,-1) (2,0). Its edge
// 0 (x = 1, shared with the cell on the left) and edge 1 (the diagonal) are internal; edge 2 is
// the top. Its vertices 0 and 2 lie on the flat top, each touching the top edge: flat vertices.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <limits>
#include <vector>

#include "detail/allowed_axes.hpp"
#include "dyop/method.hpp"
#include "exact_reference/exact_reference.hpp"
#include "workloads/input_classes.hpp"
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

// B's bottom (0.9, -0.01)–(1.4, -0.01) lies flat on A's top across A's closed vertex (1, 0), as
// the bottom of a body of several triangles on a flat ground: B's vertex 0 is closed (the middle
// of its body's bottom), its diagonal internal. Along A's top both of B's bottom vertices are the
// deepest, and the first is closed: the flat outline edge between them keeps the axis (before, no
// axis was usable and the pair lost its support: no manifold points). With B's bottom internal as
// well, nothing keeps it.
TYPED_TEST(InternalEdgeMasks, OutlineEdgeLyingFlatAtAClosedVertexKeepsItsAxis) {
  using T = TypeParam;
  const auto a = ground<T>();
  const auto b = tri<T>(T(0.9), T(-0.01), T(1.4), T(-0.01), T(1.4), T(0.5));
  const std::uint8_t b_diagonal = 1 << (3 + 2);
  const std::uint8_t b_bottom = 1 << 3;
  const std::uint8_t b_vertex0 = 1 << 3;
  for_exact_methods<T>([&](Method m) {
    const Result<T> r = penetrate(
        m, a, b, query<T>(Level::Manifold, ground_edges | b_diagonal, ground_vertices | b_vertex0));
    expect_up(r, T(0.01));
    EXPECT_EQ(r.manifold.point_count, 2);
    const Result<T> inside =
        penetrate(m, a, b,
                  query<T>(Level::Manifold, ground_edges | b_diagonal | b_bottom,
                           ground_vertices | b_vertex0));
    EXPECT_EQ(inside.manifold.point_count, 0) << "an internal bottom keeps nothing";
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

// --- The rule's kernel ----------------------------------------------------------------------

namespace dyop::workloads {
namespace {

// The rule as its definition reads, one axis at a time (`allowed_axes`'s head): allowed by the
// masks (`axis_allowed`), touched (the other triangle reaches the edge segment within `reach`:
// separating-axis test of the segment and the triangle), usable = both, unless one triangle
// reaches no edge of the other (then allowed alone); the least usable overlap of each triangle.
template <class T>
bool touched_by_definition(const detail::PairFrame<T>& f, int k, T reach) {
  const bool own_is_a = k < 3;
  const int i = own_is_a ? k : k - 3;
  const auto& own = own_is_a ? f.a : f.b;
  const auto& other = own_is_a ? f.b : f.a;
  const Triangle<T>& own_t = own_is_a ? f.ta : f.tb;
  const Triangle<T>& other_t = own_is_a ? f.tb : f.ta;
  const Vec2<T>& n = own_t.normal(i);
  const T line = n.dot(own[i]);
  T outside = -std::numeric_limits<T>::infinity();
  for (int w = 0; w < 3; ++w) outside = std::max(outside, n.dot(other[w]) - line);
  if (outside < -reach) return false;
  for (int j = 0; j < 3; ++j) {
    const Vec2<T>& m = other_t.normal(j);
    const T other_line = m.dot(other[j]);
    const T p = m.dot(own[i]) - other_line;
    const T q = m.dot(own[detail::next3(i)]) - other_line;
    if (std::min(p, q) > reach) return false;
  }
  return true;
}

template <class T>
void expect_rule_as_defined(const detail::PairFrame<T>& f, const Query<T>& q) {
  const std::array<T, 6> overlap = detail::all_overlaps(f);
  const detail::AllowedAxes<T> got = detail::allowed_axes(f, q, overlap);
  const T reach = q.margin + detail::touching_band(f);
  bool allowed[6];
  bool touched[6];
  for (int k = 0; k < 6; ++k) {
    allowed[k] = detail::axis_allowed(f, q, k);
    touched[k] = touched_by_definition(f, k, reach);
  }
  const bool a_reached = touched[0] || touched[1] || touched[2];
  const bool b_reached = touched[3] || touched[4] || touched[5];
  int best[2] = {-1, -1};
  for (int k = 0; k < 6; ++k) {
    const bool usable = allowed[k] && (!(a_reached && b_reached) || touched[k]);
    int& b = best[k / 3];
    if (usable && (b < 0 || overlap[k] < overlap[b])) b = k;
  }
  EXPECT_EQ(got.best_a, best[0]);
  EXPECT_EQ(got.best_b, best[1]);
}

// Every edge mask and closed-vertex mask over pairs of every test class, both precisions.
TEST(InternalEdgesRule, TheKernelLetsAnswerTheAxesTheRuleNames) {
  int pairs = 0;
  for (InputClass c : test_classes) {
    for (const RawPair& p : make_valid_pairs(c, 40, 71)) {
      const auto d = build<double>(p);
      const auto f = build<float>(p);
      const double margin = 0.05 * pair_size(p);
      for (unsigned edges = 0; edges < 64; edges += 5) {
        for (unsigned closed = 0; closed < 64; closed += 9) {
          const InternalEdges masks{static_cast<std::uint8_t>(edges),
                                    static_cast<std::uint8_t>(closed)};
          Query<double> qd{Level::Manifold, margin, 0, Apart::Gap};
          qd.internal_edges = masks;
          expect_rule_as_defined(detail::PairFrame<double>(d.a.triangle, d.b.triangle), qd);
          if (!f.a.ok() || !f.b.ok()) continue;
          Query<float> qf{Level::Manifold, float(margin), 0, Apart::Gap};
          qf.internal_edges = masks;
          expect_rule_as_defined(detail::PairFrame<float>(f.a.triangle, f.b.triangle), qf);
          ++pairs;
        }
      }
      if (HasFailure()) return;
    }
  }
  EXPECT_GT(pairs, 10000);
}

// The float kernel in SSE registers against the generic one, bit for bit, over reaches from 0
// to past the pair's size (where every bit flips at least once), every closed-vertex and
// internal-edge mask of the other triangle.
TEST(InternalEdgesRule, TheVectorKernelGivesTheGenericKernelsBits) {
  int compared = 0;
  for (InputClass c : test_classes) {
    for (const RawPair& p : make_valid_pairs(c, 60, 72)) {
      const auto f = build<float>(p);
      if (!f.a.ok() || !f.b.ok()) continue;
      const detail::PairFrame<float> frame(f.a.triangle, f.b.triangle);
      for (float reach : {0.0f, 1e-3f, 0.05f, 0.3f, 1.0f, 4.0f}) {
        reach *= float(pair_size(p));
        for (unsigned internal = 0; internal < 8; ++internal) {
          for (unsigned closed = 0; closed < 8; ++closed) {
            for (unsigned other_internal = 0; other_internal < 8; other_internal += 3) {
              const detail::EdgeBits generic = detail::edge_bits<float>(
                  frame.ta, frame.a, frame.b, internal, closed, other_internal, reach);
              const detail::EdgeBits vector = detail::edge_bits(
                  frame.ta, frame.a, frame.b, internal, closed, other_internal, reach);
              ASSERT_EQ(vector.allowed, generic.allowed);
              ASSERT_EQ(vector.wholly_inside, generic.wholly_inside);
              ASSERT_EQ(vector.cut_other, generic.cut_other);
              ++compared;
            }
          }
        }
      }
    }
  }
  EXPECT_GT(compared, 10000);
}

}  // namespace
}  // namespace dyop::workloads
