#include "contact.hpp"

#include <box2d/b2_block_allocator.h>
#include <box2d/b2_circle_shape.h>
#include <box2d/b2_fixture.h>
#include <box2d/b2_world.h>

#include <new>
#include <optional>
#include <typeinfo>

#include "dyop/box2d_internal_edges.hpp"
#include "dyop/box2d_measurement.hpp"
#include "evaluation.hpp"
#include "internal_edges.hpp"
#include "installation.hpp"

namespace dyop::box2d::detail {
namespace {

// Box2D's block allocator serves sizes in classes (..., 160, 192, 224, 256, 320, ...). Box2D's
// own polygon contact adds nothing to b2Contact (208 bytes in Box2D 2.4.1): the 224-byte class.
// Ours adds its `ContactMemory` (16 bytes), `FoundMasks` (8) and `ManifoldRecycling` (24): the
// 256-byte class.
constexpr std::size_t allocator_class_below = 224;
constexpr std::size_t allocator_class = 256;

// The body of `p` and `q` whose contact list is the shorter to walk for their contacts with each
// other: the non-static one when the other is static (a ground's list holds every body on it, a
// moving body's is short), else the shorter, found by stepping both lists together (measured:
// docs/measurements.md, "Choices in the code").
const b2Body& shorter_contact_list(const b2Body& p, const b2Body& q) {
  if (p.GetType() == b2_staticBody) return q;
  if (q.GetType() == b2_staticBody) return p;
  const b2ContactEdge* x = p.GetContactList();
  const b2ContactEdge* y = q.GetContactList();
  while (x && y) {
    x = x->next;
    y = y->next;
  }
  return x ? q : p;
}

// Calls `visit(Contact&)` for the plug-in's contacts between bodies `p` and `q` until it
// returns false, walking the shorter of the two bodies' contact lists (`shorter_contact_list`).
template <class Visit>
void for_contacts_between(const b2Body& p, const b2Body& q, const Visit& visit) {
  const b2Body& walked = shorter_contact_list(p, q);
  const b2Body& other = &walked == &p ? q : p;
  for (const b2ContactEdge* e = walked.GetContactList(); e; e = e->next) {
    if (e->other != &other) continue;
    if (Contact* c = Contact::ours(e->contact); c && !visit(*c)) return;
  }
}

// A contact between bodies `p` and `q` made or destroyed between steps (the world unlocked) means
// a fixture of one of them was added, destroyed, moved, enabled or changed type: the other
// contacts between the same two bodies find their internal-edge masks again. (Any fixture whose
// edge a contact's pair could push along is within the skins of it, well inside the broad phase's
// fattened boxes, so it has a contact of its own with the other body.)
void forget_internal_edges_between(const b2Body& p, const b2Body& q) {
  for_contacts_between(p, q, [](Contact& c) {
    c.forget_internal_edges();
    return true;
  });
}

// The static bodies near a contact of `p` and `q` changed (one was added, destroyed, moved or
// made static or not): static bodies share edges with each other, so every contact of a
// non-static one of the two with a static body finds its masks again; a moving body's contact
// list is short. (A static body's own list is not walked: its contacts are with moving bodies,
// each told through its own contact with the changed body, as above.)
void static_neighbourhood_changed(const b2Body& p, const b2Body& q) {
  for (const b2Body* body : {&p, &q}) {
    if (body->GetType() == b2_staticBody) continue;
    for (const b2ContactEdge* e = body->GetContactList(); e; e = e->next) {
      if (e->other->GetType() != b2_staticBody) continue;
      if (Contact* c = Contact::ours(e->contact)) c->forget_internal_edges();
    }
  }
}

// Bits 0..2 of one triangle's half of a pair's masks: A's (`high` false) or B's.
InternalEdges half(InternalEdges m, bool high) {
  const int shift = high ? 3 : 0;
  return {static_cast<std::uint8_t>((m.edges >> shift) & 7),
          static_cast<std::uint8_t>((m.closed_vertices >> shift) & 7)};
}

// With the rule on: between steps, see `forget_internal_edges_between` and
// `static_neighbourhood_changed` (a body made dynamic by `SetType` has already changed type when
// its contacts are destroyed, so every change between steps tells the static contacts); at any
// time, a contact going away whose masks no longer hold with a static body (a static body moved
// away beyond the broad phase's margin: the broad phase ends its contacts in the step) tells them
// too.
void fixtures_changed_near(const b2Contact& c) {
  if (!installation().setting.internal_edges) return;
  const b2Body& a = *c.GetFixtureA()->GetBody();
  const b2Body& b = *c.GetFixtureB()->GetBody();
  if (!a.GetWorld()->IsLocked()) {
    forget_internal_edges_between(a, b);
    static_neighbourhood_changed(a, b);
    return;
  }
  const Contact* ours = Contact::ours(const_cast<b2Contact*>(&c));
  if (ours && ours->static_stamp_stale(installation().setting.epoch)) {
    static_neighbourhood_changed(a, b);
  }
}

}  // namespace

// The size budget. Box2D's own destroy function would free a contact with
// sizeof(b2PolygonContact), the 224-byte class: ours are never handed to it, since our destroy
// function, which frees every polygon contact as what it is, stays registered once installed
// (see `uninstall`).
static_assert(sizeof(ContactMemory) == 16 && sizeof(FoundMasks) == 8 &&
                  sizeof(ManifoldRecycling) == 24,
              "the sizes the contact's budget counts on");
static_assert(sizeof(Contact) > allocator_class_below && sizeof(Contact) <= allocator_class,
              "the plug-in's contact must fit Box2D's 256-byte allocator class");

b2Contact* Contact::create(b2Fixture* fixture_a, int32 index_a, b2Fixture* fixture_b, int32 index_b,
                           b2BlockAllocator* allocator) {
  void* memory = allocator->Allocate(sizeof(Contact));
  b2Contact* contact = new (memory) Contact(fixture_a, index_a, fixture_b, index_b);
  fixtures_changed_near(*contact);
  counters().contacts.add();
  return contact;
}

void Contact::destroy(b2Contact* contact, b2BlockAllocator* allocator) {
  fixtures_changed_near(*contact);
  if (!ours(contact)) {
    // Made by Box2D's own code (before an install, or for a pair the config leaves to Box2D): its
    // own function frees it. `installation()` saved those functions before our destroy could ever
    // be registered.
    const int pair =
        taken_pair_index(contact->GetFixtureA()->GetType(), contact->GetFixtureB()->GetType());
    installation().box2d_own[static_cast<std::size_t>(pair)].destroy(contact, allocator);
    return;
  }
  static_cast<Contact*>(contact)->~Contact();
  allocator->Free(contact, sizeof(Contact));
}

void recompute_contacts_of(const b2Fixture& fixture) {
  for (const b2ContactEdge* e = fixture.GetBody()->GetContactList(); e; e = e->next) {
    Contact* c = Contact::ours(e->contact);
    if (c && (c->GetFixtureA() == &fixture || c->GetFixtureB() == &fixture)) c->recompute();
  }
}

Contact* Contact::ours(b2Contact* c) {
  return typeid(*c) == typeid(Contact) ? static_cast<Contact*>(c) : nullptr;
}

bool Contact::static_stamp_stale(std::uint8_t epoch) const {
  const std::uint16_t found = masks_.stamp;
  return found != 0 && !masks_.fixed() && found != internal_edges_stamp(epoch) &&
         with_static_body();
}

void Contact::internal_edges_stamp_moved(std::uint16_t seen) const {
  // Its static neighbours may have moved, and the pair's other static contacts may not see it in
  // their own stamps.
  if (seen != 0 && seen != FoundMasks::fixed_stamp && with_static_body()) {
    static_neighbourhood_changed(*m_fixtureA->GetBody(), *m_fixtureB->GetBody());
  }
}

InternalEdges Contact::find_internal_edges(std::uint16_t stamp, std::uint16_t fixtures,
                                           std::uint8_t epoch) const {
  // Sharing is safe within one pair of bodies: a contact of theirs with the same stamp found its
  // masks from the same fixtures, and what makes one of them stale otherwise (a contact between
  // the two bodies made or destroyed between steps) clears them all.
  // A fixture's fixed edge data first (`fix_internal_edges`): nothing to find.
  const auto triangle_half = [](std::optional<ShapeMasks> m) -> std::optional<InternalEdges> {
    if (!m) return std::nullopt;
    return InternalEdges{m->edges, m->closed_vertices};
  };
  std::optional<InternalEdges> a = triangle_half(fixed_masks_facing(*m_fixtureA, *m_fixtureB));
  std::optional<InternalEdges> b = triangle_half(fixed_masks_facing(*m_fixtureB, *m_fixtureA));
  if (!(a && b))
    for_contacts_between(*m_fixtureA->GetBody(), *m_fixtureB->GetBody(), [&](Contact& c) {
      if (&c == this || family_of(c.memory_.shapes) != Family::Triangles ||
          c.masks_.stamp != stamp || !c.masks_.settled() || c.masks_.fixtures != fixtures) {
        return true;
      }
      const InternalEdges m = c.memory_.internal_edges;
      if (!a && c.m_fixtureA == m_fixtureA) a = half(m, false);
      if (!a && c.m_fixtureB == m_fixtureA) a = half(m, true);
      if (!b && c.m_fixtureA == m_fixtureB) b = half(m, false);
      if (!b && c.m_fixtureB == m_fixtureB) b = half(m, true);
      return !(a && b);
    });
  if (!a) a = half_from_body(*m_fixtureA, epoch);
  if (!b) b = half_from_body(*m_fixtureB, epoch);
  const auto found = [](const b2Fixture& fixture, const b2Fixture& other) {
    const ShapeMasks m = masks_facing(polygon_edge_data(fixture), fixture, other);
    return InternalEdges{m.edges, m.closed_vertices};
  };
  return InternalEdges::pair(a ? *a : found(*m_fixtureA, *m_fixtureB),
                             b ? *b : found(*m_fixtureB, *m_fixtureA));
}

std::optional<InternalEdges> Contact::half_from_body(const b2Fixture& fixture,
                                                     std::uint8_t epoch) const {
  const b2Body& body = *fixture.GetBody();
  // Alone on its body, its triangle has no internal edge: `triangle_internal_edges` says so at
  // once.
  const bool alone = body.GetFixtureList() == &fixture && fixture.GetNext() == nullptr;
  if (alone || body.GetType() == b2_staticBody) return std::nullopt;
  for (const b2ContactEdge* e = body.GetContactList(); e; e = e->next) {
    const Contact* c = ours(e->contact);
    if (!c || c == this) continue;
    const bool as_a = c->m_fixtureA == &fixture;
    if (!as_a && c->m_fixtureB != &fixture) continue;
    if (const std::optional<InternalEdges> m = c->current_internal_edges(epoch)) {
      return half(*m, !as_a);
    }
  }
  return std::nullopt;
}

Contact::Contact(b2Fixture* fixture_a, int32 index_a, b2Fixture* fixture_b, int32 index_b)
    : b2Contact(fixture_a, index_a, fixture_b, index_b) {
  // The pair's family, once: the shapes of a fixture never change; and a two-sided edge's side,
  // where B is as the contact begins.
  const b2Shape& b = *fixture_b->GetShape();
  const auto* circle =
      b.m_type == b2Shape::e_circle ? static_cast<const b2CircleShape*>(&b) : nullptr;
  const auto* polygon = circle ? nullptr : static_cast<const b2PolygonShape*>(&b);
  if (fixture_a->GetType() == b2Shape::e_polygon) {
    const auto& a = *static_cast<const b2PolygonShape*>(fixture_a->GetShape());
    if (circle) {
      look_at_shapes(a, *circle, memory_);
    } else {
      look_at_shapes(a, *polygon, memory_);
    }
    return;
  }
  b2EdgeShape child;
  const b2EdgeShape& edge = edge_a(child);
  const b2Vec2 centroid_b = b2MulT(
      fixture_a->GetBody()->GetTransform(),
      b2Mul(fixture_b->GetBody()->GetTransform(), circle ? circle->m_p : polygon->m_centroid));
  if (circle) {
    look_at_shapes(edge, *circle, centroid_b, memory_);
  } else {
    look_at_shapes(edge, *polygon, centroid_b, memory_);
  }
}

namespace {

// Whether polygon fixture `fixture`'s masks against `other` need no finding, and which: its fixed
// edge data, or none for a polygon alone on a non-static body (its own outline); nothing when they
// must be found.
std::optional<ShapeMasks> masks_without_finding(const b2Fixture& fixture, const b2Fixture& other,
                                                bool* junction = nullptr) {
  const b2Body& body = *fixture.GetBody();
  const bool alone = body.GetFixtureList() == &fixture && fixture.GetNext() == nullptr;
  if (alone && body.GetType() != b2_staticBody) return ShapeMasks{};
  return fixed_masks_facing(fixture, other, junction);
}

// The masks polygon fixture `fixture`'s pairs with `other` read: its fixed edge data, else found
// now; against the body of `other` (`masks_facing`).
ShapeMasks masks_of(const b2Fixture& fixture, const b2Fixture& other) {
  if (const std::optional<ShapeMasks> fixed = fixed_masks_facing(fixture, other)) return *fixed;
  return masks_facing(polygon_edge_data(fixture), fixture, other);
}

}  // namespace

bool Contact::fixed_masks(ContactMemory& memory, bool* junction) const {
  const Family family = family_of(memory.shapes);
  if (family == Family::Triangles) {
    const std::optional<InternalEdges> fixed = fixed_internal_edges(junction);
    if (fixed) memory.internal_edges = *fixed;
    return fixed.has_value();
  }
  if (family == Family::Polygons || family == Family::PolygonAndCircle) {
    const std::optional<ShapeMasks> a = fixed_masks_facing(*m_fixtureA, *m_fixtureB, junction);
    if (!a) return false;
    const bool b_has_edges = family == Family::Polygons;
    const std::optional<ShapeMasks> b =
        b_has_edges ? fixed_masks_facing(*m_fixtureB, *m_fixtureA, junction) : ShapeMasks{};
    if (!b) return false;
    memory.internal_edges = {a->edges, a->closed_vertices};
    memory.masks_b = *b;
    return true;
  }
  // An edge: a one-sided edge's masks are its ghost vertices' (in `memory` since the first look at
  // the shapes), a two-sided edge's its fixed ends on B's side; B's its own.
  const std::optional<ShapeMasks> b =
      family == Family::EdgeAndPolygon ? masks_without_finding(*m_fixtureB, *m_fixtureA, junction)
                                       : ShapeMasks{};
  if (!b) return false;
  if (two_sided_edge(*m_fixtureA)) {
    const std::optional<EdgeEnds> ends = fixed_edge_ends(*m_fixtureA);
    if (!ends) return false;
    const ShapeMasks a = side_masks(*ends, on_edge_back(memory.shapes));
    memory.internal_edges = {a.edges, a.closed_vertices};
    memory.edge_ends = *ends;
  }
  memory.masks_b = *b;
  return true;
}

void Contact::find_masks(const FoundMasks& masks, std::uint8_t epoch, ContactMemory& memory) const {
  const Family family = family_of(memory.shapes);
  if (family == Family::Triangles) {
    memory.internal_edges = find_internal_edges(masks.stamp, masks.fixtures, epoch);
    return;
  }
  if (family == Family::Polygons || family == Family::PolygonAndCircle) {
    const ShapeMasks a = masks_of(*m_fixtureA, *m_fixtureB);
    memory.internal_edges = {a.edges, a.closed_vertices};
  } else if (two_sided_edge(*m_fixtureA)) {
    const std::optional<EdgeEnds> fixed = fixed_edge_ends(*m_fixtureA);
    memory.edge_ends = fixed ? *fixed : edge_ends(*m_fixtureA);
    const ShapeMasks a = side_masks(memory.edge_ends, on_edge_back(memory.shapes));
    memory.internal_edges = {a.edges, a.closed_vertices};
  }  // a one-sided edge's masks stay: its shape's
  const bool b_has_edges = family == Family::Polygons || family == Family::EdgeAndPolygon;
  memory.masks_b = b_has_edges ? masks_of(*m_fixtureB, *m_fixtureA) : ShapeMasks{};
}

template <class Pair>
[[gnu::noinline]] void Contact::keep_or_go_on(Contact& c, b2Manifold* manifold,
                                              const b2Transform& xf_a, const b2Transform& xf_b) {
  const Setting& setting = installation().setting;
  // Not kept: on with the pair and the pose it has (a chain's child edge is made by a call into
  // Box2D; the pose by two transforms).
  c.with_pair<Pair>(xf_a, xf_b, [&](const Pair& pair) {
    const PairPose pose = pose_of(pair, c.memory_);
    if (keep<Pair>(*manifold, setting, pose, c.memory_, c.recycling_, &c, &c.masks_)) return;
    if (!setting.backend) return pair.box2d(manifold);
    skip_or_answer_at(manifold, setting, pair, pose, c.memory_, &c, &c.masks_, &c.recycling_);
  });
}

template <class Pair>
[[gnu::noinline]] void Contact::skip_or_answer(Contact& c, b2Manifold* manifold,
                                               const b2Transform& xf_a, const b2Transform& xf_b) {
  c.with_pair<Pair>(xf_a, xf_b, [&](const Pair& pair) {
    detail::skip_or_answer(manifold, installation().setting, pair, c.memory_, &c, &c.masks_,
                           &c.recycling_);
  });
}

// Each act's function for each pair family, indexed by `ContactMemory::Shapes` (decided when the
// contact was made): one indirect call to the path of the pair's family, as Box2D v3's table of
// manifold functions per shape pair.
struct Contact::Paths {
  void (*keep_or_go_on)(Contact&, b2Manifold*, const b2Transform&, const b2Transform&);
  void (*skip_or_answer)(Contact&, b2Manifold*, const b2Transform&, const b2Transform&);
};

template <class Pair>
constexpr Contact::Paths Contact::paths_of() {
  return {&Contact::keep_or_go_on<Pair>, &Contact::skip_or_answer<Pair>};
}

const Contact::Paths Contact::paths[] = {
    paths_of<TrianglePair>(),       // Unchecked: never, a contact looks at its shapes when made
    paths_of<TrianglePair>(),       // Triangles
    paths_of<TrianglePair>(),       // InvalidTriangles
    paths_of<TrianglePair>(),       // UnvalidatedTriangles
    paths_of<PolygonPair>(),        // Polygons
    paths_of<PolygonPair>(),        // InvalidPolygons
    paths_of<PolygonCirclePair>(),  // PolygonAndCircle
    paths_of<PolygonCirclePair>(),  // InvalidPolygonAndCircle
    paths_of<EdgePolygonPair>(),    // EdgeAndPolygon
    paths_of<EdgePolygonPair>(),    // EdgeBackAndPolygon
    paths_of<EdgePolygonPair>(),    // InvalidEdgeAndPolygon
    paths_of<EdgeCirclePair>(),     // EdgeAndCircle
    paths_of<EdgeCirclePair>(),     // EdgeBackAndCircle
    paths_of<EdgeCirclePair>(),     // InvalidEdgeAndCircle
};
static_assert(static_cast<int>(ContactMemory::Shapes::InvalidEdgeAndCircle) == 13,
              "one path per value of ContactMemory::Shapes");

namespace {

// Asks the processor for the line at `p` ahead of its use; nothing where the compiler has no hint.
inline void fetch_ahead(const void* p) {
#if defined(__GNUC__)
  __builtin_prefetch(p);
#else
  static_cast<void>(p);
#endif
}

// The bodies of the contact after `contact` in its world's list, fetched ahead of Box2D's walk
// of that list (`b2ContactManager::Collide` reads each contact's bodies through its fixtures):
// a hint, no answer changes (docs/measurements.md, "The walk's next bodies fetched ahead").
void fetch_next_bodies(const b2Contact& contact) {
  const b2Contact* next = contact.GetNext();
  if (!next) return;
  fetch_ahead(next->GetFixtureA()->GetBody());
  fetch_ahead(next->GetFixtureB()->GetBody());
}

}  // namespace

// One evaluation: keep, else skip or answer (evaluation.hpp), on the path of the pair's family;
// the next contact's bodies fetched first, so that their loads overlap this evaluation.
void Contact::Evaluate(b2Manifold* manifold, const b2Transform& xf_a, const b2Transform& xf_b) {
  fetch_next_bodies(*this);
  if (manifold->pointCount == 0 && EdgePair::accepted_shapes(memory_)) face_edge(xf_a, xf_b);
  const Paths& path = paths[static_cast<int>(memory_.shapes)];
  if (recycling_.slack > 0) return path.keep_or_go_on(*this, manifold, xf_a, xf_b);
  path.skip_or_answer(*this, manifold, xf_a, xf_b);
}

void Contact::face_edge(const b2Transform& xf_a, const b2Transform& xf_b) {
  const b2Shape* a = m_fixtureA->GetShape();
  if (a->m_type != b2Shape::e_edge) return;
  const auto& edge = *static_cast<const b2EdgeShape*>(a);
  if (edge.m_oneSided) return;
  const b2Shape* b = m_fixtureB->GetShape();
  const b2Vec2& centroid = b->m_type == b2Shape::e_circle
                               ? static_cast<const b2CircleShape*>(b)->m_p
                               : static_cast<const b2PolygonShape*>(b)->m_centroid;
  face_edge_side(memory_, on_back_of(edge, b2MulT(xf_a, b2Mul(xf_b, centroid))));
}

void Contact::fresh_manifold(b2Manifold* manifold) const {
  ContactMemory memory = memory_;  // its masks and warm start, not its state
  FoundMasks masks = masks_;
  Setting setting = installation().setting;
  setting.never_recompute = false;
  const b2Transform& xf_a = m_fixtureA->GetBody()->GetTransform();
  const b2Transform& xf_b = m_fixtureB->GetBody()->GetTransform();
  const auto afresh = [&](const auto& pair) {
    detail::skip_or_answer(manifold, setting, pair, memory, this, &masks);
  };
  switch (family_of(memory.shapes)) {
    case Family::Triangles:
      return with_pair<TrianglePair>(xf_a, xf_b, afresh);
    case Family::Polygons:
      return with_pair<PolygonPair>(xf_a, xf_b, afresh);
    case Family::PolygonAndCircle:
      return with_pair<PolygonCirclePair>(xf_a, xf_b, afresh);
    case Family::EdgeAndPolygon:
      return with_pair<EdgePolygonPair>(xf_a, xf_b, afresh);
    case Family::EdgeAndCircle:
      return with_pair<EdgeCirclePair>(xf_a, xf_b, afresh);
  }
}

}  // namespace dyop::box2d::detail

namespace dyop::box2d {

void measurement::evaluate_afresh(const b2Contact& contact, b2Manifold* manifold) {
  manifold->pointCount = 0;
  const b2Fixture* fa = contact.GetFixtureA();
  const b2Fixture* fb = contact.GetFixtureB();
  if (detail::taken_pair_index(fa->GetType(), fb->GetType()) < 0) return;
  auto* c = const_cast<b2Contact*>(&contact);
  if (const detail::Contact* ours = detail::Contact::ours(c)) {
    ours->fresh_manifold(manifold);
    return;
  }
  // Box2D's own contact: its `Evaluate`, on a copy (it changes nothing but the manifold).
  const b2Transform& xf_a = fa->GetBody()->GetTransform();
  const b2Transform& xf_b = fb->GetBody()->GetTransform();
  const b2Shape* a = fa->GetShape();
  const b2Shape* b = fb->GetShape();
  // Each shape cast to what its type says, and only then (a cast to another shape's class is
  // undefined, and UBSan says so).
  const bool circle = b->m_type == b2Shape::e_circle;
  if (a->m_type == b2Shape::e_polygon) {
    const auto* polygon_a = static_cast<const b2PolygonShape*>(a);
    if (circle) {
      return b2CollidePolygonAndCircle(manifold, polygon_a, xf_a,
                                       static_cast<const b2CircleShape*>(b), xf_b);
    }
    return b2CollidePolygons(manifold, polygon_a, xf_a, static_cast<const b2PolygonShape*>(b),
                             xf_b);
  }
  b2EdgeShape child;
  const b2EdgeShape* edge = &child;
  if (a->m_type == b2Shape::e_chain) {
    static_cast<const b2ChainShape*>(a)->GetChildEdge(&child, contact.GetChildIndexA());
  } else {
    edge = static_cast<const b2EdgeShape*>(a);
  }
  if (circle) {
    return b2CollideEdgeAndCircle(manifold, edge, xf_a, static_cast<const b2CircleShape*>(b), xf_b);
  }
  b2CollideEdgeAndPolygon(manifold, edge, xf_a, static_cast<const b2PolygonShape*>(b), xf_b);
}

std::optional<InternalEdges> contact_internal_edges(const b2Contact& contact) {
  const auto* ours = detail::Contact::ours(const_cast<b2Contact*>(&contact));
  if (!ours) return std::nullopt;
  const std::optional<InternalEdges> a = detail::fixed_edges(*contact.GetFixtureA());
  const std::optional<InternalEdges> b = detail::fixed_edges(*contact.GetFixtureB());
  if (a && b) return InternalEdges::pair(*a, *b);
  return ours->current_internal_edges(detail::installation().setting.epoch);
}

void forget_internal_edges(b2World& world) {
  for (b2Contact* c = world.GetContactList(); c; c = c->GetNext()) {
    if (detail::Contact* ours = detail::Contact::ours(c)) {
      ours->forget_internal_edges();
    }
  }
}

}  // namespace dyop::box2d
