// The registry of the library's methods (dyop/method.hpp): every tool lists methods from it, so
// each row must be callable the way it says and spelt once.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "dyop/method.hpp"
#include "support/make_triangle.hpp"

namespace dyop {
namespace {

using test_support::tri;

TEST(MethodRegistry, EveryNameIsUniqueAndParsesBackToItsMethod) {
  std::set<std::string> spellings;
  for (const MethodInfo& row : method_table) {
    EXPECT_TRUE(spellings.insert(row.name).second) << row.name;
    EXPECT_EQ(parse_method(row.name), row.method);
    EXPECT_STREQ(name(row.method), row.name);
  }
  EXPECT_FALSE(parse_method("lin-canny-warm").has_value());
  EXPECT_FALSE(parse_method("").has_value());
  // A filter keeps the rows it names; an engine's own narrow phase is no method of the library.
  EXPECT_EQ(parse_method("sat", [](const MethodInfo& r) { return r.simulation(); }), Method::Sat);
  EXPECT_FALSE(parse_method("dyop-paper", [](const MethodInfo& r) { return r.simulation(); }));
  EXPECT_FALSE(parse_method("box2d").has_value());
}

TEST(MethodRegistry, PerPairRowsHaveTheirEntryPointsAndTheOthersNone) {
  for (const MethodInfo& row : method_table) {
    const bool per_pair = row.entry == Entry::PerPair;
    EXPECT_EQ(row.run_float != nullptr, per_pair) << row.name;
    EXPECT_EQ(row.run_double != nullptr, per_pair && row.runs_double()) << row.name;
    EXPECT_NE(row.levels, 0) << row.name;
  }
  EXPECT_EQ(pair_methods.size(), 6u);
  for (Method m : pair_methods) EXPECT_EQ(info(m).entry, Entry::PerPair);
}

TEST(MethodRegistry, EveryPerPairRowAnswersThroughPenetrateAsItsOwnFunction) {
  const Triangle<double> a = tri(0.0, 0.0, 2.0, 0.0, 0.0, 2.0);
  const Triangle<double> b = tri(0.5, 0.5, 3.0, 0.5, 0.5, 3.0);
  for (Method m : pair_methods) {
    const Result<double> via_registry = penetrate(m, a, b);
    const Result<double> direct = info(m).run<double>()(a, b, Query<double>{}, nullptr);
    EXPECT_EQ(via_registry.status, Status::Penetrating) << name(m);
    EXPECT_EQ(via_registry.separation, direct.separation) << name(m);
  }
}

TEST(MethodRegistry, PenetrateRefusesMethodsThatAnswerNoSinglePair) {
  const Triangle<float> a = tri(0.0f, 0.0f, 2.0f, 0.0f, 0.0f, 2.0f);
  const Result<float> r = penetrate(Method::Batch, a, a);
  EXPECT_EQ(r.status, Status::Invalid);
  EXPECT_EQ(r.reason, InvalidReason::NotPairMethod);
}

TEST(MethodRegistry, ExactAndToleranceMethodsAreTheInvariantOnes) {
  EXPECT_TRUE(info(Method::Dyop).invariant());
  EXPECT_TRUE(info(Method::Sat).invariant());
  EXPECT_TRUE(info(Method::Batch).invariant());
  EXPECT_TRUE(info(Method::Epa).invariant());
  EXPECT_FALSE(info(Method::LinCanny).invariant());
  EXPECT_FALSE(info(Method::DyopFast).invariant());
}

}  // namespace
}  // namespace dyop
