#pragma once
/// \file
/// A triangle pair as the caller gives it (world coordinates, any winding, not yet validated):
/// what every input class makes, the exact reference reads and the methods are built from.

#include <array>

#include "dyop/triangle.hpp"
#include "workloads/precision.hpp"

namespace dyop::workloads {

/// Two triangles as the caller gives them: world coordinates, any winding.
struct RawPair {
  std::array<Vec2<double>, 3> a;  ///< triangle A
  std::array<Vec2<double>, 3> b;  ///< triangle B
};

/// Both triangles of a pair built in precision T (asserting validity is the caller's job: `ok()`
/// on each).
template <class T>
struct BuiltPair {
  TriangleOrError<T> a;  ///< A, or why it is invalid in T
  TriangleOrError<T> b;  ///< B, or why it is invalid in T
};
template <class T>
BuiltPair<T> build(const RawPair& p) {
  auto cast = [](const Vec2<double>& v) { return Vec2<T>(T(v.x()), T(v.y())); };
  return {Triangle<T>::make(cast(p.a[0]), cast(p.a[1]), cast(p.a[2])),
          Triangle<T>::make(cast(p.b[0]), cast(p.b[1]), cast(p.b[2]))};
}

/// True when both triangles are valid in double.
bool valid_in_double(const RawPair& p);
/// True when the triangle is valid in double.
bool valid_in_double(const std::array<Vec2<double>, 3>& t);

/// The union of both triangles' bounding boxes.
struct PairBox {
  Vec2<double> lo;  ///< lower-left corner
  Vec2<double> hi;  ///< upper-right corner
};
PairBox pair_box(const RawPair& p);

/// The pair's size: the diagonal of `pair_box` (unit of relative errors).
double pair_size(const RawPair& p);

/// `x` rounded to precision `precision` (unchanged for double; for float held exactly in double).
double rounded_to(Precision precision, double x);

/// `v` rounded to precision `precision` (unchanged for double; for float held exactly in double).
Vec2<double> rounded_to(Precision precision, const Vec2<double>& v);

/// `p` with every vertex rounded to precision `precision`, so that the exact reference sees
/// exactly what a program in that precision sees.
RawPair rounded_to(Precision precision, const RawPair& p);

/// `rounded_to(Precision::Float, p)`.
RawPair rounded_to_float(const RawPair& p);

}  // namespace dyop::workloads
