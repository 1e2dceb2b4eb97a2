#pragma once
// Internal: what the plug-in remembers about one triangle pair between steps (it lives inside the
// contact object: no heap), and the evaluation that uses it to skip work.

#include <box2d/b2_collision.h>
#include <box2d/b2_polygon_shape.h>

#include <cstdint>

#include "dyop/box2d.hpp"

namespace dyop::box2d::detail {

// A triangle as its body holds it: validated once in the body frame, with its bounding circle.
struct BodyTriangle {
  TriangleOrError<float> triangle;
  b2Vec2 centre{0, 0};  // the shape's centroid, body frame
  float radius = 0;     // distance from `centre` to the farthest vertex
};

// Builds the body-frame triangle of a 3-vertex polygon.
BodyTriangle body_triangle(const b2PolygonShape& shape);

struct PairState {
  LinCannyCache cache;        // Lin–Canny's last features
  BodyTriangle a, b;          // valid when `shapes_ready`
  bool shapes_ready = false;
  bool has_last = false;      // `last_*` hold the previous evaluation
  b2Transform last_xf_a{}, last_xf_b{};
  b2Manifold last{};
  std::int8_t last_face = -1;  // face judged on last time: 0..2 A's edges, 3..5 B's, -1 none
};

// The plug-in's answer for one polygon pair with `config`'s skips, counted in `stats`.
void evaluate_pair(b2Manifold* manifold, Backend backend, const Config& config,
                   const b2PolygonShape& a, const b2Transform& xf_a, const b2PolygonShape& b,
                   const b2Transform& xf_b, PairState& state);

}  // namespace dyop::box2d::detail
