#pragma once
// Internal: Box2D's contact registry entries for polygon–polygon and polygon–circle pairs.

#include <box2d/b2_contact.h>

namespace dyop::box2d::detail {

// What Box2D calls to make and to free the contact of a pair of shapes.
struct PolygonContactFcns {
  b2ContactCreateFcn* create = nullptr;
  b2ContactDestroyFcn* destroy = nullptr;
};

// The registered pair of functions (Box2D's own `b2PolygonContact` unless changed).
PolygonContactFcns polygon_contact_fcns();

// Registers `f` for polygon–polygon pairs, process-wide.
void register_polygon_contact(const PolygonContactFcns& f);

// The registered pair of functions for polygon–circle pairs (Box2D's own
// `b2PolygonAndCircleContact` unless changed).
PolygonContactFcns polygon_circle_contact_fcns();

// Registers `f` for polygon–circle pairs (polygon as fixture A), process-wide.
void register_polygon_circle_contact(const PolygonContactFcns& f);

}  // namespace dyop::box2d::detail
