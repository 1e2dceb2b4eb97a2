// The paper's equations taken literally, pinned to its Figure 6, and made harmless on bad input.
#include <gtest/gtest.h>

#include <cmath>

#include "dyop/dyop_paper.hpp"
#include "workloads/input_classes.hpp"

namespace dyop::workloads {
namespace {

using V = Vec2<double>;

// Figure 6 prints 6 significant digits: a printed value is within half a unit of its last digit.
constexpr double half_unit(double printed_last_digit) { return 0.5 * printed_last_digit; }

TEST(DyopPaper, ReproducesFigure6TrueDistanceAndEquation8Value) {
  // Edge PQ with M = 1.33333, C = -2.6 (P = (3, 1.4), Q = (0, -2.6)); the vertex on the y axis
  // at C_i = C - |ΔC| with the printed |ΔC| = 0.0966835 (C_i is printed rounded as -2.69668).
  const V p(3, 1.4), q(0, -2.6);
  const V x(0, -2.6 - 0.0966835);
  const PaperLinesOrError<double> out = paper_lines(p, q, x);
  ASSERT_EQ(out.reason, InvalidReason::None);
  EXPECT_NEAR(out.lines.m, 1.33333, half_unit(1e-5));
  EXPECT_NEAR(out.lines.c, -2.6, half_unit(1e-6));
  EXPECT_NEAR(out.lines.c_vertex, -2.69668, half_unit(1e-5));
  EXPECT_NEAR(std::abs(out.lines.c_vertex - out.lines.c), 0.0966835, half_unit(1e-7));
  // "The Shortest Distance": |ΔC| / sqrt(1 + M²), the correct line distance.
  EXPECT_NEAR(out.lines.true_distance, 0.0580101, half_unit(1e-7));
  // The printed "penetration depth": eq. 8's |ΔC| / sqrt(X_P² + Y_P²).
  EXPECT_NEAR(out.lines.depth_eq8, 0.0292043, half_unit(1e-7));
}

TEST(DyopPaper, ReproducesFigure6HorizontalCaseOfEquation7) {
  // mvalueObjA 0, cvalueObjA -0.950001, newparamcvalueObjA 1.4: eq. 7 gives C - C_i = -2.35.
  const PaperLinesOrError<double> out = paper_lines(V(1, -0.950001), V(4, -0.950001), V(2, 1.4));
  ASSERT_EQ(out.reason, InvalidReason::None);
  EXPECT_EQ(out.lines.m, 0);
  EXPECT_NEAR(out.lines.depth_eq8, -2.35, half_unit(1e-2));
}

TEST(DyopPaper, VerticalEdgeIsInvalidWithAReasonNotInfinity) {
  const PaperLinesOrError<double> out = paper_lines(V(1, 0), V(1, 3), V(0, 0));
  ASSERT_NE(out.reason, InvalidReason::None);
  EXPECT_NE(std::string(describe(out.reason)).find("vertical"), std::string::npos);
  EXPECT_EQ(out.lines.depth_eq8, 0);
}

TEST(DyopPaper, EdgeThroughTheOriginMakesEquation8DivideByZeroSoItIsInvalid) {
  const PaperLinesOrError<double> out = paper_lines(V(0, 0), V(1, 1), V(0, 1));
  ASSERT_NE(out.reason, InvalidReason::None);
}

TEST(DyopPaper, EquationEightDependsOnWhereTheOriginIs) {
  // The same geometry moved by 10: the true distance stays, eq. 8's value does not.
  const PaperLinesOrError<double> here = paper_lines(V(3, 1.4), V(0, -2.6), V(0, -2.69668));
  const V d(10, 10);
  const PaperLinesOrError<double> there =
      paper_lines(V(V(3, 1.4) + d), V(V(0, -2.6) + d), V(V(0, -2.69668) + d));
  EXPECT_NEAR(here.lines.true_distance, there.lines.true_distance, 1e-12);
  EXPECT_GT(std::abs(here.lines.depth_eq8 - there.lines.depth_eq8), 1e-3);
}

TEST(DyopPaper, EveryPairGetsFiniteNumbersOrAReason) {
  for (InputClass c : test_classes) {
    for (const RawPair& p : make_valid_pairs(c, 1000, 3)) {
      const auto t = build<double>(p);
      const Result<double> r = dyop_paper(t.a.triangle, t.b.triangle, {Level::Manifold});
      if (r.status == Status::Invalid) {
        EXPECT_NE(r.reason, InvalidReason::None);
        continue;
      }
      EXPECT_TRUE(std::isfinite(r.separation) && std::isfinite(r.depth)) << name(c);
      EXPECT_TRUE(r.normal.allFinite() && r.witness_a.allFinite()) << name(c);
      EXPECT_GE(r.depth, 0);
    }
  }
}

}  // namespace
}  // namespace dyop::workloads
