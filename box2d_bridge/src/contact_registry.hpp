#pragma once
// Internal: Box2D's contact registry entries for the shape pairs the plug-in takes.

#include <box2d/b2_contact.h>
#include <box2d/b2_shape.h>

#include <array>

namespace dyop::box2d::detail {

// What Box2D calls to make and to free the contact of a pair of shapes.
struct ContactFcns {
  b2ContactCreateFcn* create = nullptr;
  b2ContactDestroyFcn* destroy = nullptr;
};

// A pair of shape types in Box2D's registry order (A's, B's).
struct ShapePair {
  b2Shape::Type a;
  b2Shape::Type b;
};

// The pairs the plug-in's contact can take, in this order: polygon–polygon, polygon–circle, then
// edge and chain (A) against polygon and circle (B).
inline constexpr int taken_pair_count = 6;
inline constexpr std::array<ShapePair, taken_pair_count> taken_pairs = {{
    {b2Shape::e_polygon, b2Shape::e_polygon},
    {b2Shape::e_polygon, b2Shape::e_circle},
    {b2Shape::e_edge, b2Shape::e_polygon},
    {b2Shape::e_edge, b2Shape::e_circle},
    {b2Shape::e_chain, b2Shape::e_polygon},
    {b2Shape::e_chain, b2Shape::e_circle},
}};

// The index in `taken_pairs` of the pair of a contact whose fixtures have types `a` and `b`
// (Box2D's order), or -1.
inline int taken_pair_index(b2Shape::Type a, b2Shape::Type b) {
  for (int i = 0; i < taken_pair_count; ++i) {
    if (taken_pairs[static_cast<std::size_t>(i)].a == a &&
        taken_pairs[static_cast<std::size_t>(i)].b == b) {
      return i;
    }
  }
  return -1;
}

// The registered pair of functions for `pair` (Box2D's own unless changed).
ContactFcns contact_fcns(ShapePair pair);

// Registers `f` for `pair` (A's type as fixture A), process-wide.
void register_contact(const ContactFcns& f, ShapePair pair);

}  // namespace dyop::box2d::detail
