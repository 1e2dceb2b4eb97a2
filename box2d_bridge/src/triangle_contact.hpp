#pragma once
// Internal: the plug-in's Box2D contact for polygon–polygon pairs.

#include <box2d/b2_body.h>
#include <box2d/b2_contact.h>
#include <box2d/b2_contact_manager.h>
#include <box2d/b2_fixture.h>
#include <box2d/b2_world.h>

#include "dyop/box2d.hpp"
#include "recycling.hpp"

namespace dyop::box2d::detail {

// Box2D's contact for a polygon pair made while the plug-in is installed: `Evaluate` is the
// plug-in's evaluation with whatever is installed at the time (Box2D's own answer once
// uninstalled). Holds no heap memory (b2World's destructor frees contacts without running their
// destructors): what the pair remembers between steps is its `ContactMemory`, inside the object.
// Last step's manifold needs no copy: Box2D passes it back to `Evaluate` in `m_manifold`.
class TriangleContact final : public b2Contact {
 public:
  // Box2D's create / destroy functions for the registry (b2ContactCreateFcn / b2ContactDestroyFcn).
  static b2Contact* create(b2Fixture* fixture_a, int32 index_a, b2Fixture* fixture_b,
                           int32 index_b, b2BlockAllocator* allocator);
  // Frees any polygon contact as what it is: ours here, Box2D's own through Box2D's own function.
  static void destroy(b2Contact* contact, b2BlockAllocator* allocator);

  void Evaluate(b2Manifold* manifold, const b2Transform& xf_a, const b2Transform& xf_b) override;

  // The plug-in's contact `c` is, or nullptr (Box2D's own, made before an install).
  static TriangleContact* ours(b2Contact* c);

  // What its internal-edge masks would be found under now (`ContactMemory::internal_edges_stamp`):
  // install `epoch` and its world's fixture proxies, never 0. Why the proxy count: it is the
  // world's own and moves whenever a fixture of the world is created or destroyed (a fixture
  // added next to a triangle, or one taken away from under a body resting elsewhere on its
  // neighbour, changes that neighbour's masks), in O(1). Folded with the install so that a change
  // of either gives another stamp (short of a multiple of 2^16 proxies). Inline: every full
  // evaluation with the rule on asks.
  std::uint16_t internal_edges_stamp(std::uint8_t epoch) const {
    const auto proxies = static_cast<std::uint32_t>(
        m_fixtureA->GetBody()->GetWorld()->GetContactManager().m_broadPhase.GetProxyCount());
    const auto stamp = static_cast<std::uint16_t>(proxies * 257u + epoch);
    return stamp != 0 ? stamp : 1;
  }

  // The pair's internal-edge masks (`ContactMemory::internal_edges`) under `stamp`: each
  // triangle's half taken from another contact between the same two bodies that has the same
  // fixture and masks found under `stamp`, else found from the fixture's body
  // (`triangle_internal_edges`). A box on a ground finds a ground triangle's masks once for all
  // its fixtures touching it.
  InternalEdges find_internal_edges(std::uint16_t stamp) const;

  // The manifold it would compute now with nothing kept (`measurement::evaluate_afresh`), its
  // state unchanged.
  void evaluate_afresh(b2Manifold* manifold) const;

  // Its internal-edge masks are found again when next needed (a fixture near it changed).
  void forget_internal_edges() { memory_.internal_edges_stamp = 0; }

 private:
  TriangleContact(b2Fixture* fixture_a, b2Fixture* fixture_b);

  ContactMemory memory_;
  ManifoldRecycling recycling_;
};

}  // namespace dyop::box2d::detail
