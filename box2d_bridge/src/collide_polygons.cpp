#include "backend.hpp"
#include "stats.hpp"
#include "triangle_manifold.hpp"

namespace dyop::box2d {

void collide_polygons(b2Manifold* manifold, Backend backend, const b2PolygonShape* shape_a,
                      const b2Transform& xf_a, const b2PolygonShape* shape_b,
                      const b2Transform& xf_b, LinCannyCache* cache) {
  Stats& count = detail::counters();
  if (shape_a->m_count != 3 || shape_b->m_count != 3) {
    ++count.polygon_pairs;
    b2CollidePolygons(manifold, shape_a, xf_a, shape_b, xf_b);
    return;
  }
  ++count.triangle_pairs[static_cast<int>(backend)];
  // Backend::Box2D has no library method: Box2D's own code is its answer, not a fallback. A
  // method that cannot answer falls back so that the world goes on, and is counted.
  const std::optional<Method> method = detail::method_of(backend);
  if (!method || !detail::triangle_manifold(*method, *shape_a, *shape_b, b2MulT(xf_a, xf_b),
                                            cache, manifold)) {
    if (method) ++count.fallbacks;
    b2CollidePolygons(manifold, shape_a, xf_a, shape_b, xf_b);
  }
  if (manifold->pointCount > 0) ++count.manifolds;
}

}  // namespace dyop::box2d
