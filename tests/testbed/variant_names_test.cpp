// The testbed's spellings of the ways it runs the registry's methods (adapters/variant.hpp): a
// warm-startable method's two runs are told apart in every table, the others keep their name.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "adapters/variant.hpp"
#include "dyop/method.hpp"

namespace dyop::adapters {
namespace {

TEST(MethodRegistry, VariantNamesSayColdOrWarmOnlyForWarmStartableMethods) {
  EXPECT_STREQ(variant_name(Method::LinCanny, false), "lin-canny-cold");
  EXPECT_STREQ(variant_name(Method::LinCanny, true), "lin-canny-warm");
  for (const MethodInfo& row : method_table) {
    if (row.warm_start()) continue;
    EXPECT_STREQ(variant_name(row.method, false), row.name);
    EXPECT_STREQ(variant_name(row.method, true), row.name);
  }
}

TEST(MethodRegistry, EveryWarmStartableMethodHasTwoSpellingsOfItsOwn) {
  std::set<std::string> spellings;
  for (const MethodInfo& row : method_table) EXPECT_TRUE(spellings.insert(row.name).second);
  int spelt = 0;
  for (const WarmStartSpelling& row : warm_start_spellings) {
    EXPECT_TRUE(info(row.method).warm_start()) << name(row.method);
    EXPECT_TRUE(spellings.insert(row.cold).second) << row.cold;
    EXPECT_TRUE(spellings.insert(row.warm).second) << row.warm;
    ++spelt;
  }
  int warm_startable = 0;
  for (const MethodInfo& row : method_table) warm_startable += row.warm_start() ? 1 : 0;
  EXPECT_EQ(spelt, warm_startable);
  EXPECT_EQ(variants([](const MethodInfo&) { return true; }).size(),
            static_cast<std::size_t>(method_count + warm_startable));
}

}  // namespace
}  // namespace dyop::adapters
