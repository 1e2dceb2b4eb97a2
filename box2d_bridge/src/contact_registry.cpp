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

  static ContactFcns get(ShapePair pair) {
    initialize();
    const b2ContactRegister& r = s_registers[pair.a][pair.b];
    return {r.createFcn, r.destroyFcn};
  }

  // `AddType` also fills the mirrored entry as not primary, so Box2D hands the fixtures over in
  // this order (A's type as fixture A).
  static void set(const ContactFcns& f, ShapePair pair) {
    initialize();
    AddType(f.create, f.destroy, pair.a, pair.b);
  }
};

}  // namespace

ContactFcns contact_fcns(ShapePair pair) { return Registry::get(pair); }

void register_contact(const ContactFcns& f, ShapePair pair) { Registry::set(f, pair); }

}  // namespace dyop::box2d::detail
