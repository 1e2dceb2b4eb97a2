#pragma once
/// \file
/// The 2D vector type of the library and the two products everything else is built from.
///
/// Units: lengths are in the caller's units (metres in Box2D worlds); the library never
/// assumes a scale. Scalar `T` is `float` or `double` throughout.

#include <Eigen/Core>

namespace dyop {

/// A point or a direction in the plane.
template <class T>
using Vec2 = Eigen::Matrix<T, 2, 1>;

/// z-component of the 3D cross product: positive when `b` is counter-clockwise from `a`.
template <class T>
inline T cross(const Vec2<T>& a, const Vec2<T>& b) {
  return a.x() * b.y() - a.y() * b.x();
}

/// `v` turned clockwise by 90°: the outward normal direction of a counter-clockwise edge `v`.
template <class T>
inline Vec2<T> right_perp(const Vec2<T>& v) {
  return Vec2<T>(v.y(), -v.x());
}

/// `v` turned counter-clockwise by the angle whose cosine and sine are `c` and `s` (c² + s² = 1).
template <class T>
inline Vec2<T> rotated(const Vec2<T>& v, T c, T s) {
  return Vec2<T>(c * v.x() - s * v.y(), s * v.x() + c * v.y());
}

}  // namespace dyop
