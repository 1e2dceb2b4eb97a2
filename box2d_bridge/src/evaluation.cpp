#include "evaluation.hpp"

#include <cmath>

#include "contact.hpp"

namespace dyop::box2d {
namespace detail {

// True when a world's contact holds no masks that hold now (`masks`; the rule on): none found
// under its stamp as it is now (see `Contact::internal_edges_stamp`), or found before a
// change of the world's fixture count and the pair has moved since as far as such a change could
// matter (`masks_hold`; `recycling`: the pose of the last answer afresh). A new stamp is recorded
// at once, and a contact with a static body then tells the others
// (`Contact::internal_edges_stamp_moved`); a new fixture count tells nobody (every contact
// sees it). But the masks are found only for an answer that needs them (`needs_masks`): most
// contacts a broad phase makes never come within the margin, and finding a static triangle's
// masks costs a query of the world's broad phase and the covering tests.
bool masks_put_off(const Setting& setting, const PairPose& pose, FoundMasks& masks,
                   const Contact& contact, const ManifoldRecycling* recycling) {
  const std::uint16_t stamp = contact.internal_edges_stamp(setting.epoch);
  if (masks.stamp != stamp) {
    contact.internal_edges_stamp_moved(masks.stamp);
    masks.stamp = stamp;
    masks.motion = FoundMasks::not_found;
  } else {
    notice_fixture_count(masks, contact.world_fixtures());
    if (masks.found() && masks.motion >= 0) {
      // Since the last answer afresh, which had not seen the count move or followed the motion
      // already: every evaluation in between kept its manifold (within the recycling distance of
      // that pose) or was a skip (then the motion is infinite).
      masks.motion += recycling ? recycling->motion(pose.b_in_a.q, pose.centroid_b_in_a,
                                                    pose.lever(), setting.epoch)
                                : HUGE_VALF;
      if (!masks_hold(masks, setting.config.recycle_distance)) {
        masks.motion = FoundMasks::not_found;
      }
    }
  }
  return !masks.found();
}

template void answer<PolygonPair>(b2Manifold*, const Setting&, const PolygonPair&, const PairPose&,
                                  ContactMemory&, const Contact*, FoundMasks*, ManifoldRecycling*);
template void answer<PolygonCirclePair>(b2Manifold*, const Setting&, const PolygonCirclePair&,
                                        const PairPose&, ContactMemory&, const Contact*,
                                        FoundMasks*, ManifoldRecycling*);
template void answer<EdgePolygonPair>(b2Manifold*, const Setting&, const EdgePolygonPair&,
                                      const PairPose&, ContactMemory&, const Contact*, FoundMasks*,
                                      ManifoldRecycling*);
template void answer<EdgeCirclePair>(b2Manifold*, const Setting&, const EdgeCirclePair&,
                                     const PairPose&, ContactMemory&, const Contact*, FoundMasks*,
                                     ManifoldRecycling*);

}  // namespace detail

void collide_polygons(b2Manifold* manifold, Backend backend, const b2PolygonShape& shape_a,
                      const b2Transform& xf_a, const b2PolygonShape& shape_b,
                      const b2Transform& xf_b, ContactMemory* memory, const Config& config) {
  if (!memory) {
    ContactMemory cold;
    return collide_polygons(manifold, backend, shape_a, xf_a, shape_b, xf_b, &cold, config);
  }
  ContactMemory& m = *memory;
  const detail::Setting setting(backend, config, 0);
  if (m.shapes == ContactMemory::Shapes::Unchecked) detail::look_at_shapes(shape_a, shape_b, m);
  if (detail::family_of(m.shapes) == detail::Family::Triangles) {
    detail::skip_or_answer(manifold, setting, detail::TrianglePair{shape_a, xf_a, shape_b, xf_b},
                           m);
  } else {
    detail::skip_or_answer(manifold, setting, detail::PolygonPair(shape_a, xf_a, shape_b, xf_b), m);
  }
}

void collide_polygon_and_circle(b2Manifold* manifold, Backend backend,
                                const b2PolygonShape& polygon, const b2Transform& xf_a,
                                const b2CircleShape& circle, const b2Transform& xf_b,
                                ContactMemory* memory, const Config& config) {
  if (!memory) {
    ContactMemory cold;
    return collide_polygon_and_circle(manifold, backend, polygon, xf_a, circle, xf_b, &cold,
                                      config);
  }
  ContactMemory& m = *memory;
  if (m.shapes == ContactMemory::Shapes::Unchecked) detail::look_at_shapes(polygon, circle, m);
  detail::skip_or_answer(manifold, detail::Setting(backend, config, 0),
                         detail::PolygonCirclePair(polygon, xf_a, circle, xf_b), m);
}

void collide_edge_and_polygon(b2Manifold* manifold, Backend backend, const b2EdgeShape& edge,
                              const b2Transform& xf_a, const b2PolygonShape& polygon,
                              const b2Transform& xf_b, ContactMemory* memory,
                              const Config& config) {
  ContactMemory cold;
  ContactMemory& m = memory ? *memory : cold;
  const detail::EdgePolygonPair pair(edge, xf_a, polygon, xf_b);
  if (m.shapes == ContactMemory::Shapes::Unchecked) {
    detail::look_at_shapes(edge, polygon, b2Mul(b2MulT(xf_a, xf_b), polygon.m_centroid), m);
  }
  detail::skip_or_answer(manifold, detail::Setting(backend, config, 0), pair, m);
}

void collide_edge_and_circle(b2Manifold* manifold, Backend backend, const b2EdgeShape& edge,
                             const b2Transform& xf_a, const b2CircleShape& circle,
                             const b2Transform& xf_b, ContactMemory* memory, const Config& config) {
  ContactMemory cold;
  ContactMemory& m = memory ? *memory : cold;
  const detail::EdgeCirclePair pair(edge, xf_a, circle, xf_b);
  if (m.shapes == ContactMemory::Shapes::Unchecked) {
    detail::look_at_shapes(edge, circle, b2Mul(b2MulT(xf_a, xf_b), circle.m_p), m);
  }
  detail::skip_or_answer(manifold, detail::Setting(backend, config, 0), pair, m);
}

}  // namespace dyop::box2d
