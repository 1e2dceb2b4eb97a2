#pragma once
/// \file
/// Which face of which polygon a manifold was clipped against: what the contact streams and the
/// viewer compare and show.

#include <box2d/b2_collision.h>
#include <box2d/b2_math.h>
#include <box2d/b2_polygon_shape.h>

namespace dyop::experiments {

/// The reference edge of a manifold with points whose reference face (`e_faceA` or `e_faceB`)
/// belongs to the polygon `reference`: its normal nearest `localNormal` (the plug-in and Box2D
/// both copy it from `m_normals`, so the nearest is the one copied).
inline int reference_edge(const b2Manifold& m, const b2PolygonShape& reference) {
  int best = 0;
  for (int i = 1; i < reference.m_count; ++i) {
    if (b2Dot(reference.m_normals[i], m.localNormal) >
        b2Dot(reference.m_normals[best], m.localNormal)) {
      best = i;
    }
  }
  return best;
}

/// The same for a manifold of two polygons: the edge of `shape_a` (`e_faceA`) or `shape_b`.
inline int reference_edge(const b2Manifold& m, const b2PolygonShape& shape_a,
                          const b2PolygonShape& shape_b) {
  return reference_edge(m, m.type == b2Manifold::e_faceA ? shape_a : shape_b);
}

}  // namespace dyop::experiments
