#pragma once
// Internal: the plug-in's Box2D contact, for every shape pair it takes (`taken_pairs`): a pair
// family's evaluation (evaluation.hpp) with the masks the contact finds or reads for it.

#include <box2d/b2_body.h>
#include <box2d/b2_chain_shape.h>
#include <box2d/b2_contact.h>
#include <box2d/b2_contact_manager.h>
#include <box2d/b2_fixture.h>
#include <box2d/b2_world.h>

#include <cstring>
#include <optional>
#include <type_traits>

#include "dyop/box2d.hpp"
#include "edge_data.hpp"
#include "found_masks.hpp"
#include "installation.hpp"
#include "pair_families.hpp"
#include "recycling.hpp"

namespace dyop::box2d::detail {

// `h` with `body`'s frame folded in when it is static (its type too: a body made static or not
// folds differently); a moving body's frame is not part of any mask. The frame as two 64-bit
// words, one multiplication each (`mix_word`): every kept manifold of a pair with a static body
// pays it.
inline std::uint32_t fold_static_frame(std::uint32_t h, const b2Body& body) {
  if (body.GetType() != b2_staticBody) return h;
  std::uint64_t words[2];
  static_assert(sizeof(b2Transform) == sizeof words, "b2Transform is four floats");
  std::memcpy(words, &body.GetTransform(), sizeof words);
  std::uint64_t x = h;
  for (const std::uint64_t w : words) x = mix_word(x, w);
  return static_cast<std::uint32_t>(x >> 32);
}

// Where the body of `other` is for the masks of `fixture`: its centre of mass in `fixture`'s body
// frame. The body's, not its fixture's: every contact between two bodies sees the same masks, as
// the contacts that lend each other masks assume (`Contact::find_internal_edges`).
inline b2Vec2 body_in_frame_of(const b2Fixture& other, const b2Fixture& fixture) {
  return b2MulT(fixture.GetBody()->GetTransform(), other.GetBody()->GetWorldCenter());
}

// `data`'s masks of polygon fixture `fixture` as the rule applies them against the body of
// `other`: with what its junction hides from that body (`masks_facing`).
inline ShapeMasks masks_facing(const PolygonEdgeData& data, const b2Fixture& fixture,
                               const b2Fixture& other) {
  if (data.junction.vertex == Junction::none) return data.masks;
  return masks_facing(data, fixture, body_in_frame_of(other, fixture));
}

// The fixed masks of polygon fixture `fixture` against the body of `other` (`masks_facing`), or
// nothing: never fixed. `junction`, if given, is set when they depend on where that body is.
inline std::optional<ShapeMasks> fixed_masks_facing(const b2Fixture& fixture,
                                                    const b2Fixture& other,
                                                    bool* junction = nullptr) {
  const std::optional<PolygonEdgeData> record = fixed_polygon_record(fixture);
  if (!record) return std::nullopt;
  if (junction && record->junction.vertex != Junction::none) *junction = true;
  return masks_facing(*record, fixture, other);
}

// Box2D's contact for a pair the plug-in takes, made while it is installed: `Evaluate` is the
// plug-in's evaluation with whatever is installed at the time (Box2D's own answer once
// uninstalled). Holds no heap memory (b2World's destructor frees contacts without running their
// destructors): what the pair remembers between steps is its `ContactMemory`, inside the object.
// Last step's manifold needs no copy: Box2D passes it back to `Evaluate` in `m_manifold`.
class Contact final : public b2Contact {
 public:
  // Box2D's create / destroy functions for the registry (b2ContactCreateFcn / b2ContactDestroyFcn).
  static b2Contact* create(b2Fixture* fixture_a, int32 index_a, b2Fixture* fixture_b, int32 index_b,
                           b2BlockAllocator* allocator);
  // Frees any polygon contact as what it is: ours here, Box2D's own through Box2D's own function.
  static void destroy(b2Contact* contact, b2BlockAllocator* allocator);

  void Evaluate(b2Manifold* manifold, const b2Transform& xf_a, const b2Transform& xf_b) override;

  // The plug-in's contact `c` is, or nullptr (Box2D's own, made before an install).
  static Contact* ours(b2Contact* c);

  // What its internal-edge masks would be found under now (`FoundMasks::stamp`): install `epoch`,
  // the count of fixed records written (a fixture of it may have been fixed since: its fixed data
  // then decides, `fixed_masks`) and the frames of its static bodies, never 0 nor
  // `FoundMasks::fixed_stamp`. Why a static body's
  // frame: static bodies share edges with each other, so moving one (`SetTransform`) or making it
  // static or not (`SetType`) changes its triangles' masks, and nothing else in the world records a
  // move within the broad phase's margin. Folded with the install so that a change of either gives
  // another stamp (short of a 16-bit collision). Inline: every evaluation with the rule on that
  // keeps a manifold or answers afresh asks.
  std::uint16_t internal_edges_stamp(std::uint8_t epoch) const {
    std::uint32_t h = epoch ^ (fixed_records_written.load(std::memory_order_relaxed) << 8);
    h = fold_static_frame(h, *m_fixtureA->GetBody());
    h = fold_static_frame(h, *m_fixtureB->GetBody());
    const auto stamp = static_cast<std::uint16_t>(h ^ (h >> 16));
    if (stamp == 0) return 1;
    return stamp != FoundMasks::fixed_stamp ? stamp : FoundMasks::fixed_stamp - 1;
  }

  // The world's count of fixture proxies, its low 16 bits (`FoundMasks::fixtures`). Why: it is the
  // world's own and moves whenever a fixture of the world is created or destroyed (a fixture added
  // next to a triangle, or one taken away from under a body resting elsewhere on its neighbour,
  // changes that neighbour's masks), in O(1). A change far from a pair matters only once the pair
  // has moved toward it: from then on the pair follows its motion (`FoundMasks::motion`).
  std::uint16_t world_fixtures() const {
    return static_cast<std::uint16_t>(
        m_fixtureA->GetBody()->GetWorld()->GetContactManager().m_broadPhase.GetProxyCount());
  }

  // The pair's internal-edge masks (`ContactMemory::internal_edges`) under `stamp` (install
  // `epoch`) and `fixtures` (`world_fixtures`): each triangle's half taken from another contact
  // between the same two bodies that has the same fixture and masks found under both, settled
  // (both contacts were evaluated at the same steps, and saw the same counts); for a non-static
  // body's triangle, else
  // from any contact of its body with that fixture whose masks still hold (`half_from_body`);
  // else found from the fixture's edge group (`triangle_internal_edges`). A box on a ground finds
  // a ground triangle's masks once for all its fixtures touching it, and a body in a pile finds
  // each of its triangles' masks once for all the bodies it touches.
  InternalEdges find_internal_edges(std::uint16_t stamp, std::uint16_t fixtures,
                                    std::uint8_t epoch) const;

  // Its stamp moved from `seen` (`FoundMasks::stamp`, 0: none) to another. Seen
  // before, with a static body in the pair: its static neighbourhood changed, and the pair's
  // other contacts with static bodies find their masks again too (see
  // `static_neighbourhood_changed` in the .cpp).
  void internal_edges_stamp_moved(std::uint16_t seen) const;

  // The manifold it would compute now with nothing kept (`measurement::evaluate_afresh`), its
  // state unchanged.
  void fresh_manifold(b2Manifold* manifold) const;

  // True when a body of its pair is static.
  bool with_static_body() const {
    return m_fixtureA->GetBody()->GetType() == b2_staticBody ||
           m_fixtureB->GetBody()->GetType() == b2_staticBody;
  }

  // Its masks when they hold under install `epoch` as the world is now (found under the stamp and
  // the fixture count it would have now, and the count never seen to move since: it may have
  // come back by other changes), else nothing.
  std::optional<InternalEdges> current_internal_edges(std::uint8_t epoch) const {
    if (family_of(memory_.shapes) != Family::Triangles || !masks_.settled() || masks_.stamp == 0 ||
        masks_.stamp != internal_edges_stamp(epoch) || masks_.fixtures != world_fixtures()) {
      return std::nullopt;
    }
    return memory_.internal_edges;
  }

  // Its pair's masks from the fixed edge data of its two fixtures (`fix_internal_edges`), when
  // both have it: then nothing is found, stamped or followed for the pair. For a pair of
  // triangles (`ContactMemory::Shapes`).
  std::optional<InternalEdges> fixed_internal_edges(bool* junction = nullptr) const {
    const std::optional<ShapeMasks> a = fixed_masks_facing(*m_fixtureA, *m_fixtureB, junction);
    if (!a) return std::nullopt;
    const std::optional<ShapeMasks> b = fixed_masks_facing(*m_fixtureB, *m_fixtureA, junction);
    if (!b) return std::nullopt;
    return InternalEdges::pair({a->edges, a->closed_vertices}, {b->edges, b->closed_vertices});
  }

  // Its pair's masks, for the pair's family (`memory.shapes`), into `memory` when nothing need be
  // found: each fixture's fixed edge data (`fix_internal_edges`), a one-sided edge's own (its
  // ghost vertices, read by the family), a circle's none; false (nothing written) otherwise.
  // Every answer with the rule on asks, unless the masks it read last still hold. `junction` is
  // set when they depend on where the bodies are (a polygon's junction with two-sided edges).
  bool fixed_masks(ContactMemory& memory, bool* junction) const;
  // Its pair's masks found now (`masks`: what it found before, under install `epoch`) into
  // `memory`: a triangle pair's by `find_internal_edges`, others fixture by fixture.
  void find_masks(const FoundMasks& masks, std::uint8_t epoch, ContactMemory& memory) const;

  // Its next evaluation computes afresh, whatever it keeps (its fixed edge data was refreshed).
  void recompute() { recycling_.slack = 0; }

  // Its internal-edge masks are found again when next needed (a fixture near it changed).
  void forget_internal_edges() { masks_.stamp = 0; }

  // True when its masks were found under a stamp that no longer holds under `epoch` and a body of
  // the pair is static: the static bodies near it changed (or the world's fixtures).
  bool static_stamp_stale(std::uint8_t epoch) const;

 private:
  Contact(b2Fixture* fixture_a, int32 index_a, b2Fixture* fixture_b, int32 index_b);

  // The masks of `fixture`'s triangle (one of its two), bits 0..2, from another contact of its
  // body with the same fixture whose masks were found under the stamp that contact would have
  // now, or nothing. Only for a non-static body: its triangles share edges with its own
  // triangles alone, so their masks do not depend on the other body of a contact, and its
  // contact list is short (a static body's spans the world).
  std::optional<InternalEdges> half_from_body(const b2Fixture& fixture, std::uint8_t epoch) const;

  // A pair of a two-sided edge that touched nothing last step takes its side afresh from B's
  // centroid (`face_edge_side`): the side is decided as the pair starts touching, and kept while
  // it touches but for going around an end (`EdgePair::faces_away`).
  void face_edge(const b2Transform& xf_a, const b2Transform& xf_b);

  // Its edge (fixture A of an edge family): the fixture's own, or its chain's child edge, made in
  // `child`.
  const b2EdgeShape& edge_a(b2EdgeShape& child) const {
    const b2Shape* shape = m_fixtureA->GetShape();
    if (shape->m_type == b2Shape::e_edge) return *static_cast<const b2EdgeShape*>(shape);
    static_cast<const b2ChainShape*>(shape)->GetChildEdge(&child, m_indexA);
    return child;
  }
  // Calls `f(pair)` with its pair as its family's (`TrianglePair`, ..., `EdgeCirclePair`) at the
  // bodies' transforms `xf_a`, `xf_b`.
  template <class Pair, class F>
  [[gnu::always_inline]] void with_pair(const b2Transform& xf_a, const b2Transform& xf_b,
                                        const F& f) const {
    const b2Shape* b = m_fixtureB->GetShape();
    using B = std::remove_cv_t<std::remove_reference_t<decltype(Pair::b)>>;
    const B& shape_b = *static_cast<const B*>(b);
    if constexpr (std::is_base_of_v<EdgePair, Pair>) {
      b2EdgeShape child;
      f(Pair(edge_a(child), xf_a, shape_b, xf_b));
    } else {
      f(Pair(*static_cast<const b2PolygonShape*>(m_fixtureA->GetShape()), xf_a, shape_b, xf_b));
    }
  }

  // `Evaluate`'s two paths for contact `c` of a pair family: keep, else skip or answer; skip or
  // answer. Static: `Paths` holds plain function pointers.
  template <class Pair>
  static void keep_or_go_on(Contact& c, b2Manifold* manifold, const b2Transform& xf_a,
                            const b2Transform& xf_b);
  template <class Pair>
  static void skip_or_answer(Contact& c, b2Manifold* manifold, const b2Transform& xf_a,
                             const b2Transform& xf_b);
  struct Paths;
  template <class Pair>
  static constexpr Paths paths_of();
  static const Paths paths[];

  ContactMemory memory_;
  FoundMasks masks_;
  ManifoldRecycling recycling_;
};

// Makes every contact of the plug-in with `fixture` compute afresh at its next evaluation.
void recompute_contacts_of(const b2Fixture& fixture);

}  // namespace dyop::box2d::detail
