#pragma once
// Internal: the plug-in's Box2D contact for polygon–polygon pairs.

#include <box2d/b2_contact.h>

#include "dyop/box2d.hpp"
#include "pair_state.hpp"

namespace dyop::box2d::detail {

// Box2D's contact for a polygon pair while the plug-in is installed: `Evaluate` is
// `evaluate_pair` with the backend and skips installed when the contact was made. Holds no heap
// memory (b2World's destructor frees contacts without running their destructors): what the pair
// remembers between steps (Lin–Canny's cache, its triangles, its last manifold) lives in the object.
class TriangleContact final : public b2Contact {
 public:
  // Box2D's create / destroy functions for the registry (b2ContactCreateFcn / b2ContactDestroyFcn).
  static b2Contact* create(b2Fixture* fixture_a, int32 index_a, b2Fixture* fixture_b,
                           int32 index_b, b2BlockAllocator* allocator);
  static void destroy(b2Contact* contact, b2BlockAllocator* allocator);

  // The backend and skips of contacts made from now on.
  static void use(Backend backend, const Config& config);
  // Contacts made and not yet destroyed.
  static int live();

  void Evaluate(b2Manifold* manifold, const b2Transform& xf_a, const b2Transform& xf_b) override;

 private:
  TriangleContact(b2Fixture* fixture_a, b2Fixture* fixture_b, Backend backend,
                  const Config& config);
  ~TriangleContact() override;

  Backend backend_;
  Config config_;
  PairState state_;
};

}  // namespace dyop::box2d::detail
