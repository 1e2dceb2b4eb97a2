#include "contact_registry.hpp"

namespace dyop::box2d::detail {
namespace {

// The registry and its helpers are protected members of b2Contact; a subclass that is never
// instantiated is the only way in without touching Box2D.
class Registry : public b2Contact {
 public:
  // Box2D fills the registry lazily, on the first contact it creates; doing it first means that
  // lazy fill cannot overwrite our entry later (nor have overwritten it already).
  static void initialize() {
    if (!s_initialized) {
      InitializeRegisters();
      s_initialized = true;
    }
  }

  static PolygonContactFcns get(b2Shape::Type b) {
    initialize();
    const b2ContactRegister& r = s_registers[b2Shape::e_polygon][b];
    return {r.createFcn, r.destroyFcn};
  }

  // `AddType` also fills the mirrored entry as not primary, so Box2D hands the fixtures over in
  // this order (the polygon as A).
  static void set(const PolygonContactFcns& f, b2Shape::Type b) {
    initialize();
    AddType(f.create, f.destroy, b2Shape::e_polygon, b);
  }
};

}  // namespace

PolygonContactFcns polygon_contact_fcns() { return Registry::get(b2Shape::e_polygon); }

void register_polygon_contact(const PolygonContactFcns& f) { Registry::set(f, b2Shape::e_polygon); }

PolygonContactFcns polygon_circle_contact_fcns() { return Registry::get(b2Shape::e_circle); }

void register_polygon_circle_contact(const PolygonContactFcns& f) {
  Registry::set(f, b2Shape::e_circle);
}

}  // namespace dyop::box2d::detail
