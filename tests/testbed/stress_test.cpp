// `dyop stress` on a moderate number of pairs per category: the "done when" asserted,
// the figures recorded as test properties (`--gtest_output=xml:FILE` shows them).
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "dyop/method.hpp"
#include "exact_reference/exact_reference.hpp"
#include "workloads/input_classes.hpp"
#include "experiments/stress.hpp"
#include "experiments/stress_convex.hpp"

namespace dyop::experiments {
namespace {

using workloads::InputClass;
using workloads::Precision;
using workloads::RawPair;

// "method precision class", for failure messages and recorded figures.
std::string what(const StressRecord& r) {
  return std::string(adapters::name(r.method)) + " " + workloads::name(r.precision) + " " +
         workloads::name(r.cls);
}

constexpr int kPairs = 400;  // per category and precision: about a second in Release

class StressPromises : public ::testing::TestWithParam<Precision> {
 protected:
  // One run per precision, shared by the tests of the suite.
  static const std::vector<StressRecord>& records(Precision p) {
    static std::vector<StressRecord> cache[2];
    std::vector<StressRecord>& r = cache[p == Precision::Float];
    if (r.empty()) {
      StressOptions o;
      o.pairs = kPairs;
      o.run_double = p == Precision::Double;
      o.run_float = p == Precision::Float;
      std::ostringstream progress;
      r = run_stress(o, progress);
      for (const StressRecord& x : r) {
        ::testing::Test::RecordProperty(
            what(x), "max " + std::to_string(x.err_max) + ", p99 " + std::to_string(x.err_p99) +
                         ", nonfinite " + std::to_string(x.nonfinite) + ", misclassified " +
                         std::to_string(x.misclassified) + ", rejected " +
                         std::to_string(x.rejected));
      }
    }
    return r;
  }
};

TEST_P(StressPromises, SatDyopAndBatchAreExactInEveryCategory) {
  const double bound = exact_bound(GetParam());
  for (const StressRecord& r : records(GetParam())) {
    if (!promises_exact(r.method)) continue;
    EXPECT_LE(r.err_max, bound) << what(r) << ", worst pair " << r.worst_pair;
    EXPECT_EQ(r.misclassified, 0) << what(r);
    EXPECT_EQ(r.invalid, 0) << what(r);
  }
}

TEST_P(StressPromises, NoMethodGivesNaNOrInfOnValidInput) {
  for (const StressRecord& r : records(GetParam())) {
    // Box2D's own code is measured, not promised: see docs/measurements.md, "Stress: hostile
    // input".
    if (r.method == adapters::NarrowPhase::box2d()) continue;
    EXPECT_EQ(r.nonfinite, 0) << what(r);
  }
}

TEST_P(StressPromises, OnlyDyopPaperAnswersInvalidAndOnlyByDesign) {
  for (const StressRecord& r : records(GetParam())) {
    EXPECT_EQ(r.invalid, 0) << what(r);
    if (r.method != adapters::NarrowPhase::of(Method::DyopPaper)) {
      EXPECT_EQ(r.invalid_by_design, 0) << what(r);
    }
  }
}

TEST_P(StressPromises, SatDyopEpaAndBatchAreInvariantUnderMotionReorderingAndSwapping) {
  for (const StressRecord& r : records(GetParam())) {
    if (!promises_invariance(r.method)) continue;
    for (int k = 0; k < invariance_count; ++k) {
      EXPECT_EQ(r.invariance[k], 0) << what(r) << " " << name(static_cast<Invariance>(k));
    }
  }
}

TEST_P(StressPromises, BrokenPromisesListsNothing) {
  std::ostringstream all;
  for (const std::string& b : broken_promises(records(GetParam()))) all << b << '\n';
  EXPECT_EQ(all.str(), "");
}

// Rejections happen only where the category means them to: nearly collinear triangles, and in
// float slivers (below float's flatness tolerance) and the smallest scales (B down to 1e-14, below
// float's min_size); a double never rejects what its generator meant to be valid.
TEST_P(StressPromises, OnlyDegenerateCategoriesHaveRejectedPairs) {
  for (const StressRecord& r : records(GetParam())) {
    const bool may_reject = r.cls == InputClass::NearlyCollinear ||
                            (GetParam() == Precision::Float &&
                             (r.cls == InputClass::Sliver || r.cls == InputClass::Scale));
    if (!may_reject) {
      EXPECT_EQ(r.rejected, 0) << what(r);
    }
    if (r.cls == InputClass::NearlyCollinear) {
      // The category straddles the tolerance: some triangles pass, some are rejected.
      EXPECT_GT(r.rejected, 0);
      EXPECT_LT(r.rejected, r.pairs);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(BothPrecisions, StressPromises,
                         ::testing::Values(Precision::Double, Precision::Float),
                         [](const auto& info) { return std::string(workloads::name(info.param)); });

// The convex part: `dyop::collide` exact, classified, finite and independent of winding on every
// convex class, in both precisions, as `dyop stress --check` promises; its rows are every family
// on every class.
TEST(ConvexStress, EveryPromiseHoldsOnEveryClassAndFamily) {
  StressOptions o;
  o.pairs = kPairs / 2;
  std::ostringstream progress;
  const std::vector<ConvexStressRecord> records = run_convex_stress(o, progress);
  constexpr std::size_t kFamilies = 4;  // polygon and segment against polygon and circle
  EXPECT_EQ(records.size(), 2u * kFamilies * std::size(workloads::convex_classes));
  std::ostringstream all;
  for (const std::string& b : broken_convex_promises(records)) all << b << '\n';
  EXPECT_EQ(all.str(), "");
  for (const ConvexStressRecord& r : records) EXPECT_EQ(r.pairs, o.pairs) << name(r.family);
}

// The categories are what they say, in the precision they are made for.

TEST(StressClasses, FloatPairsAreExactlyRepresentableInFloat) {
  // What the reference sees must be what a float program sees (a compiler that drops the round
  // trip would make every float figure measure input rounding instead).
  for (InputClass c : workloads::stress_classes) {
    for (const RawPair& p : workloads::make_pairs(c, 200, 3, Precision::Float)) {
      for (const auto* t : {&p.a, &p.b}) {
        for (const Vec2<double>& v : *t) {
          ASSERT_EQ(double(float(v.x())), v.x()) << workloads::name(c);
          ASSERT_EQ(double(float(v.y())), v.y()) << workloads::name(c);
        }
      }
    }
  }
}

TEST(StressClasses, TheSameSeedGivesTheSamePairs) {
  for (InputClass c : workloads::stress_classes) {
    const auto x = workloads::make_pairs(c, 50, 11, Precision::Double);
    const auto y = workloads::make_pairs(c, 50, 11, Precision::Double);
    ASSERT_EQ(x.size(), 50u);
    for (std::size_t k = 0; k < x.size(); ++k) {
      EXPECT_EQ(x[k].a, y[k].a);
      EXPECT_EQ(x[k].b, y[k].b);
    }
  }
}

TEST(StressClasses, OffsetsReachButDoNotPassTheirLimit) {
  for (Precision p : {Precision::Double, Precision::Float}) {
    double farthest = 0;
    for (const RawPair& q : workloads::make_pairs(InputClass::Far, 500, 5, p)) {
      farthest = std::max(farthest, q.a[0].norm());
    }
    EXPECT_GT(farthest, 0.5 * workloads::max_offset(p));
    EXPECT_LT(farthest, 1.01 * workloads::max_offset(p) + 10);
  }
}

TEST(StressClasses, TouchingPairsAreWithinAFewUlpsOfTouchingOnBothSides) {
  for (Precision p : {Precision::Double, Precision::Float}) {
    const double eps = p == Precision::Float ? 1.2e-7 : 2.3e-16;
    int in = 0;
    int out = 0;
    for (const RawPair& q : workloads::make_pairs(InputClass::TouchingUlp, 300, 9, p)) {
      const workloads::ExactAnswer e = workloads::exact_separation(q);
      // A few ulps of coordinates up to 1e3 (float: 10) from the origin, for pairs of size ~1.
      const double reach = q.a[0].norm() + 2;
      EXPECT_LE(std::abs(e.separation), 8 * eps * reach) << workloads::name(p);
      in += e.sign < 0;
      out += e.sign > 0;
    }
    EXPECT_GT(in, 0) << workloads::name(p);
    EXPECT_GT(out, 0) << workloads::name(p);
  }
}

TEST(StressClasses, ScalesSpanSixteenOrdersOfMagnitude) {
  double least = INFINITY;
  double most = 0;
  for (const RawPair& q : workloads::make_pairs(InputClass::Scale, 500, 4, Precision::Double)) {
    const double s = workloads::pair_size(q);
    least = std::min(least, s);
    most = std::max(most, s);
  }
  EXPECT_LT(least, 1e-7);
  EXPECT_GT(most, 1e7);
}

}  // namespace
}  // namespace dyop::experiments
