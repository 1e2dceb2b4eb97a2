#include "triangle_contact.hpp"

#include <box2d/b2_block_allocator.h>
#include <box2d/b2_fixture.h>
#include <box2d/b2_world.h>

#include <new>
#include <optional>
#include <typeinfo>

#include "dyop/box2d_measurement.hpp"
#include "evaluation.hpp"
#include "internal_edges.hpp"
#include "installation.hpp"

namespace dyop::box2d::detail {
namespace {

// Box2D's block allocator serves sizes in classes (..., 160, 192, 224, 256, 320, ...). Box2D's
// own polygon contact adds nothing to b2Contact (208 bytes in Box2D 2.4.1): the 224-byte class.
// Ours adds its `ContactMemory` (16 bytes) and `ManifoldRecycling` (24): the 256-byte class.
constexpr std::size_t allocator_class_below = 224;
constexpr std::size_t allocator_class = 256;

// Calls `visit(TriangleContact&)` for the plug-in's contacts between bodies `p` and `q` until it
// returns false, walking the shorter of the two bodies' contact lists: a ground's may be long, a
// falling body's is short.
template <class Visit>
void for_contacts_between(const b2Body& p, const b2Body& q, const Visit& visit) {
  const b2ContactEdge* x = p.GetContactList();
  const b2ContactEdge* y = q.GetContactList();
  while (x && y) {
    x = x->next;
    y = y->next;
  }
  const b2Body& walked = x ? q : p;
  const b2Body& other = x ? p : q;
  for (const b2ContactEdge* e = walked.GetContactList(); e; e = e->next) {
    if (e->other != &other) continue;
    if (TriangleContact* c = TriangleContact::ours(e->contact); c && !visit(*c)) return;
  }
}

// A contact between bodies `p` and `q` made or destroyed between steps (the world unlocked) means
// a fixture of one of them was added, destroyed, moved, enabled or changed type: the other
// contacts between the same two bodies find their internal-edge masks again. (Any fixture whose
// edge a contact's pair could push along is within the skins of it, well inside the broad phase's
// fattened boxes, so it has a contact of its own with the other body.)
void forget_internal_edges_between(const b2Body& p, const b2Body& q) {
  for_contacts_between(p, q, [](TriangleContact& c) {
    c.forget_internal_edges();
    return true;
  });
}

// Bits 0..2 of one triangle's half of a pair's masks: A's (`high` false) or B's.
InternalEdges half(InternalEdges m, bool high) {
  const int shift = high ? 3 : 0;
  return {static_cast<std::uint8_t>((m.edges >> shift) & 7),
          static_cast<std::uint8_t>((m.closed_vertices >> shift) & 7)};
}

// Between steps, with the rule on: see `forget_internal_edges_between`.
void fixtures_changed_near(const b2Contact& c) {
  const b2Body& a = *c.GetFixtureA()->GetBody();
  if (installation().setting.internal_edges && !a.GetWorld()->IsLocked()) {
    forget_internal_edges_between(a, *c.GetFixtureB()->GetBody());
  }
}

}  // namespace

// The size budget. Box2D's own destroy function would free a contact with
// sizeof(b2PolygonContact), the 224-byte class: ours are never handed to it, since our destroy
// function, which frees every polygon contact as what it is, stays registered once installed
// (see `uninstall`).
static_assert(sizeof(TriangleContact) > allocator_class_below &&
                  sizeof(TriangleContact) <= allocator_class,
              "the plug-in's contact must fit Box2D's 256-byte allocator class");

b2Contact* TriangleContact::create(b2Fixture* fixture_a, int32, b2Fixture* fixture_b, int32,
                                   b2BlockAllocator* allocator) {
  void* memory = allocator->Allocate(sizeof(TriangleContact));
  b2Contact* contact = new (memory) TriangleContact(fixture_a, fixture_b);
  fixtures_changed_near(*contact);
  return contact;
}

void TriangleContact::destroy(b2Contact* contact, b2BlockAllocator* allocator) {
  fixtures_changed_near(*contact);
  if (!ours(contact)) {
    // Made by Box2D's own code before an install: its own function frees it. `installation()`
    // saved that function before our destroy could ever be registered.
    installation().box2d_own.destroy(contact, allocator);
    return;
  }
  static_cast<TriangleContact*>(contact)->~TriangleContact();
  allocator->Free(contact, sizeof(TriangleContact));
}

TriangleContact* TriangleContact::ours(b2Contact* c) {
  return typeid(*c) == typeid(TriangleContact) ? static_cast<TriangleContact*>(c) : nullptr;
}

InternalEdges TriangleContact::find_internal_edges(std::uint16_t stamp) const {
  // Sharing is safe within one pair of bodies: a contact of theirs with the same stamp found its
  // masks from the same fixtures, and what makes one of them stale otherwise (a contact between
  // the two bodies made or destroyed between steps) clears them all.
  std::optional<InternalEdges> a;
  std::optional<InternalEdges> b;
  for_contacts_between(*m_fixtureA->GetBody(), *m_fixtureB->GetBody(), [&](TriangleContact& c) {
    if (&c == this || c.memory_.internal_edges_stamp != stamp) return true;
    const InternalEdges m = c.memory_.internal_edges;
    if (!a && c.m_fixtureA == m_fixtureA) a = half(m, false);
    if (!a && c.m_fixtureB == m_fixtureA) a = half(m, true);
    if (!b && c.m_fixtureA == m_fixtureB) b = half(m, false);
    if (!b && c.m_fixtureB == m_fixtureB) b = half(m, true);
    return !(a && b);
  });
  return InternalEdges::pair(a ? *a : triangle_internal_edges(*m_fixtureA),
                             b ? *b : triangle_internal_edges(*m_fixtureB));
}

TriangleContact::TriangleContact(b2Fixture* fixture_a, b2Fixture* fixture_b)
    : b2Contact(fixture_a, 0, fixture_b, 0) {}

void TriangleContact::Evaluate(b2Manifold* manifold, const b2Transform& xf_a,
                               const b2Transform& xf_b) {
  // The registry dispatches only polygon–polygon pairs here.
  const auto& a = *static_cast<const b2PolygonShape*>(m_fixtureA->GetShape());
  const auto& b = *static_cast<const b2PolygonShape*>(m_fixtureB->GetShape());
  evaluate(manifold, installation().setting, {a, xf_a, b, xf_b}, memory_, this, &recycling_);
}

void TriangleContact::evaluate_afresh(b2Manifold* manifold) const {
  const auto& a = *static_cast<const b2PolygonShape*>(m_fixtureA->GetShape());
  const auto& b = *static_cast<const b2PolygonShape*>(m_fixtureB->GetShape());
  ContactMemory memory = memory_;  // its masks and warm start, not its state
  Setting setting = installation().setting;
  setting.never_recompute = false;
  evaluate(manifold, setting,
           {a, m_fixtureA->GetBody()->GetTransform(), b, m_fixtureB->GetBody()->GetTransform()},
           memory, this);
}

}  // namespace dyop::box2d::detail

namespace dyop::box2d {

void measurement::evaluate_afresh(const b2Contact& contact, b2Manifold* manifold) {
  manifold->pointCount = 0;
  const b2Fixture* fa = contact.GetFixtureA();
  const b2Fixture* fb = contact.GetFixtureB();
  if (fa->GetType() != b2Shape::e_polygon || fb->GetType() != b2Shape::e_polygon) return;
  auto* c = const_cast<b2Contact*>(&contact);
  if (const detail::TriangleContact* ours = detail::TriangleContact::ours(c)) {
    ours->evaluate_afresh(manifold);
    return;
  }
  b2CollidePolygons(manifold, static_cast<const b2PolygonShape*>(fa->GetShape()),
                    fa->GetBody()->GetTransform(),
                    static_cast<const b2PolygonShape*>(fb->GetShape()),
                    fb->GetBody()->GetTransform());
}

}  // namespace dyop::box2d
