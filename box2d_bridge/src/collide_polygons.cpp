#include <cmath>

#include "backend.hpp"
#include "pair_state.hpp"
#include "stats.hpp"
#include "triangle_manifold.hpp"

namespace dyop::box2d {
namespace detail {
namespace {

bool same(const b2Transform& x, const b2Transform& y) {
  return x.p.x == y.p.x && x.p.y == y.p.y && x.q.s == y.q.s && x.q.c == y.q.c;
}

// Separation of the pair along face `face` (0..2: A's edge, 3..5: B's), with the other
// triangle's full support: a lower bound on the pair's distance, computed in the face's frame.
float face_separation(int face, const b2PolygonShape& a, const b2PolygonShape& b,
                      const b2Transform& b_in_a) {
  const bool on_a = face < 3;
  const b2PolygonShape& own = on_a ? a : b;
  const b2PolygonShape& other = on_a ? b : a;
  const int e = on_a ? face : face - 3;
  // The other triangle's vertices in the face's body frame.
  auto other_vertex = [&](int k) {
    return on_a ? b2Mul(b_in_a, other.m_vertices[k]) : b2MulT(b_in_a, other.m_vertices[k]);
  };
  float least = b2Dot(own.m_normals[e], other_vertex(0) - own.m_vertices[e]);
  for (int k = 1; k < 3; ++k) {
    least = std::min(least, b2Dot(own.m_normals[e], other_vertex(k) - own.m_vertices[e]));
  }
  return least;
}

void remember(PairState& state, const b2Manifold& m, const b2Transform& xf_a,
              const b2Transform& xf_b) {
  state.last = m;
  state.last_xf_a = xf_a;
  state.last_xf_b = xf_b;
  state.has_last = true;
}

}  // namespace

BodyTriangle body_triangle(const b2PolygonShape& shape) {
  BodyTriangle t;
  auto v = [&](int i) { return Vec2<float>(shape.m_vertices[i].x, shape.m_vertices[i].y); };
  t.triangle = Triangle<float>::make(v(0), v(1), v(2));
  t.centre = shape.m_centroid;
  t.radius = 0;
  for (int i = 0; i < 3; ++i) {
    t.radius = std::max(t.radius, (shape.m_vertices[i] - shape.m_centroid).Length());
  }
  return t;
}

void evaluate_pair(b2Manifold* manifold, Backend backend, const Config& config,
                   const b2PolygonShape& a, const b2Transform& xf_a, const b2PolygonShape& b,
                   const b2Transform& xf_b, PairState& state) {
  Stats& count = counters();
  if (a.m_count != 3 || b.m_count != 3) {
    ++count.polygon_pairs;
    b2CollidePolygons(manifold, &a, xf_a, &b, xf_b);
    return;
  }
  ++count.triangle_pairs[static_cast<int>(backend)];
  auto skipped = [&](Skip why) { ++count.skipped[static_cast<int>(why)]; };

  // Same bodies at the same places: the same inputs, so the same manifold.
  if (config.reuse_unmoved && state.has_last && same(xf_a, state.last_xf_a) &&
      same(xf_b, state.last_xf_b)) {
    *manifold = state.last;
    skipped(Skip::Unmoved);
    if (manifold->pointCount > 0) ++count.manifolds;
    return;
  }
  if (!config.shape_cache || !state.shapes_ready) {
    state.a = body_triangle(a);
    state.b = body_triangle(b);
    state.shapes_ready = true;
  }
  const b2Transform b_in_a = b2MulT(xf_a, xf_b);
  const float far = reach(a.m_radius + b.m_radius);
  auto empty = [&](Skip why) {
    manifold->pointCount = 0;
    skipped(why);
    remember(state, *manifold, xf_a, xf_b);
  };
  if (config.bounds_early_out) {
    const float gap =
        (b2Mul(b_in_a, state.b.centre) - state.a.centre).Length() - state.a.radius - state.b.radius;
    if (gap > far) return empty(Skip::Bounds);
  }
  const std::optional<Method> method = method_of(backend);
  if (config.warm_axis && method && state.last_face >= 0 &&
      face_separation(state.last_face, a, b, b_in_a) > far) {
    return empty(Skip::WarmAxis);
  }

  // Backend::Box2D has no library method: Box2D's own code is its answer, not a fallback. A
  // method that cannot answer falls back so that the world goes on, and is counted.
  bool answered = false;
  if (method && state.a.triangle.ok() && state.b.triangle.ok()) {
    const Triangle<float> tb = state.b.triangle.triangle.moved(
        b_in_a.q.c, b_in_a.q.s, Vec2<float>(b_in_a.p.x, b_in_a.p.y));
    LinCannyCache cold;
    answered = triangle_manifold(*method, state.a.triangle.triangle, tb, a, b, b_in_a,
                                 config.lin_canny_cache ? &state.cache : &cold, manifold,
                                 &state.last_face);
  }
  if (!answered) {
    if (method) ++count.fallbacks;
    b2CollidePolygons(manifold, &a, xf_a, &b, xf_b);
  }
  if (manifold->pointCount > 0) ++count.manifolds;
  remember(state, *manifold, xf_a, xf_b);
}

}  // namespace detail

void collide_polygons(b2Manifold* manifold, Backend backend, const b2PolygonShape* shape_a,
                      const b2Transform& xf_a, const b2PolygonShape* shape_b,
                      const b2Transform& xf_b, LinCannyCache* cache) {
  // One evaluation with nothing remembered from before: no skip, the given cache only.
  detail::PairState state;
  Config config = Config::none();
  if (cache) {
    state.cache = *cache;
    config.lin_canny_cache = true;
  }
  detail::evaluate_pair(manifold, backend, config, *shape_a, xf_a, *shape_b, xf_b, state);
  if (cache) *cache = state.cache;
}

}  // namespace dyop::box2d
