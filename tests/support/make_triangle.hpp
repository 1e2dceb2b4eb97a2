#pragma once
// Test support: a triangle from six coordinates that the test asserts to be valid.

#include <gtest/gtest.h>

#include "dyop/triangle.hpp"

namespace dyop::test_support {

template <class T>
Triangle<T> tri(T x0, T y0, T x1, T y1, T x2, T y2) {
  auto t = Triangle<T>::make(Vec2<T>(x0, y0), Vec2<T>(x1, y1), Vec2<T>(x2, y2));
  EXPECT_TRUE(t.ok()) << describe(t.error);
  return t.triangle;
}

}  // namespace dyop::test_support
