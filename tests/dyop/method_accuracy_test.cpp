// Every method against the exact rational reference, per class of input and per precision: the
// property each method promises is asserted, and its error figures are recorded as test
// properties (`--gtest_output=xml:FILE` shows them).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "dyop/method.hpp"
#include "exact_reference/exact_reference.hpp"
#include "workloads/input_classes.hpp"

namespace dyop::workloads {
namespace {

constexpr int kAccuracyPairsPerClass = 2000;

struct Figures {
  int pairs = 0;
  int invalid = 0;
  int misclassified = 0;  // penetrating vs not, outside the touching band
  double max_error = 0;   // |separation - exact| / pair size, over valid answers
  double sum_error = 0;
  void add(double e) {
    max_error = std::max(max_error, e);
    sum_error += e;
  }
};

template <class T>
Figures measure(Method m, InputClass c, double& worst_depth_below_exact) {
  Figures f;
  worst_depth_below_exact = 0;
  for (const RawPair& raw : make_valid_pairs(c, kAccuracyPairsPerClass, 41)) {
    const RawPair p = std::is_same_v<T, float> ? rounded_to_float(raw) : raw;
    const auto t = build<T>(p);
    if (!t.a.ok() || !t.b.ok()) continue;  // a float-degenerate sliver is rejected, not solved
    ++f.pairs;
    const ExactAnswer exact = exact_separation(p);
    const Result<T> r = penetrate(m, t.a.triangle, t.b.triangle, Query<T>{Level::Depth});
    if (r.status == Status::Invalid) {
      ++f.invalid;
      continue;
    }
    EXPECT_TRUE(std::isfinite(r.separation) && r.normal.allFinite()) << name(m) << name(c);
    const double size = pair_size(p);
    const double band = 4 * touching_tolerance<T>() * size;
    if (std::abs(exact.separation) > band &&
        (exact.sign < 0) != (r.status == Status::Penetrating)) {
      ++f.misclassified;
      continue;
    }
    f.add(std::abs(double(r.separation) - exact.separation) / size);
    if (exact.sign < 0) {
      worst_depth_below_exact =
          std::max(worst_depth_below_exact, (-exact.separation - double(r.depth)) / size);
    }
  }
  return f;
}

std::string describe(const Figures& f) {
  std::ostringstream s;
  s << "pairs " << f.pairs << ", invalid " << f.invalid << ", misclassified " << f.misclassified
    << ", max err/size " << f.max_error << ", mean " << (f.pairs ? f.sum_error / f.pairs : 0);
  return s.str();
}

template <class T>
void check_method(Method m, double exact_tol) {
  for (InputClass c : test_classes) {
    double below = 0;
    const Figures f = measure<T>(m, c, below);
    ::testing::Test::RecordProperty(std::string(name(m)) + "." + name(c), describe(f));
    switch (info(m).accuracy) {
      case Accuracy::Exact:
      case Accuracy::ToTolerance:
        EXPECT_EQ(f.invalid, 0) << name(c);
        EXPECT_EQ(f.misclassified, 0) << name(c);
        EXPECT_LE(f.max_error, exact_tol) << name(m) << " " << name(c);
        break;
      case Accuracy::LocalDepth:
        // Exact distance apart; a local minimum of overlap is never shallower than the true depth.
        EXPECT_EQ(f.invalid, 0) << name(c);
        EXPECT_EQ(f.misclassified, 0) << name(c);
        EXPECT_LE(below, exact_tol) << name(c);
        break;
      case Accuracy::Approximate:
        break;  // heuristics: their figures are the result (finiteness is checked per pair)
    }
  }
}

class MethodAccuracy : public ::testing::TestWithParam<Method> {};

// Double: the exact methods within 1e-12 of the pair's size (the bound); EPA too, since
// on triangles its polytope reaches a Minkowski edge exactly.
TEST_P(MethodAccuracy, DoubleMeetsItsPromiseInEveryClass) {
  check_method<double>(GetParam(), exact_bound(Precision::Double));
}

// Float on float-rounded input: within 1e-5 of the pair's size.
TEST_P(MethodAccuracy, FloatMeetsItsPromiseInEveryClass) {
  check_method<float>(GetParam(), exact_bound(Precision::Float));
}

INSTANTIATE_TEST_SUITE_P(EveryMethod, MethodAccuracy, ::testing::ValuesIn(pair_methods),
                         [](const auto& info) {
                           std::string n = name(info.param);
                           n.erase(std::remove(n.begin(), n.end(), '-'), n.end());
                           return n;
                         });

}  // namespace
}  // namespace dyop::workloads
