#pragma once
/// \file
/// A world's triangle contact as the exact reference sees it: both triangles in A's body frame,
/// in double, from the float shapes and transforms (B's vertices moved by the relative transform
/// computed in double), so that the reference's answer is exact for the pose the world holds.

#include <optional>

#include "dyop/convex_pair.hpp"

#include "dyop/triangle.hpp"
#include "dyop/vec2.hpp"

class b2Contact;
struct b2Vec2;

namespace dyop::scenes {

/// B's body frame given in A's, in double.
struct FrameBInA {
  double c = 1, s = 0;   ///< rotation: cosine, sine
  Vec2<double> t{0, 0};  ///< translation

  /// A point given in B's body frame, in A's.
  Vec2<double> point(const b2Vec2& p) const { return direction(p) + t; }
  /// A direction given in B's body frame, in A's.
  Vec2<double> direction(const b2Vec2& d) const;
};

/// The two triangles of a contact in A's body frame, in double.
struct ExactPair {
  FrameBInA b_in_a;    ///< B's body frame in A's
  Triangle<double> a;  ///< A's triangle as its shape stores it
  Triangle<double> b;  ///< B's, moved into A's frame
};

/// The contact's triangles in A's frame; nothing when a fixture is not a triangle, or a triangle
/// is rejected in double (`Triangle<double>::make`).
std::optional<ExactPair> exact_pair(const b2Contact& contact);

/// A contact beyond two triangles in A's body frame, in double: polygon A (or segment A: an edge or
/// a chain's edge) and polygon B (a side of 4 to 8 vertices) or circle B.
struct ExactConvexPair {
  FrameBInA b_in_a;                  ///< B's body frame in A's
  std::optional<Polygon<double>> a;  ///< A's polygon as its shape stores it, or nothing: a segment
  std::optional<Segment<double>> segment;  ///< A's edge, when `a` is nothing
  std::optional<Polygon<double>> b;  ///< B's polygon moved into A's frame, or nothing: a circle
  Circle<double> circle;             ///< B's circle moved into A's frame, when `b` is nothing

  /// The exact answer at `level` (`dyop::collide`).
  Result<double> exact(Level level) const;
  /// How deep the pair overlaps along the unit direction `u` (from A to B).
  double overlap_along(const Vec2<double>& u) const;
};

/// The contact's shapes in A's frame when it is a polygon pair with a side of more than 3
/// vertices, a polygon–circle pair or an edge (chain) pair; nothing otherwise, or when
/// `Polygon<double>` or `Segment<double>` rejects one.
std::optional<ExactConvexPair> exact_convex_pair(const b2Contact& contact);

}  // namespace dyop::scenes
