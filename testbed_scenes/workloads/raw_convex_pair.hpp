#pragma once
/// \file
/// The convex pairs beyond two triangles as the caller gives them: polygon–polygon and
/// polygon–circle, A a segment where it has 2 vertices (world coordinates, any winding, not yet
/// validated).

#include "dyop/convex_pair.hpp"
#include "workloads/raw_circle.hpp"
#include "workloads/raw_polygon.hpp"

namespace dyop::workloads {

/// Two convex polygons, A and B.
struct RawPolygonPair {
  RawPolygon a;  ///< polygon A
  RawPolygon b;  ///< polygon B
};

/// Polygon A and circle B (`collide`'s order).
struct RawCirclePair {
  RawPolygon a;  ///< polygon A
  RawCircle b;   ///< circle B
};

/// True when both shapes are valid in precision T.
template <class T>
bool valid_in(const RawPolygonPair& p) {
  return valid_in<T>(p.a) && valid_in<T>(p.b);
}
/// True when both shapes are valid in precision T.
template <class T>
bool valid_in(const RawCirclePair& p) {
  return valid_in<T>(p.a) && valid_in<T>(p.b);
}

/// `collide` on the pair in precision T (A a `Segment` when it has 2 vertices); both shapes must be
/// valid there (`valid_in<T>`).
template <class T>
Result<T> collide_raw(const RawPolygonPair& p, const ConvexQuery<T>& q) {
  const Polygon<T> b = build<T>(p.b).polygon;
  if (p.a.count == 2) return collide(build_segment<T>(p.a).segment, b, q);
  return collide(build<T>(p.a).polygon, b, q);
}
/// The same for a polygon (or segment) and a circle.
template <class T>
Result<T> collide_raw(const RawCirclePair& p, const ConvexQuery<T>& q) {
  const Circle<T> b = build<T>(p.b);
  if (p.a.count == 2) return collide(build_segment<T>(p.a).segment, b, q);
  return collide(build<T>(p.a).polygon, b, q);
}

/// The bounding box of `p`'s vertices.
PairBox bounding_box(const RawPolygon& p);
/// The bounding box of the disk: its centre ± its radius.
PairBox bounding_box(const RawCircle& c);

/// True when the boxes share a point.
bool boxes_meet(const PairBox& x, const PairBox& y);

/// The union of both shapes' bounding boxes (a circle's: its centre ± radius).
PairBox pair_box(const RawPolygonPair& p);
/// The union of both shapes' bounding boxes (a circle's: its centre ± radius).
PairBox pair_box(const RawCirclePair& p);

/// The pair's size: the diagonal of `pair_box` (unit of relative errors, as for triangle pairs).
double pair_size(const RawPolygonPair& p);
/// The pair's size: the diagonal of `pair_box` (unit of relative errors, as for triangle pairs).
double pair_size(const RawCirclePair& p);

/// `p` with every number rounded to `precision`.
RawPolygonPair rounded_to(Precision precision, const RawPolygonPair& p);
/// `p` with every number rounded to `precision`.
RawCirclePair rounded_to(Precision precision, const RawCirclePair& p);

}  // namespace dyop::workloads
