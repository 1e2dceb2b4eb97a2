#include "dyop/polygon.hpp"

#include <algorithm>
#include <cmath>

#include "detail/validated_size.hpp"

namespace dyop {

const char* describe(ConvexError e) {
  switch (e) {
    case ConvexError::None:
      return "valid shape";
    case ConvexError::VertexCount:
      return "vertex count outside 3..8 (max_polygon_vertices)";
    case ConvexError::NonFinite:
      return "non-finite coordinate or radius (NaN or infinity)";
    case ConvexError::TooLarge:
      return "coordinate or radius too large (beyond max_coordinate: squares would overflow)";
    case ConvexError::TooSmall:
      return "shape too small (longest edge or radius below min_size: squares would underflow)";
    case ConvexError::RepeatedVertex:
      return "repeated vertex (two consecutive vertices are equal)";
    case ConvexError::NotConvex:
      return "not strictly convex (a vertex on or outside another edge's line: reflex, collinear "
             "or self-intersecting)";
  }
  return "unknown shape error";
}

namespace {

template <class T>
ConvexError check_coordinates(const Vec2<T>* points, int count) {
  bool finite = true;
  T largest = 0;
  for (int i = 0; i < count; ++i) {
    for (const T x : {points[i].x(), points[i].y()}) {
      finite = finite && std::isfinite(x);
      largest = std::max(largest, std::abs(x));
    }
  }
  if (!finite) return ConvexError::NonFinite;
  if (largest > max_coordinate<T>()) return ConvexError::TooLarge;
  return ConvexError::None;
}

}  // namespace

template <class T>
ConvexError Polygon<T>::check(const Vec2<T>* points, int count) {
  if (count < 3 || count > max_polygon_vertices) return ConvexError::VertexCount;
  if (const ConvexError e = check_coordinates(points, count); e != ConvexError::None) return e;
  T longest_sq = 0;
  for (int i = 0; i < count; ++i) {
    const Vec2<T>& p = points[i];
    const Vec2<T>& q = points[i + 1 < count ? i + 1 : 0];
    if (p == q) return ConvexError::RepeatedVertex;
    longest_sq = std::max(longest_sq, Vec2<T>(q - p).squaredNorm());
  }
  if (!(longest_sq >= min_size<T>() * min_size<T>())) return ConvexError::TooSmall;
  // Strictly convex in one winding: every vertex off every edge line it is not on, on the same
  // side, by more than the flatness tolerance of `Triangle` (the orientation test's rounding is
  // the same). All n·(n − 2) tests: a star polygon turns the same way at every vertex and is
  // caught only by vertices beyond a far edge's line.
  const T side = cross(Vec2<T>(points[1] - points[0]), Vec2<T>(points[2] - points[0])) < 0 ? -1 : 1;
  const T least = degenerate_tolerance<T>() * longest_sq;
  for (int i = 0; i < count; ++i) {
    const Vec2<T>& p = points[i];
    const Vec2<T> edge = points[i + 1 < count ? i + 1 : 0] - p;
    for (int k = 0; k < count; ++k) {
      if (k == i || k == (i + 1) % count) continue;
      if (!(side * cross(edge, Vec2<T>(points[k] - p)) > least)) return ConvexError::NotConvex;
    }
  }
  return ConvexError::None;
}

template <class T>
PolygonOrError<T> Polygon<T>::make(const Vec2<T>* points, int count) {
  PolygonOrError<T> out;
  out.error = check(points, count);
  if (out.error != ConvexError::None) return out;
  Polygon<T>& p = out.polygon;
  p.count_ = count;
  p.flipped_ = cross(Vec2<T>(points[1] - points[0]), Vec2<T>(points[2] - points[0])) < 0;
  for (int i = 0; i < count; ++i) p.v_[i] = points[p.input_vertex(i)];
  for (int i = 0; i < count; ++i) {
    const Vec2<T> e = p.v_[p.next(i)] - p.v_[i];
    const T length = e.norm();
    p.n_[i] = right_perp(e) / length;
    p.size_ = std::max(p.size_, length);
  }
  return out;
}

template <class T>
Polygon<T> Polygon<T>::from_triangle(const Triangle<T>& t) {
  Polygon<T> p;
  p.count_ = 3;
  p.flipped_ = t.flipped();
  for (int i = 0; i < 3; ++i) {
    p.v_[i] = t.vertex(i);
    p.n_[i] = t.normal(i);
  }
  p.size_ = t.size();
  return p;
}

template <class T>
Polygon<T> Polygon<T>::from_validated(const Vec2<T>* ccw, const Vec2<T>* normals, int count) {
  Polygon<T> p;
  p.count_ = count;
  for (int i = 0; i < count; ++i) {
    p.v_[i] = ccw[i];
    p.n_[i] = normals[i];
  }
  p.size_ = detail::validated_size<T>(
      count, [&](int i) { return ccw[i]; }, [&](int i) { return normals[i]; });
  return p;
}

template <class T>
Polygon<T> Polygon<T>::from_validated(const Vec2<T>* ccw, const Vec2<T>* normals, int count, T c,
                                      T s, const Vec2<T>& translation) {
  Polygon<T> p = from_validated(ccw, normals, count);
  for (int i = 0; i < count; ++i) {
    const Vec2<T>& v = ccw[i];
    const Vec2<T>& n = normals[i];
    p.v_[i] = Vec2<T>(c * v.x() - s * v.y(), s * v.x() + c * v.y()) + translation;
    p.n_[i] = Vec2<T>(c * n.x() - s * n.y(), s * n.x() + c * n.y());
  }
  return p;
}

template <class T>
ConvexError Segment<T>::check(const Vec2<T>& p0, const Vec2<T>& p1) {
  const Vec2<T> both[2] = {p0, p1};
  if (const ConvexError e = check_coordinates(both, 2); e != ConvexError::None) return e;
  if (p0 == p1) return ConvexError::RepeatedVertex;
  if (!(Vec2<T>(p1 - p0).squaredNorm() >= min_size<T>() * min_size<T>())) {
    return ConvexError::TooSmall;
  }
  return ConvexError::None;
}

template <class T>
SegmentOrError<T> Segment<T>::make(const Vec2<T>& p0, const Vec2<T>& p1) {
  SegmentOrError<T> out;
  out.error = check(p0, p1);
  if (out.error != ConvexError::None) return out;
  Segment<T>& s = out.segment;
  s.v_ = {p0, p1};
  const Vec2<T> e = p1 - p0;
  s.size_ = e.norm();
  s.n_[0] = right_perp(e) / s.size_;
  s.n_[1] = -s.n_[0];
  return out;
}

template <class T>
ConvexError Circle<T>::check(const Vec2<T>& center, T radius) {
  const Vec2<T> both[2] = {center, Vec2<T>(radius, 0)};
  if (const ConvexError e = check_coordinates(both, 2); e != ConvexError::None) return e;
  if (!(radius >= min_size<T>())) return ConvexError::TooSmall;
  return ConvexError::None;
}

template class Segment<float>;
template class Segment<double>;
template class Polygon<float>;
template class Polygon<double>;
template struct Circle<float>;
template struct Circle<double>;

}  // namespace dyop
