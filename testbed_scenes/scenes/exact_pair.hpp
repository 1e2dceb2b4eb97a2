#pragma once
/// \file
/// A world's triangle contact as the exact reference sees it: both triangles in A's body frame,
/// in double, from the float shapes and transforms (B's vertices moved by the relative transform
/// computed in double), so that the reference's answer is exact for the pose the world holds.

#include <optional>

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

}  // namespace dyop::scenes
