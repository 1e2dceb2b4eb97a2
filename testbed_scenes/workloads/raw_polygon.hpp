#pragma once
/// \file
/// A convex polygon as the caller gives it (world coordinates, any winding, not yet validated):
/// what the convex input classes make, the exact reference reads and `Polygon<T>::make` is given.

#include <array>

#include "dyop/polygon.hpp"
#include "workloads/raw_pair.hpp"

namespace dyop::workloads {

/// 3 to `max_polygon_vertices` vertices as the caller gives them: world coordinates, any winding;
/// or 2, a segment (`Segment`: from `v[0]` to `v[1]`, its front to the right of that direction).
struct RawPolygon {
  /// The first `count` are the vertices; the rest are zero (Eigen leaves a vector it is not
  /// given uninitialised).
  std::array<Vec2<double>, max_polygon_vertices> v = zeros();
  int count = 0;  ///< number of vertices

  /// Every vertex at the origin.
  static std::array<Vec2<double>, max_polygon_vertices> zeros() {
    std::array<Vec2<double>, max_polygon_vertices> z;
    z.fill(Vec2<double>::Zero());
    return z;
  }

  /// The triangle `t` as a polygon: the same vertices in the same order.
  static RawPolygon from_triangle(const std::array<Vec2<double>, 3>& t) {
    RawPolygon p;
    for (int i = 0; i < 3; ++i) p.v[static_cast<std::size_t>(i)] = t[static_cast<std::size_t>(i)];
    p.count = 3;
    return p;
  }
};

/// `p`'s vertices in precision T, in the caller's order.
template <class T>
std::array<Vec2<T>, max_polygon_vertices> vertices_in(const RawPolygon& p) {
  std::array<Vec2<T>, max_polygon_vertices> out{};
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = Vec2<T>(T(p.v[i].x()), T(p.v[i].y()));
  return out;
}

/// `p` validated in precision T (`ok()` says whether it is a usable polygon there).
template <class T>
PolygonOrError<T> build(const RawPolygon& p) {
  const auto v = vertices_in<T>(p);
  return Polygon<T>::make(v.data(), p.count);
}

/// `p`, of 2 vertices, validated as a segment in precision T.
template <class T>
SegmentOrError<T> build_segment(const RawPolygon& p) {
  const auto v = vertices_in<T>(p);
  return Segment<T>::make(v[0], v[1]);
}

/// True when `Polygon<T>::make` accepts `p` (`Segment<T>::make`, for 2 vertices).
template <class T>
bool valid_in(const RawPolygon& p) {
  const auto v = vertices_in<T>(p);
  if (p.count == 2) return Segment<T>::check(v[0], v[1]) == ConvexError::None;
  return Polygon<T>::check(v.data(), p.count) == ConvexError::None;
}

/// `p` with every vertex rounded to `precision`.
inline RawPolygon rounded_to(Precision precision, const RawPolygon& p) {
  RawPolygon out = p;
  for (Vec2<double>& v : out.v) v = rounded_to(precision, v);
  return out;
}

/// `p` with its vertices in the reverse order (vertex 0 kept first): the same polygon in the
/// other winding, caller's vertex i of `p` being vertex (count − i) % count of the result.
inline RawPolygon reversed(const RawPolygon& p) {
  RawPolygon out = p;
  for (int i = 1; i < p.count; ++i) {
    out.v[static_cast<std::size_t>(i)] = p.v[static_cast<std::size_t>(p.count - i)];
  }
  return out;
}

}  // namespace dyop::workloads
