#pragma once
// Internal: the plug-in's one evaluation of a pair, for every pair family (pair_families.hpp), for
// a world's contact and for the single-pair entry points (`collide_polygons`,
// `collide_polygon_and_circle`) alike: keep the last manifold, else skip, else answer. Each act is
// written once here; what differs between families (a face's separation, the masks, the manifold
// function) is the family's. Which skips apply, where the masks come from and what is counted are
// decided here and nowhere else.
//
// Inline: most evaluations in a world end in a kept manifold or a skip that costs a few dozen
// instructions, and Box2D's own contact answers a pair apart after one face test, so every call,
// every register saved and every transformed vertex counts: a world's contact runs each act in
// its own function for its pair's family (`Contact::Evaluate`), and the answer is out of
// line, so that a keep or a skip pays no register saves for the acts after it.

#include <box2d/b2_collision.h>

#include <algorithm>
#include <limits>
#include <optional>
#include <type_traits>

#include "dyop/box2d.hpp"
#include "found_masks.hpp"
#include "installation.hpp"
#include "pair_families.hpp"
#include "recycling.hpp"
#include "stats.hpp"
#include "contact.hpp"

namespace dyop::box2d::detail {

// True unless `r` (with `Apart::Gap`) is apart beyond `margin` with an empty manifold: such an
// answer is the answer under any masks (`Query::internal_edges`, `ConvexQuery`'s masks,
// `Apart::Gap`; tested over every input class and edge mask in the library's `InternalEdgesRule`
// test), for every pair family. (The face hysteresis may keep a point on A's face while B's face
// separates the pair beyond the margin: that point is the rule's to judge.)
inline bool needs_masks(const Result<float>& r, float margin) {
  return !(r.status == Status::Separated && r.separation > margin && r.manifold.point_count == 0);
}

// True when a world's contact `contact` (the rule on) holds no masks that hold now under the
// setting's install and the world as it is (see evaluation.cpp); its stamp and fixture count are
// brought up to date. `recycling`: the pose of its last answer afresh, nullptr for none.
bool masks_put_off(const Setting& setting, const PairPose& pose, FoundMasks& masks,
                   const Contact& contact, const ManifoldRecycling* recycling);

// Where `pair` is now (`memory`: its bounding radii).
template <class Pair>
[[gnu::always_inline]] inline PairPose pose_of(const Pair& pair, const ContactMemory& memory) {
  const b2Transform b_in_a = b2MulT(pair.xf_a, pair.xf_b);
  return {b_in_a, b2Mul(b_in_a, pair.centroid_b()), pair.margin(), memory.radius_sum};
}

// The manifold in `manifold` may stay (`Config::recycle_distance`, or the measurement floor's
// `Setting::never_recompute`): see recycling.hpp. A change of the pair's internal-edge masks
// (their stamp moved, or they were forgotten) recomputes; a change of the world's fixture count
// alone recomputes only once the pair may have moved toward it (`masks_hold`): one near the pair
// makes or ends a contact with one of its bodies, which forgets the masks at once. `rule`: the
// internal-edge rule is in force for the pair.
inline bool keeps_manifold(const Setting& setting, bool rule, const PairPose& pose,
                           const ManifoldRecycling& recycling, const Contact* contact,
                           FoundMasks* masks) {
  if (setting.never_recompute) return recycling.slack > 0 && recycling.epoch == setting.epoch;
  if (!recycling.keeps(pose.b_in_a.q, pose.centroid_b_in_a, pose.lever(), setting.epoch)) {
    return false;
  }
  if (!rule || !contact) return true;
  if (masks->fixed()) return true;  // changed only by a refresh, which recomputes
  if (masks->stamp != contact->internal_edges_stamp(setting.epoch)) return false;
  // Put off: the manifold was answered without masks (apart beyond the margin, the same under any).
  if (!masks->found()) return true;
  notice_fixture_count(*masks, contact->world_fixtures());
  return masks_hold(*masks, setting.config.recycle_distance);
}

// Keep: true when a world's contact keeps the manifold in `manifold` (see `keeps_manifold`),
// counted. Otherwise its pose stays until an answer replaces it, or a skip loses it. Only a
// solver's answer remembers a pose; an uninstall keeps the epoch, hence the method's check.
template <class Pair>
[[gnu::always_inline]] inline bool keep(const b2Manifold& manifold, const Setting& setting,
                                        const PairPose& pose, const ContactMemory& memory,
                                        const ManifoldRecycling& recycling, const Contact* contact,
                                        FoundMasks* masks) {
  if (!(recycling.slack > 0) || !setting.method ||
      !keeps_manifold(setting, Pair::rule(setting), pose, recycling, contact, masks)) {
    return false;
  }
  ThreadCounters& count = counters();
  Pair::count(count, setting, memory);
  count.recycled.add();
  if (manifold.pointCount > 0) count.manifolds.add();
  return true;
}

// The skip that proves the pair's manifold empty, if any: the bounding circles farther apart than
// a manifold reaches (`Config::bounds_early_out`; compared squared: no root), or the face the
// solver last judged the pair on still separating it beyond a manifold's reach
// (`Config::warm_axis`; see `face_reach`).
template <class Pair>
[[gnu::always_inline]] inline std::optional<Skip> skip_of(const Setting& setting, const Pair& pair,
                                                          const PairPose& pose,
                                                          const ContactMemory& memory) {
  if (setting.config.bounds_early_out) {
    const float reach_sum = pose.radius_sum + reach(pose.margin);
    if ((pose.centroid_b_in_a - pair.centroid_a()).LengthSquared() > reach_sum * reach_sum) {
      return Skip::Bounds;
    }
  }
  if (setting.config.warm_axis && Pair::solver_on(setting) && memory.last_face >= 0 &&
      pair.face_separation(memory.last_face, pose) > face_reach(pose.margin)) {
    return Skip::WarmAxis;
  }
  return std::nullopt;
}

// Skip: true when the pair, nothing kept, is skipped (`skip_of`): its manifold emptied, its pose
// lost (`recycling`, nullptr for a single pair), counted last (the thread's first count makes its
// counters: a call, with nothing else left to keep across it).
template <class Pair>
[[gnu::always_inline]] inline bool skip(b2Manifold* manifold, const Setting& setting,
                                        const Pair& pair, const PairPose& pose,
                                        const ContactMemory& memory, ManifoldRecycling* recycling) {
  const std::optional<Skip> reason = skip_of(setting, pair, pose, memory);
  if (!reason) return false;
  manifold->pointCount = 0;
  if (recycling) {
    if (setting.never_recompute && setting.method) {
      recycling->remember(pose.b_in_a.q, pose.centroid_b_in_a, 1, setting.epoch);
    } else {
      recycling->lose_pose();
    }
  }
  if constexpr (std::is_base_of_v<ExactPair, Pair>) {
    ThreadCounters& count = counters();
    Pair::count(count, setting, memory);
    ExactPair::count_skip_reason(count, *reason);
  } else {
    Pair::count_skip(counters(), setting, memory, *reason);
  }
  return true;
}

// Appends the answer of triangle pair `pair` about to be written (`memory` as the answer began,
// but for the masks: `q`'s, those the solver read) to `answers` (`measurement::record_answers`).
[[gnu::noinline]] inline void record_answer(std::vector<measurement::RecordedAnswer>& answers,
                                            const TrianglePair& pair, const ContactMemory& memory,
                                            const TrianglePair::Query& q) {
  measurement::RecordedAnswer a{pair.a, pair.b, pair.xf_a, pair.xf_b, memory};
  a.memory.internal_edges = q.internal_edges;
  answers.push_back(a);
}

// The query of the solver's answer for the pair, with the internal-edge rule's masks taken: both
// fixtures' fixed edge data; else a world's contact's own masks when they hold, else none yet
// (`put_off`: found only once an answer without them is not apart beyond the skins, by
// `find_put_off_masks`); a single pair's as its caller set them in `memory`. `contact`: the world's
// contact, whose memory is `memory` and `masks`, nullptr for a single pair; `recycling`: its kept
// pose (it bounds how far the pair moved since: `FoundMasks::motion`), nullptr for none. The
// answer itself is the caller's, so that it is built where it is read.
template <class Pair>
struct Asked {
  typename Pair::Query q;
  bool put_off = false;     // the masks are still to be found
  bool faces_away = false;  // B, the masks known, faces another edge than A: no question
};

template <class Pair>
[[gnu::always_inline]] inline Asked<Pair> ask(const Setting& setting, const Pair& pair,
                                              const PairPose& pose, ContactMemory& memory,
                                              const Contact* contact, FoundMasks* masks,
                                              const ManifoldRecycling* recycling) {
  Asked<Pair> asked;
  typename Pair::Query& q = asked.q;
  q.level = Level::Manifold;
  q.margin = pose.margin;  // the skins: speculative, as Box2D's
  q.face_hysteresis = Pair::hysteresis(pose);
  q.apart = Apart::Gap;  // beyond the skins a manifold is empty: no distance is needed
  q.witnesses = false;   // Box2D's solver reads the manifold alone
  // A lead of twice the distance or more never limits the keeping (`face_room`).
  q.lead_reach = setting.recycles() ? 2 * setting.config.recycle_distance : 0;
  if (Pair::rule(setting) && contact) {
    // Fixed masks read since the last record was written, free of the poses, hold as they are;
    // masks found under the stamp the contact has now were found since too: no fixture of the
    // pair was fixed since. Else its fixed data first, then the masks it finds.
    const std::uint16_t records = fixed_records_stamp();
    if (!masks->fixed_since(records)) {
      const bool found_since =
          masks->found() && masks->stamp == contact->internal_edges_stamp(setting.epoch);
      bool junction = false;
      if (!found_since && contact->fixed_masks(memory, &junction)) {
        masks->fixed_now(records, junction);
      } else {
        asked.put_off = masks_put_off(setting, pose, *masks, *contact, recycling);
      }
    }
    if (!asked.put_off) {
      asked.faces_away = pair.faces_away(pose, memory);
      if (!asked.faces_away) pair.take_masks(q, memory);
    }
  } else if (Pair::rule(setting)) {
    asked.faces_away = pair.faces_away(pose, memory);
    if (!asked.faces_away) pair.take_masks(q, memory);
  }
  return asked;
}

// The answer `r` to a query whose masks were put off (`Asked::put_off`): the same answer unless it
// needs masks (`needs_masks`); then the contact finds them and the solver answers again with them.
// False when B, the masks found, faces another edge than A.
template <class Pair>
[[gnu::noinline]] bool find_put_off_masks(const Setting& setting, const Pair& pair,
                                          const PairPose& pose, ContactMemory& memory,
                                          const Contact& contact, FoundMasks& masks,
                                          typename Pair::Query& q, Result<float>& r) {
  if (!needs_masks(r, q.margin)) return true;
  masks.found_now(contact.world_fixtures());
  contact.find_masks(masks, setting.epoch, memory);
  if (pair.faces_away(pose, memory)) return false;
  pair.take_masks(q, memory);
  if (Pair::any_masks(q)) r = pair.solve(setting, q, pose, memory);
  return true;
}

// Remembers the pose of a manifold just answered: kept while the pair moves less than the
// setting's distance (a share of it with a static body: `static_pair_share`); one with points
// also no farther than `face_room` (how far the pair may move before another face could beat its
// reference face by more than the hysteresis), an empty one no farther than `gap`
// (how far the pair may move before a manifold could have points: a lower bound, so that no new
// contact is missed); never below 0 (that marks a skip: `ManifoldRecycling::lose_pose`).
inline void remember(const Setting& setting, const PairPose& pose, const b2Manifold& manifold,
                     float gap, const Contact* contact, ManifoldRecycling& recycling,
                     float face_room = std::numeric_limits<float>::infinity()) {
  if (!setting.recycles()) return;
  float slack = 1;
  if (!setting.never_recompute) {
    const bool static_pair = contact && contact->with_static_body();
    const float distance = setting.config.recycle_distance * (static_pair ? static_pair_share : 1);
    slack = std::max(0.0f, std::min(distance, manifold.pointCount > 0 ? face_room : gap));
  }
  recycling.remember(pose.b_in_a.q, pose.centroid_b_in_a, slack, setting.epoch);
}

// How far a pair may move before another face could beat the reference face of its manifold by
// more than `hysteresis` (`Manifold::lead`: every overlap moves at most as far as the pair, the
// difference of two at most twice that): a kept manifold's depth then stays within the hysteresis
// of the least overlap, the bound a fresh answer keeps.
inline float face_room(float hysteresis, float lead) { return (hysteresis + lead) / 2; }

// Answer, once nothing was kept or skipped: the solver's answer to the query `ask` makes, its pose
// remembered for keeping (`recycling`: the world's contact's, nullptr for a single pair); Box2D's
// function where the family's solver is off under the setting (its answer, not a fallback), for
// shapes the solver refuses and for a method that could not answer (a counted fallback, so that
// the world goes on).
template <class Pair>
[[gnu::noinline]] void answer(b2Manifold* manifold, const Setting& setting, const Pair& pair,
                              const PairPose& pose, ContactMemory& memory, const Contact* contact,
                              FoundMasks* masks, ManifoldRecycling* recycling) {
  ThreadCounters& count = counters();
  Pair::count(count, setting, memory);
  if (Pair::solver_on(setting)) {
    if (pair.accepted(memory)) {
      // Box2D's one-sided rules (`EdgePair::excluded`): no contact while B keeps out of reach.
      if (const std::optional<float> gap = pair.excluded(pose)) {
        manifold->pointCount = 0;
        if (recycling) remember(setting, pose, *manifold, *gap, contact, *recycling);
        return;
      }
      const auto faces_away = [&] {  // B faces another edge: no contact, judged afresh next time
        manifold->pointCount = 0;
        memory.last_face = -1;
        if (recycling) remember(setting, pose, *manifold, 0, contact, *recycling);
      };
      Asked<Pair> asked = ask(setting, pair, pose, memory, contact, masks, recycling);
      if (asked.faces_away) return faces_away();
      Result<float> r = pair.solve(setting, asked.q, pose, memory);
      if (asked.put_off &&
          !find_put_off_masks(setting, pair, pose, memory, *contact, *masks, asked.q, r)) {
        return faces_away();
      }
      if (Pair::any_masks(asked.q)) count.internal_edge_pairs.add();
      if constexpr (std::is_same_v<Pair, TrianglePair>) {
        if (count.answers) record_answer(*count.answers, pair, memory, asked.q);
      }
      if (r.status != Status::Invalid) {
        memory.last_face = judged_face(r.manifold, pair.count_a());
        pair.write(manifold, r.manifold, pose);
        if (manifold->pointCount > 0) count.manifolds.add();
        if (recycling) {
          // The gap bounds only an empty manifold's keeping (`remember`).
          const float gap = manifold->pointCount > 0 ? 0 : pair.gap(r, pose, memory);
          remember(setting, pose, *manifold, gap, contact, *recycling,
                   face_room(Pair::hysteresis(pose), r.manifold.lead));
        }
        return;
      }
    }
    count.fallbacks.add();
  }
  pair.box2d(manifold);
  if (manifold->pointCount > 0) count.manifolds.add();
}

// The answers of the families beyond two triangles are compiled once, in evaluation.cpp, for the
// world's contact and the entry points alike: their solvers are instantiated for several vertex
// counts each (`PolygonPair::solve`), which costs seconds of build per translation unit.
extern template void answer<PolygonPair>(b2Manifold*, const Setting&, const PolygonPair&,
                                         const PairPose&, ContactMemory&, const Contact*,
                                         FoundMasks*, ManifoldRecycling*);
extern template void answer<PolygonCirclePair>(b2Manifold*, const Setting&,
                                               const PolygonCirclePair&, const PairPose&,
                                               ContactMemory&, const Contact*, FoundMasks*,
                                               ManifoldRecycling*);
extern template void answer<EdgePolygonPair>(b2Manifold*, const Setting&, const EdgePolygonPair&,
                                             const PairPose&, ContactMemory&, const Contact*,
                                             FoundMasks*, ManifoldRecycling*);
extern template void answer<EdgeCirclePair>(b2Manifold*, const Setting&, const EdgeCirclePair&,
                                            const PairPose&, ContactMemory&, const Contact*,
                                            FoundMasks*, ManifoldRecycling*);

// Skip, else answer, the pair at `pose` (`pose_of`), installed; see `skip_or_answer`.
template <class Pair>
[[gnu::always_inline]] inline void skip_or_answer_at(b2Manifold* manifold, const Setting& setting,
                                                     const Pair& pair, const PairPose& pose,
                                                     ContactMemory& memory, const Contact* contact,
                                                     FoundMasks* masks,
                                                     ManifoldRecycling* recycling) {
  if (skip(manifold, setting, pair, pose, memory, recycling)) return;
  answer(manifold, setting, pair, pose, memory, contact, masks, recycling);
}

// An evaluation, once nothing was kept (or with nothing to keep): skip, else answer; uninstalled,
// Box2D's own answer, uncounted, exactly as Box2D's own contact. `memory` is the pair's state, its
// shapes looked at (`look_at_shapes`), updated; `contact` the world's contact it belongs to, if
// any, `masks` what it found of its masks and `recycling` its kept manifold's pose (all nullptr
// for a single pair). A world's contact tries `keep` first (`Contact::Evaluate`).
template <class Pair>
[[gnu::always_inline]] inline void skip_or_answer(b2Manifold* manifold, const Setting& setting,
                                                  const Pair& pair, ContactMemory& memory,
                                                  const Contact* contact = nullptr,
                                                  FoundMasks* masks = nullptr,
                                                  ManifoldRecycling* recycling = nullptr) {
  if (!setting.backend) return pair.box2d(manifold);
  skip_or_answer_at(manifold, setting, pair, pose_of(pair, memory), memory, contact, masks,
                    recycling);
}

}  // namespace dyop::box2d::detail
