// Exact methods against the exact rational reference, per class of input.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "dyop/dyop.hpp"
#include "dyop/sat.hpp"
#include "exact_reference/exact_reference.hpp"
#include "workloads/input_classes.hpp"

namespace dyop::workloads {
namespace {

// The bound: within 1e-12 of the pair's size, in double, wherever the pair is.
constexpr double kExactRelTol = 1e-12;
constexpr int kAgreementPairsPerClass = 10000;  // 10 classes: 100,000 pairs

class ExactAgreement : public ::testing::TestWithParam<InputClass> {};

TEST_P(ExactAgreement, SatAndDyopMatchTheRationalReferenceWithin1e12OfPairSize) {
  const auto pairs = make_valid_pairs(GetParam(), kAgreementPairsPerClass, 7);
  double worst_sat = 0;
  double worst_dyop = 0;
  int signs[3] = {0, 0, 0};  // penetrating, touching, apart
  for (const RawPair& p : pairs) {
    const auto t = build<double>(p);
    ASSERT_TRUE(t.a.ok() && t.b.ok());
    const ExactAnswer exact = exact_separation(p);
    const double size = pair_size(p);
    ++signs[exact.sign + 1];
    const Result<double> s = sat(t.a.triangle, t.b.triangle);
    const Result<double> d = dyop(t.a.triangle, t.b.triangle);
    worst_sat = std::max(worst_sat, std::abs(s.separation - exact.separation) / size);
    worst_dyop = std::max(worst_dyop, std::abs(d.separation - exact.separation) / size);
    // Status: exact sign, except inside the touching band where rounding decides.
    const double band = touching_tolerance<double>() * size;
    if (std::abs(exact.separation) > band) {
      const Status want = exact.sign < 0 ? Status::Penetrating : Status::Separated;
      EXPECT_EQ(s.status, want);
      EXPECT_EQ(d.status, want);
    }
  }
  EXPECT_LE(worst_sat, kExactRelTol) << name(GetParam());
  EXPECT_LE(worst_dyop, kExactRelTol) << name(GetParam());
  std::ostringstream figures;
  figures << name(GetParam()) << ": penetrating " << signs[0] << ", touching " << signs[1]
          << ", apart " << signs[2] << "; max |error|/size sat " << worst_sat << ", dyop "
          << worst_dyop;
  RecordProperty("figures", figures.str());
}

INSTANTIATE_TEST_SUITE_P(EveryClass, ExactAgreement, ::testing::ValuesIn(test_classes),
                         [](const auto& info) {
                           std::string n = name(info.param);
                           for (char& c : n)
                             if (c == '-') c = '_';
                           return n;
                         });

}  // namespace
}  // namespace dyop::workloads
