#include "internal_edges.hpp"

#include <box2d/b2_body.h>
#include <box2d/b2_polygon_shape.h>
#include <box2d/b2_world.h>
#include <box2d/b2_world_callbacks.h>

#include <cstring>
#include <vector>

namespace dyop::box2d::detail {
namespace {

// A vertex outline turning by less than this (the sine of the angle between its two outline
// edges) counts as flat. Why: vertices placed on one line by float arithmetic (i · cell) are
// collinear to ~1e-7 relative, and a turn of a thousandth of a radian is no corner: the own
// edge's normal is within that angle of the outline's.
constexpr float flat_outline_sine = 1e-3f;

// A body with at most this many fixtures has its list walked instead of the broad phase queried.
// Why: the result is the same (every triangle of the body is a candidate; only those sharing a
// vertex count), and a walk costs tens of instructions per fixture against about 3,500 for one
// query of a ground's broad phase (callgrind): below a few dozen fixtures the walk is cheaper, and
// a split box or a star (2 to 10 fixtures) never pays for a query.
constexpr int walked_body_fixtures = 16;


// A body-frame vertex as its two floats' bits (-0 made +0: the same point).
std::uint64_t point_key(const b2Vec2& v) {
  const float x = v.x + 0.0f;
  const float y = v.y + 0.0f;
  std::uint32_t bx;
  std::uint32_t by;
  std::memcpy(&bx, &x, sizeof bx);
  std::memcpy(&by, &y, sizeof by);
  return static_cast<std::uint64_t>(bx) << 32 | by;
}

const b2PolygonShape* triangle_of(const b2Fixture& f) {
  if (f.GetType() != b2Shape::e_polygon) return nullptr;
  const auto* p = static_cast<const b2PolygonShape*>(f.GetShape());
  return p->m_count == 3 ? p : nullptr;
}

// A triangle's three vertices as keys, Box2D's order.
struct TriangleKeys {
  std::uint64_t v[3];
  explicit TriangleKeys(const b2PolygonShape& p)
      : v{point_key(p.m_vertices[0]), point_key(p.m_vertices[1]), point_key(p.m_vertices[2])} {}
  // True when this triangle has the vertex p.
  bool has_vertex(std::uint64_t p) const { return v[0] == p || v[1] == p || v[2] == p; }
  // True when this triangle has the edge p–q, either way round.
  bool has_edge(std::uint64_t p, std::uint64_t q) const {
    for (int i = 0; i < 3; ++i) {
      const std::uint64_t a = v[i];
      const std::uint64_t b = v[i < 2 ? i + 1 : 0];
      if ((a == p && b == q) || (a == q && b == p)) return true;
    }
    return false;
  }
};

// The other triangle fixtures of one fixture's body that share a vertex with it: the only ones
// its masks depend on. Looked for among all of the body's fixtures for a small body, else among
// those whose broad-phase boxes overlap its own.
class Neighbours : public b2QueryCallback {
 public:
  struct Entry {
    const b2PolygonShape* shape;
    TriangleKeys keys;
  };

  // `scratch` is emptied and filled: the calling thread's, reused so that finding masks
  // allocates nothing once it has grown to the largest neighbourhood seen.
  Neighbours(const b2Fixture& self, const TriangleKeys& keys, std::vector<Entry>& scratch)
      : self_(self), keys_(keys), shapes_(scratch) {
    shapes_.clear();
  }

  void collect() {
    const b2Body& body = *self_.GetBody();
    int count = 0;
    const b2Fixture* f = body.GetFixtureList();
    for (; f && count < walked_body_fixtures; f = f->GetNext()) ++count;
    if (f == nullptr) {  // a small body: all of it
      for (f = body.GetFixtureList(); f; f = f->GetNext()) consider(*f);
    } else {
      body.GetWorld()->QueryAABB(this, self_.GetAABB(0));
    }
  }

  bool ReportFixture(b2Fixture* f) override {
    consider(*f);
    return true;  // every overlap
  }

  const std::vector<Entry>& found() const { return shapes_; }

  // True when a triangle among them has the edge p–q.
  bool shared(std::uint64_t p, std::uint64_t q) const {
    for (const Entry& e : shapes_) {
      if (e.keys.has_edge(p, q)) return true;
    }
    return false;
  }

 private:
  void consider(const b2Fixture& f) {
    if (&f == &self_ || f.GetBody() != self_.GetBody()) return;
    const b2PolygonShape* p = triangle_of(f);
    if (!p) return;
    const TriangleKeys keys(*p);
    if (keys.has_vertex(keys_.v[0]) || keys.has_vertex(keys_.v[1]) || keys.has_vertex(keys_.v[2])) {
      shapes_.push_back({p, keys});
    }
  }

  const b2Fixture& self_;
  const TriangleKeys& keys_;
  std::vector<Entry>& shapes_;
};

// The outline edges (edges of one triangle only) leaving and entering a vertex.
struct VertexOutline {
  b2Vec2 in{0, 0};
  b2Vec2 out{0, 0};
  int ins = 0;
  int outs = 0;

  // Counts triangle `p`'s outline edges at the vertex `at` (its edges found in no other triangle
  // of the body: `is_outline`).
  template <class IsOutline>
  void add(const b2PolygonShape& p, const TriangleKeys& keys, std::uint64_t at,
           const IsOutline& is_outline) {
    for (int i = 0; i < 3; ++i) {
      const int j = i < 2 ? i + 1 : 0;
      if (keys.v[i] != at && keys.v[j] != at) continue;
      if (!is_outline(keys.v[i], keys.v[j])) continue;
      const b2Vec2 edge = p.m_vertices[j] - p.m_vertices[i];
      if (keys.v[i] == at) {
        out = edge;
        ++outs;
      } else {
        in = edge;
        ++ins;
      }
    }
  }

  // A simple outline vertex (one edge in, one out) turning by less than a corner, or reflex.
  bool flat_or_reflex() const {
    return ins == 1 && outs == 1 &&
           b2Cross(in, out) <= flat_outline_sine * in.Length() * out.Length();
  }
};

}  // namespace

InternalEdges triangle_internal_edges(const b2Fixture& fixture) {
  const b2PolygonShape* own = triangle_of(fixture);
  const b2Body& body = *fixture.GetBody();
  if (!own || (body.GetFixtureList() == &fixture && fixture.GetNext() == nullptr)) return {};

  const TriangleKeys keys(*own);
  thread_local std::vector<Neighbours::Entry> scratch;
  Neighbours near(fixture, keys, scratch);
  near.collect();
  if (near.found().empty()) return {};

  InternalEdges masks;
  for (int i = 0; i < 3; ++i) {
    if (near.shared(keys.v[i], keys.v[i < 2 ? i + 1 : 0])) {
      masks.edges |= static_cast<std::uint8_t>(1u << i);
    }
  }
  for (int i = 0; i < 3; ++i) {
    const bool out_internal = (masks.edges >> i) & 1;
    const bool in_internal = (masks.edges >> (i > 0 ? i - 1 : 2)) & 1;
    // A corner of the outline made by this triangle's own two edges: every direction between
    // their normals is the outline's, as for a lone triangle.
    if (!out_internal && !in_internal) continue;
    // Both edges internal: the vertex is inside the body, or on the outline between other
    // triangles' edges (a fan's apex touching the top), whose own pairs carry its contact with
    // their edges' normals; none of this triangle's pairs may push there.
    if (!(out_internal && in_internal)) {
      // One edge internal: closed where the outline through the vertex is flat or reflex. Every
      // triangle with this vertex is among the neighbours, so the body's outline edges there are
      // the edges at it that one triangle only has (this one or a neighbour).
      const std::uint64_t at = keys.v[i];
      thread_local std::vector<const Neighbours::Entry*> around;  // the neighbours with `at`
      around.clear();
      for (const Neighbours::Entry& e : near.found()) {
        if (e.keys.has_vertex(at)) around.push_back(&e);
      }
      // An edge at `at` is shared only with triangles that have `at`.
      const auto shared_around = [&](std::uint64_t p, std::uint64_t q, const void* except) {
        for (const Neighbours::Entry* e : around) {
          if (e != except && e->keys.has_edge(p, q)) return true;
        }
        return false;
      };
      VertexOutline outline;
      outline.add(*own, keys, at, [&](std::uint64_t p, std::uint64_t q) {
        return !shared_around(p, q, nullptr);
      });
      for (const Neighbours::Entry* e : around) {
        outline.add(*e->shape, e->keys, at, [&](std::uint64_t p, std::uint64_t q) {
          return !keys.has_edge(p, q) && !shared_around(p, q, e);
        });
      }
      if (!outline.flat_or_reflex()) continue;
    }
    masks.closed_vertices |= static_cast<std::uint8_t>(1u << i);
  }
  return masks;
}

}  // namespace dyop::box2d::detail
