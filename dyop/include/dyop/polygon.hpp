#pragma once
/// \file
/// Validated convex shapes beyond the triangle: `Polygon` (3 to `max_polygon_vertices` vertices,
/// every polygon a Box2D 2.4 `b2PolygonShape` can hold, `SetAsBox` included), `Circle` and
/// `Segment` (a Box2D edge, or one edge of a chain). The input types of `collide`
/// (`dyop/convex_pair.hpp`).
///
/// Conventions (as for `Triangle`, `dyop/triangle.hpp`):
/// - Vertices are given in world coordinates, in any winding. The polygon stores them
///   counter-clockwise (CCW); `input_vertex` / `input_edge` map a CCW index back to the caller's
///   order, and every feature index a result reports is already in the caller's order.
/// - Edge `i` runs from vertex `i` to vertex `(i + 1) % count` (in whichever order is spoken of).
/// - Normals are unit and point out of the polygon.

#include <array>
#include <cstdint>

#include "dyop/triangle.hpp"
#include "dyop/vec2.hpp"

namespace dyop {

/// Most vertices a `Polygon` holds: Box2D 2.4's `b2_maxPolygonVertices`.
inline constexpr int max_polygon_vertices = 8;

/// What is wrong with points that do not make a usable convex polygon or circle.
enum class ConvexError : std::uint8_t {
  None,            ///< a valid shape
  VertexCount,     ///< fewer than 3 or more than `max_polygon_vertices` vertices
  NonFinite,       ///< a coordinate (or the radius) is NaN or infinite
  TooLarge,        ///< a coordinate (or the radius) beyond `max_coordinate`
  TooSmall,        ///< longest edge (a segment's length, or the radius) below `min_size`
  RepeatedVertex,  ///< two consecutive vertices are equal (a segment's two ends)
  NotConvex,       ///< a vertex lies on or outside the line of an edge it is not on (see
                   ///< `degenerate_tolerance`): reflex, collinear, self-intersecting or flat
};

/// A static, human-readable description of `e` ("not convex", ...).
const char* describe(ConvexError e);

template <class T>
class Polygon;

/// The outcome of `Polygon<T>::make`: `polygon` is meaningful only when `error == None`.
template <class T>
struct PolygonOrError;

/// A strictly convex polygon of 3 to `max_polygon_vertices` vertices, stored counter-clockwise
/// with its unit outward edge normals.
template <class T>
class Polygon {
 public:
  /// Validates `points[0..count)` (world coordinates, any winding). Strictly convex: every vertex
  /// lies inside the line of every edge it is not on, by more than `degenerate_tolerance<T>()`
  /// times the longest edge. Never asserts, never fixes input (no hull is taken).
  static PolygonOrError<T> make(const Vec2<T>* points, int count);
  /// What `make` would find wrong with `points[0..count)` (`None`: it would accept them).
  static ConvexError check(const Vec2<T>* points, int count);
  /// The triangle as a polygon: the same vertices, normals and caller's order.
  static Polygon from_triangle(const Triangle<T>& t);

  /// A polygon from data validated before, placed by the rigid motion x ↦ R·x + translation (R the
  /// rotation whose cosine and sine are `c` and `s`): `ccw[0..count)` are vertices that `make`
  /// accepted, counter-clockwise, and `normals` their unit outward edge normals. Nothing is
  /// checked: the caller vouches for the data (the Box2D plug-in: a `b2PolygonShape` holds both).
  static Polygon from_validated(const Vec2<T>* ccw, const Vec2<T>* normals, int count, T c, T s,
                                const Vec2<T>& translation);
  /// `from_validated` where the data is already in place (no motion: no arithmetic on it).
  static Polygon from_validated(const Vec2<T>* ccw, const Vec2<T>* normals, int count);

  /// Number of vertices (and edges), 3..`max_polygon_vertices`.
  int count() const { return count_; }
  /// CCW vertex `i` (0..count-1), world coordinates.
  const Vec2<T>& vertex(int i) const { return v_[static_cast<std::size_t>(i)]; }
  /// Unit outward normal of CCW edge `i` (from vertex `i` to vertex `i + 1`).
  const Vec2<T>& normal(int i) const { return n_[static_cast<std::size_t>(i)]; }
  /// The CCW index after `i`.
  int next(int i) const { return i + 1 < count_ ? i + 1 : 0; }
  /// Length of the longest edge: the polygon's size, the unit of its relative tolerances.
  T size() const { return size_; }
  /// True when the caller gave the vertices clockwise.
  bool flipped() const { return flipped_; }
  /// Caller's index of CCW vertex `i`. Clockwise input: CCW vertex i is caller's (count − i) %
  /// count.
  int input_vertex(int i) const { return flipped_ && i != 0 ? count_ - i : i; }
  /// Caller's index of CCW edge `i`. Clockwise input: CCW edge i is caller's edge count − 1 − i.
  int input_edge(int i) const { return flipped_ ? count_ - 1 - i : i; }

 private:
  Polygon() = default;
  friend struct PolygonOrError<T>;

  std::array<Vec2<T>, max_polygon_vertices> v_{};
  std::array<Vec2<T>, max_polygon_vertices> n_{};
  T size_ = 0;
  int count_ = 0;
  bool flipped_ = false;
};

template <class T>
struct PolygonOrError {
  ConvexError error = ConvexError::None;                  ///< None when `polygon` is valid
  Polygon<T> polygon;                                     ///< valid only when `error == None`
  bool ok() const { return error == ConvexError::None; }  ///< true when `error == None`
};

/// A disk: its centre (world coordinates) and radius (length units, > 0).
template <class T>
struct Circle {
  Vec2<T> center = Vec2<T>::Zero();  ///< world coordinates
  T radius = 0;                      ///< length units; `check` wants at least `min_size<T>()`
  /// What is wrong with `center` and `radius` (`None`: a usable disk): non-finite, a coordinate or
  /// the radius beyond `max_coordinate`, or a radius below `min_size`.
  static ConvexError check(const Vec2<T>& center, T radius);
};

template <class T>
class Segment;

/// The outcome of `Segment<T>::make`: `segment` is meaningful only when `error == None`.
template <class T>
struct SegmentOrError;

/// A line segment from `vertex(0)` to `vertex(1)`, as Box2D's `b2EdgeShape` holds one. It is read
/// as a polygon of two vertices and two edges, one per side: edge 0 runs from vertex 0 to vertex 1
/// and its outward normal `normal(0)` points to the right of that direction (Box2D's edge normal,
/// the front of a one-sided edge); edge 1 runs back from vertex 1 to vertex 0, `normal(1)` the
/// opposite (the back). Masks (`ShapeMasks`): edge bit 0 the front, bit 1 the back (set for a
/// one-sided edge: no push through to its back); vertex bits 0 and 1 its ends.
template <class T>
class Segment {
 public:
  /// Validates the end points (world coordinates): finite, within `max_coordinate`, distinct and
  /// at least `min_size` apart. Never asserts, never fixes input.
  static SegmentOrError<T> make(const Vec2<T>& p0, const Vec2<T>& p1);
  /// What `make` would find wrong with the end points (`None`: it would accept them).
  static ConvexError check(const Vec2<T>& p0, const Vec2<T>& p1);

  /// Number of vertices (and edges, one per side): 2.
  static constexpr int count() { return 2; }
  /// End point `i` (0 or 1), world coordinates.
  const Vec2<T>& vertex(int i) const { return v_[static_cast<std::size_t>(i)]; }
  /// Unit normal of side `i`: 0 the front (right of vertex 0 → vertex 1), 1 the back.
  const Vec2<T>& normal(int i) const { return n_[static_cast<std::size_t>(i)]; }
  /// The other end.
  static constexpr int next(int i) { return 1 - i; }
  /// Its length: the unit of its relative tolerances.
  T size() const { return size_; }
  /// The caller's order is the segment's own: vertex and edge indices map to themselves.
  static constexpr int input_vertex(int i) { return i; }
  /// See `input_vertex`.
  static constexpr int input_edge(int i) { return i; }

 private:
  Segment() = default;
  friend struct SegmentOrError<T>;

  std::array<Vec2<T>, 2> v_{};
  std::array<Vec2<T>, 2> n_{};
  T size_ = 0;
};

template <class T>
struct SegmentOrError {
  ConvexError error = ConvexError::None;                  ///< None when `segment` is valid
  Segment<T> segment;                                     ///< valid only when `error == None`
  bool ok() const { return error == ConvexError::None; }  ///< true when `error == None`
};

/// \cond EXPLICIT_INSTANTIATIONS
extern template class Segment<float>;
extern template class Segment<double>;
extern template class Polygon<float>;
extern template class Polygon<double>;
extern template struct Circle<float>;
extern template struct Circle<double>;
/// \endcond

}  // namespace dyop
