#pragma once
/// \file
/// A disk as the caller gives it (not yet validated): what the convex input classes make for the
/// polygon–circle pairs and the exact reference reads.

#include "dyop/polygon.hpp"
#include "workloads/raw_pair.hpp"

namespace dyop::workloads {

/// A disk: centre (world coordinates) and radius.
struct RawCircle {
  Vec2<double> center = Vec2<double>::Zero();  ///< world coordinates
  double radius = 0;                           ///< length units
};

/// `c` in precision T (`valid_in<T>` says whether it is usable there).
template <class T>
Circle<T> build(const RawCircle& c) {
  return Circle<T>{Vec2<T>(T(c.center.x()), T(c.center.y())), T(c.radius)};
}

/// True when `Circle<T>::check` accepts `c`.
template <class T>
bool valid_in(const RawCircle& c) {
  const Circle<T> built = build<T>(c);
  return Circle<T>::check(built.center, built.radius) == ConvexError::None;
}

/// `c` with its centre and radius rounded to `precision`.
inline RawCircle rounded_to(Precision precision, const RawCircle& c) {
  return {rounded_to(precision, c.center), rounded_to(precision, c.radius)};
}

}  // namespace dyop::workloads
