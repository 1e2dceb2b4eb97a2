#pragma once
/// \file
/// The everyday bodies the grounds and terrain sections of `dyop compare` put on their levels: a
/// `SetAsBox` box, a hexagon, a ball and a box of two triangle fixtures, each about 0.6 m across
/// (a game's crowd; the plug-in answers every polygon and circle pair of them against triangles).
///
/// Units: metres, kilograms (density 1).

#include <box2d/b2_circle_shape.h>
#include <box2d/b2_polygon_shape.h>

#include <utility>
#include <vector>

#include "worlds/world.hpp"

namespace dyop::experiments {

/// The everyday bodies' shapes; the box of two triangles has none (`add_everyday_body` makes it).
struct EverydayShapes {
  b2PolygonShape box;      ///< `SetAsBox(0.25, 0.3)`
  b2PolygonShape hexagon;  ///< regular, its corners 0.3 m from its centre
  b2CircleShape ball;      ///< radius 0.3 m
  EverydayShapes();
  /// Each body's name and shape, in this order: `SetAsBox` box, hexagon, ball, then the box of two
  /// triangles (shape nullptr; half-size 0.3 m).
  std::vector<std::pair<const char*, const b2Shape*>> all() const;
};

/// A dynamic body at `at` with one fixture of `shape` (density 1, `friction`), or, for nullptr, a
/// box of two triangle fixtures of half-size 0.3 m.
b2Body* add_everyday_body(worlds::World& world, const b2Shape* shape, const b2Vec2& at,
                          float friction);

/// The height of the body's origin above y = 0 when its lowest point rests on y = 0 (nullptr: the
/// box of two triangles).
float resting_height(const b2Shape* shape);

}  // namespace dyop::experiments
