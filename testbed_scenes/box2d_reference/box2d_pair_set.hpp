#pragma once
/// \file
/// A bench class's pairs (`workloads/pair_sets.hpp`) as Box2D bodies hold them, for timing Box2D's
/// own narrow phase on the same input as the library's methods.

#include <box2d/b2_collision.h>
#include <box2d/b2_polygon_shape.h>

#include <cstddef>
#include <vector>

#include "workloads/pair_sets.hpp"

namespace dyop::workloads {

/// The same pairs as Box2D bodies would hold them: each triangle a `b2PolygonShape` about its own
/// centroid (skin radius 0), placed by a translation.
struct Box2DPairSet {
  std::vector<b2PolygonShape> shape_a, shape_b;
  std::vector<b2Transform> xf_a, xf_b;
  std::size_t size() const { return shape_a.size(); }
};
Box2DPairSet make_box2d_pair_set(const PairSet<float>& set);

}  // namespace dyop::workloads
