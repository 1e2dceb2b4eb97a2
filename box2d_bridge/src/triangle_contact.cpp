#include "triangle_contact.hpp"

#include <box2d/b2_block_allocator.h>
#include <box2d/b2_fixture.h>
#include <box2d/b2_world.h>

#include <new>
#include <typeinfo>

#include "body_edges.hpp"
#include "evaluate_pair.hpp"
#include "installation.hpp"

namespace dyop::box2d::detail {
namespace {

// Box2D's own polygon contact adds nothing to b2Contact (208 bytes in Box2D 2.4.1), which its
// block allocator serves from the 224-byte class (classes: ..., 160, 192, 224, 256, ...).
constexpr std::size_t box2d_polygon_contact_size = sizeof(b2Contact);
constexpr std::size_t allocator_class_below = 192;
constexpr std::size_t allocator_class = 224;

}  // namespace

// The size budget, and what makes any registration safe for any live contact: Box2D's own
// destroy function frees a contact with sizeof(b2PolygonContact), which the block allocator maps
// to the same class as ours, after calling the (virtual) destructor of what the contact is.
static_assert(box2d_polygon_contact_size > allocator_class_below &&
                  box2d_polygon_contact_size <= allocator_class,
              "Box2D's polygon contact is no longer in the 224-byte allocator class");
static_assert(sizeof(TriangleContact) > allocator_class_below &&
                  sizeof(TriangleContact) <= allocator_class,
              "the plug-in's contact must share b2PolygonContact's allocator class (224 bytes)");

b2Contact* TriangleContact::create(b2Fixture* fixture_a, int32, b2Fixture* fixture_b, int32,
                                   b2BlockAllocator* allocator) {
  void* memory = allocator->Allocate(sizeof(TriangleContact));
  return new (memory) TriangleContact(fixture_a, fixture_b);
}

void TriangleContact::destroy(b2Contact* contact, b2BlockAllocator* allocator) {
  if (typeid(*contact) != typeid(TriangleContact)) {
    // Made by Box2D's own code before an install: its own function frees it. `installation()`
    // saved that function before our destroy could ever be registered.
    installation().box2d_own.destroy(contact, allocator);
    return;
  }
  const b2Body& body_a = *contact->GetFixtureA()->GetBody();
  if (!body_a.GetWorld()->IsLocked()) {
    // Destroyed between steps: a fixture or a body is going, or a body changed type or was
    // disabled. The bodies' internal edges are found again when next needed.
    forget_body(body_a);
    forget_body(*contact->GetFixtureB()->GetBody());
  }
  static_cast<TriangleContact*>(contact)->~TriangleContact();
  allocator->Free(contact, sizeof(TriangleContact));
}

TriangleContact::TriangleContact(b2Fixture* fixture_a, b2Fixture* fixture_b)
    : b2Contact(fixture_a, 0, fixture_b, 0) {}

void TriangleContact::Evaluate(b2Manifold* manifold, const b2Transform& xf_a,
                               const b2Transform& xf_b) {
  // The registry dispatches only polygon–polygon pairs here.
  const auto& a = *static_cast<const b2PolygonShape*>(m_fixtureA->GetShape());
  const auto& b = *static_cast<const b2PolygonShape*>(m_fixtureB->GetShape());
  const Installation& now = installation();
  if (!now.backend) {
    b2CollidePolygons(manifold, &a, xf_a, &b, xf_b);  // uninstalled: as Box2D's own contact
    return;
  }
  if (now.find_internal_edges && memory_.edges_generation != index_generation()) {
    // Once per contact, the first time the rule applies, and again after a body's fixtures
    // changed: a world that never needs it never pays for the search (callgrind, rain 150 steps:
    // 11 M instructions of 175 M in Collide).
    memory_.edges_generation = index_generation();
    const TriangleEdges ea = triangle_edges(*m_fixtureA);
    const TriangleEdges eb = triangle_edges(*m_fixtureB);
    memory_.inactive_edges = static_cast<std::uint8_t>(ea.inactive_edges | eb.inactive_edges << 3);
    memory_.flat_vertices = static_cast<std::uint8_t>(ea.flat_vertices | eb.flat_vertices << 3);
  }
  evaluate_pair(manifold, *now.backend, now.config, a, xf_a, b, xf_b, memory_);
}

}  // namespace dyop::box2d::detail
