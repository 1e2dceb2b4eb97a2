#pragma once
// Internal: the size of a polygon given with its unit outward normals (`Polygon::size`, the
// longest edge), as every reader of validated data measures it: `Polygon::from_validated`, and the
// Box2D plug-in reading a `b2PolygonShape` in place. Measured along the tangents (the normals
// turned left), with no square root. And a bound on it that costs nothing to read (`size_bound`).

#include <algorithm>

#include "dyop/vec2.hpp"

namespace dyop::detail {

// `vertex(i)` and `normal(i)`: CCW vertex i and the unit outward normal of edge i (i to i + 1).
template <class T, class Vertex, class Normal>
inline T validated_size(int count, const Vertex& vertex, const Normal& normal) {
  T size = 0;
  for (int i = 0; i < count; ++i) {
    const Vec2<T> n = normal(i);
    const T length = Vec2<T>(-n.y(), n.x()).dot(vertex(i + 1 < count ? i + 1 : 0) - vertex(i));
    size = std::max(size, length);
  }
  return size;
}

// At least polygon-like `p`'s `size()`, free to read: `p.size_bound()` where its type measures its
// size only when asked (the Box2D plug-in's shapes read in place), else `p.size()` itself.
template <class P>
inline auto size_bound(const P& p) -> decltype(p.size_bound()) {
  return p.size_bound();
}
template <class P, class... None>
inline auto size_bound(const P& p, None...) -> decltype(p.size()) {
  return p.size();
}

}  // namespace dyop::detail
