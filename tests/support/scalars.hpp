#pragma once
// Test support: the two precisions every typed suite runs in, named "float" and "double" in the
// test names (and given explicitly, which clang's -Wpedantic asks of TYPED_TEST_SUITE).

#include <gtest/gtest.h>

#include <string>
#include <type_traits>

namespace dyop::test_support {

using Scalars = ::testing::Types<float, double>;

struct ScalarNames {
  template <class T>
  static std::string GetName(int) {
    return std::is_same_v<T, float> ? "float" : "double";
  }
};

}  // namespace dyop::test_support
