#include "workloads/raw_convex_pair.hpp"

namespace dyop::workloads {
namespace {

using V = Vec2<double>;

PairBox joined(PairBox x, const PairBox& y) {
  x.lo = x.lo.cwiseMin(y.lo);
  x.hi = x.hi.cwiseMax(y.hi);
  return x;
}

double diagonal(const PairBox& box) { return (box.hi - box.lo).norm(); }

}  // namespace

PairBox bounding_box(const RawPolygon& p) {
  PairBox box{p.v[0], p.v[0]};
  for (int i = 1; i < p.count; ++i) {
    box.lo = box.lo.cwiseMin(p.v[static_cast<std::size_t>(i)]);
    box.hi = box.hi.cwiseMax(p.v[static_cast<std::size_t>(i)]);
  }
  return box;
}

PairBox bounding_box(const RawCircle& c) {
  const V r(c.radius, c.radius);
  return {c.center - r, c.center + r};
}

bool boxes_meet(const PairBox& x, const PairBox& y) {
  return (x.lo.array() <= y.hi.array()).all() && (y.lo.array() <= x.hi.array()).all();
}

PairBox pair_box(const RawPolygonPair& p) { return joined(bounding_box(p.a), bounding_box(p.b)); }

PairBox pair_box(const RawCirclePair& p) { return joined(bounding_box(p.a), bounding_box(p.b)); }

double pair_size(const RawPolygonPair& p) { return diagonal(pair_box(p)); }

double pair_size(const RawCirclePair& p) { return diagonal(pair_box(p)); }

RawPolygonPair rounded_to(Precision precision, const RawPolygonPair& p) {
  return {rounded_to(precision, p.a), rounded_to(precision, p.b)};
}

RawCirclePair rounded_to(Precision precision, const RawCirclePair& p) {
  return {rounded_to(precision, p.a), rounded_to(precision, p.b)};
}

}  // namespace dyop::workloads
