#pragma once
/// \file
/// A validated triangle: the input type of every penetration-depth method.
///
/// Conventions (used by every header of the library):
/// - Vertices are given in world coordinates, in any winding. The triangle stores them
///   counter-clockwise (CCW); `input_vertex` / `input_edge` map a CCW index back to the
///   caller's order, and every feature index a result reports is already in the caller's order.
/// - Edge `i` runs from vertex `i` to vertex `(i + 1) % 3` (in whichever order is being spoken of).
/// - Normals are unit and point out of the triangle.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

#include "dyop/vec2.hpp"

namespace dyop {

/// What is wrong with three points that do not make a usable triangle.
enum class TriangleError : std::uint8_t {
  None,            ///< a valid triangle
  NonFinite,       ///< a coordinate is NaN or infinite
  TooLarge,        ///< a coordinate beyond `max_coordinate`: squared lengths would overflow
  TooSmall,        ///< longest edge below `min_size`: squared lengths would underflow
  RepeatedVertex,  ///< two vertices are equal
  Degenerate,      ///< (nearly) collinear: see `degenerate_tolerance`
};

/// A static, human-readable description of `e` ("non-finite coordinate", ...).
const char* describe(TriangleError e);

/// Relative flatness below which a triangle is rejected as degenerate: twice its area must exceed
/// `degenerate_tolerance<T>() * longest_edge²` (height over the longest edge larger than this
/// fraction of that edge). Why this value: the orientation test `cross(e1, e2)` has a rounding
/// error of at most about 3·eps·|e1||e2|; 64·eps leaves a 20× margin, so a triangle that passes
/// has a trustworthy winding and trustworthy edge normals. double: 1.4e-14, float: 7.6e-6.
template <class T>
constexpr T degenerate_tolerance() {
  return T(64) * Eigen::NumTraits<T>::epsilon();
}

/// Largest coordinate magnitude accepted. Why: validation and every method square edge lengths
/// and differences of coordinates; below sqrt(max)/8 no such square overflows. double: 1.7e153,
/// float: 2.3e18.
template <class T>
inline T max_coordinate() {
  return std::sqrt(std::numeric_limits<T>::max()) / T(8);
}

/// Smallest size accepted: the longest edge must be at least this long. Why: validation and every
/// method square lengths and differences of coordinates, and the exact methods resolve distances
/// down to eps × size; from sqrt(min)/eps on, every such square is a normal number, so no digit
/// is lost to underflow (below it, an edge's squared length can round to zero and its normal
/// become NaN). double: 6.7e-139, float: 9.1e-13.
template <class T>
inline T min_size() {
  return std::sqrt(std::numeric_limits<T>::min()) / std::numeric_limits<T>::epsilon();
}

template <class T>
class Triangle;

/// The outcome of `Triangle<T>::make`: `triangle` is meaningful only when `error == None`.
template <class T>
struct TriangleOrError;

/// A non-degenerate triangle, stored counter-clockwise with its unit outward edge normals.
template <class T>
class Triangle {
 public:
  /// Validates `p0, p1, p2` (world coordinates, any winding). Never asserts, never fixes input.
  static TriangleOrError<T> make(const Vec2<T>& p0, const Vec2<T>& p1, const Vec2<T>& p2);
  /// What `make` would find wrong with `p0, p1, p2` (`None`: it would accept them), without
  /// building the triangle: no square root, no division. For a caller that validates data once
  /// and places it later with `from_validated` (the Box2D plug-in, on a contact's first
  /// evaluation).
  static TriangleError check(const Vec2<T>& p0, const Vec2<T>& p1, const Vec2<T>& p2);

  /// A triangle from data validated before, placed by the rigid motion x ↦ R·x + translation (R
  /// as in `moved`): `ccw` are three vertices that `make` accepted, counter-clockwise, and
  /// `normals` their unit outward edge normals (normal `i` for the edge from vertex `i` to `i+1`).
  /// Nothing is checked or normalised: the caller vouches for the data. This is how a shape
  /// validated once is placed every step at no validation cost (the Box2D plug-in: a
  /// `b2PolygonShape` holds its vertices and normals). Edge lengths are measured along the edges'
  /// tangents (the normals turned left), with no square root.
  static Triangle from_validated(const std::array<Vec2<T>, 3>& ccw,
                                 const std::array<Vec2<T>, 3>& normals, T c, T s,
                                 const Vec2<T>& translation);
  /// `from_validated` where the data is already in place (no motion: no arithmetic on it).
  static Triangle from_validated(const std::array<Vec2<T>, 3>& ccw,
                                 const std::array<Vec2<T>, 3>& normals);

  /// CCW vertex `i` (0..2), world coordinates.
  const Vec2<T>& vertex(int i) const { return v_[i]; }
  /// Unit outward normal of CCW edge `i` (from vertex `i` to vertex `i+1`).
  const Vec2<T>& normal(int i) const { return n_[i]; }
  /// Length of CCW edge `i`.
  T edge_length(int i) const { return len_[i]; }
  /// Unit direction of CCW edge `i` (from vertex `i` to vertex `i+1`): the normal turned left.
  Vec2<T> tangent(int i) const { return Vec2<T>(-n_[i].y(), n_[i].x()); }
  /// Length of the longest edge: the triangle's size, the unit of its relative tolerances.
  T size() const { return size_; }
  /// This triangle after the rigid motion x ↦ R·x + translation, R the rotation by the angle whose
  /// cosine and sine are `c` and `s` (c² + s² = 1). Vertices and normals are rotated, not
  /// recomputed, and nothing is re-validated: a rigid motion keeps a valid triangle valid. This is
  /// how a body's triangle, validated once in its body frame, is placed in another frame.
  Triangle moved(T c, T s, const Vec2<T>& translation) const;
  /// True when the caller gave the vertices clockwise.
  bool flipped() const { return flipped_; }
  /// Caller's index of CCW vertex `i`. Clockwise input: CCW vertices 0, 1, 2 are caller's 0, 2, 1.
  int input_vertex(int i) const { return kInputVertex[flipped_][i]; }
  /// Caller's index of CCW edge `i`. Clockwise input: CCW edge 0 (caller 0→2) is caller edge 2.
  int input_edge(int i) const { return kInputEdge[flipped_][i]; }

 private:
  Triangle() = default;
  friend struct TriangleOrError<T>;

  // Index maps by `flipped_`, looked up rather than selected: half of all inputs are clockwise,
  // so a branch on it is mispredicted half the time.
  static constexpr std::uint8_t kInputVertex[2][3] = {{0, 1, 2}, {0, 2, 1}};
  static constexpr std::uint8_t kInputEdge[2][3] = {{0, 1, 2}, {2, 1, 0}};

  std::array<Vec2<T>, 3> v_{};
  std::array<Vec2<T>, 3> n_{};
  std::array<T, 3> len_{};
  T size_ = 0;
  bool flipped_ = false;
};

// Inline, scalar by scalar: the Box2D plug-in checks two triangles on every contact's first
// evaluation, and a tall rain makes 45,000 contacts in 150 steps.
template <class T>
inline TriangleError Triangle<T>::check(const Vec2<T>& p0, const Vec2<T>& p1, const Vec2<T>& p2) {
  const T coordinates[6] = {p0.x(), p0.y(), p1.x(), p1.y(), p2.x(), p2.y()};
  bool finite = true;
  T largest = 0;
  for (const T x : coordinates) {
    finite = finite && std::isfinite(x);
    largest = std::max(largest, std::abs(x));
  }
  if (!finite) return TriangleError::NonFinite;
  if (largest > max_coordinate<T>()) return TriangleError::TooLarge;
  if (p0 == p1 || p1 == p2 || p2 == p0) return TriangleError::RepeatedVertex;
  // Edges are differences of the inputs, so the test is invariant under translation.
  const Vec2<T> e01 = p1 - p0;
  const Vec2<T> e12 = p2 - p1;
  const Vec2<T> e20 = p0 - p2;
  const T longest_sq = std::max({e01.squaredNorm(), e12.squaredNorm(), e20.squaredNorm()});
  if (!(longest_sq >= min_size<T>() * min_size<T>())) return TriangleError::TooSmall;
  const T twice_area = cross(e01, Vec2<T>(p2 - p0));
  if (!(std::abs(twice_area) > degenerate_tolerance<T>() * longest_sq)) {
    return TriangleError::Degenerate;
  }
  return TriangleError::None;
}

template <class T>
inline Triangle<T> Triangle<T>::from_validated(const std::array<Vec2<T>, 3>& ccw,
                                               const std::array<Vec2<T>, 3>& normals, T c, T s,
                                               const Vec2<T>& translation) {
  // Inline: it runs once per triangle per contact update, where a call costs more than the work.
  Triangle<T> t = from_validated(ccw, normals);
  for (int i = 0; i < 3; ++i) {
    t.v_[i] = rotated(ccw[i], c, s) + translation;
    t.n_[i] = rotated(normals[i], c, s);
  }
  return t;
}

template <class T>
inline Triangle<T> Triangle<T>::from_validated(const std::array<Vec2<T>, 3>& ccw,
                                               const std::array<Vec2<T>, 3>& normals) {
  Triangle<T> t;
  t.v_ = ccw;
  t.n_ = normals;
  for (int i = 0; i < 3; ++i) {
    t.len_[i] = Vec2<T>(-normals[i].y(), normals[i].x()).dot(ccw[i == 2 ? 0 : i + 1] - ccw[i]);
  }
  t.size_ = std::max(std::max(t.len_[0], t.len_[1]), t.len_[2]);
  return t;
}

template <class T>
struct TriangleOrError {
  TriangleError error = TriangleError::None;                ///< None when `triangle` is valid
  Triangle<T> triangle;                                     ///< valid only when `error == None`
  bool ok() const { return error == TriangleError::None; }  ///< true when `error == None`
};

/// \cond EXPLICIT_INSTANTIATIONS
extern template class Triangle<float>;
extern template class Triangle<double>;
/// \endcond

}  // namespace dyop
