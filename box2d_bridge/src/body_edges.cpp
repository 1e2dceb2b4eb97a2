#include "body_edges.hpp"

#include <box2d/b2_body.h>
#include <box2d/b2_polygon_shape.h>
#include <box2d/b2_world.h>

#include <cstring>
#include <unordered_map>
#include <utility>
#include <vector>

namespace dyop::box2d::detail {
namespace {

// A vertex outline turning by less than this (the sine of the angle between its two outline
// edges) counts as flat. Why: vertices placed on one line by float arithmetic (i · cell) are
// collinear to ~1e-7 relative, and a turn of a thousandth of a radian is no corner: the own
// edge's normal is within that angle of the outline's.
constexpr float flat_outline_sine = 1e-3f;

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

struct EdgeKey {
  std::uint64_t lo;
  std::uint64_t hi;
  bool operator==(const EdgeKey& o) const { return lo == o.lo && hi == o.hi; }
};

EdgeKey edge_key(const b2Vec2& p, const b2Vec2& q) {
  const std::uint64_t a = point_key(p);
  const std::uint64_t b = point_key(q);
  return a < b ? EdgeKey{a, b} : EdgeKey{b, a};
}

struct EdgeHash {
  std::size_t operator()(const EdgeKey& e) const {
    return std::hash<std::uint64_t>()(e.lo * 0x9E3779B97F4A7C15ull ^ e.hi);
  }
};

// The outline edges (edges of one triangle only) leaving and entering a vertex.
struct VertexOutline {
  b2Vec2 in{0, 0};
  b2Vec2 out{0, 0};
  int ins = 0;
  int outs = 0;
};

// What a body's index was built from. Checked in O(1) first: the world's broad-phase proxy count
// (it moves when any fixture of the world is created or destroyed), the head of the body's fixture
// list (a new fixture goes to the head) and the head's shape and vertices (a destroyed head whose
// memory a new fixture reuses). Only when that changed is the list walked for its count, since
// Box2D keeps the count private: an index is rebuilt only when the body's fixtures changed.
struct Signature {
  int proxies = -1;
  const b2Fixture* head = nullptr;
  const b2Shape* head_shape = nullptr;
  std::uint64_t head_vertices[3] = {0, 0, 0};
  int count = 0;  // set by `count_fixtures`, not compared by `same_head`

  bool same_head(const Signature& o) const {
    return head == o.head && head_shape == o.head_shape && head_vertices[0] == o.head_vertices[0] &&
           head_vertices[1] == o.head_vertices[1] && head_vertices[2] == o.head_vertices[2];
  }
};

struct BodyIndex {
  Signature signature;
  bool built = false;
  std::unordered_map<const b2Fixture*, TriangleEdges> triangles;
};

const b2PolygonShape* triangle_of(const b2Fixture& f) {
  if (f.GetType() != b2Shape::e_polygon) return nullptr;
  const auto* p = static_cast<const b2PolygonShape*>(f.GetShape());
  return p->m_count == 3 ? p : nullptr;
}

Signature quick_signature(const b2Body& body) {
  Signature s;
  s.proxies = body.GetWorld()->GetProxyCount();
  const b2Fixture* head = body.GetFixtureList();
  s.head = head;
  if (head) {
    s.head_shape = head->GetShape();
    if (const b2PolygonShape* p = triangle_of(*head)) {
      for (int i = 0; i < 3; ++i) s.head_vertices[i] = point_key(p->m_vertices[i]);
    }
  }
  return s;
}

int count_fixtures(const b2Body& body) {
  int count = 0;
  for (const b2Fixture* f = body.GetFixtureList(); f; f = f->GetNext()) ++count;
  return count;
}

void build(const b2Body& body, BodyIndex& index) {
  std::vector<std::pair<const b2Fixture*, const b2PolygonShape*>> tris;
  for (const b2Fixture* f = body.GetFixtureList(); f; f = f->GetNext()) {
    if (const b2PolygonShape* p = triangle_of(*f)) tris.emplace_back(f, p);
  }
  std::unordered_map<EdgeKey, int, EdgeHash> shared;
  shared.reserve(3 * tris.size());
  for (const auto& [f, p] : tris) {
    for (int i = 0; i < 3; ++i) ++shared[edge_key(p->m_vertices[i], p->m_vertices[(i + 1) % 3])];
  }
  std::unordered_map<std::uint64_t, VertexOutline> outline;
  outline.reserve(3 * tris.size());
  index.triangles.clear();
  index.triangles.reserve(tris.size());
  for (const auto& [f, p] : tris) {
    TriangleEdges& t = index.triangles[f];
    for (int i = 0; i < 3; ++i) {
      const b2Vec2& from = p->m_vertices[i];
      const b2Vec2& to = p->m_vertices[(i + 1) % 3];
      if (shared[edge_key(from, to)] > 1) {
        t.inactive_edges |= static_cast<std::uint8_t>(1u << i);
        continue;
      }
      VertexOutline& start = outline[point_key(from)];
      start.out = to - from;
      ++start.outs;
      VertexOutline& end = outline[point_key(to)];
      end.in = to - from;
      ++end.ins;
    }
  }
  for (const auto& [f, p] : tris) {
    TriangleEdges& t = index.triangles[f];
    for (int i = 0; i < 3; ++i) {
      const bool out_internal = (t.inactive_edges >> i) & 1;
      const bool in_internal = (t.inactive_edges >> ((i + 2) % 3)) & 1;
      // A corner of the outline made by this triangle's own two edges: every direction between
      // their normals is the outline's, as for a lone triangle.
      if (!out_internal && !in_internal) continue;
      // Both edges internal: the vertex is inside the body, or on the outline between other
      // triangles' edges (a fan's apex touching the top), whose own pairs carry its contact with
      // their edges' normals; none of this triangle's pairs may push there.
      if (out_internal && in_internal) {
        t.flat_vertices |= static_cast<std::uint8_t>(1u << i);
        continue;
      }
      const VertexOutline& v = outline[point_key(p->m_vertices[i])];
      if (v.ins != 1 || v.outs != 1) continue;  // not a simple outline vertex: left as it is
      const float turn = b2Cross(v.in, v.out);
      if (turn <= flat_outline_sine * v.in.Length() * v.out.Length()) {
        t.flat_vertices |= static_cast<std::uint8_t>(1u << i);
      }
    }
  }
}

std::unordered_map<const b2Body*, BodyIndex>& bodies() {
  static std::unordered_map<const b2Body*, BodyIndex> table;
  return table;
}

void advance_generation() {
  if (++index_generation_now == 0) index_generation_now = 1;  // 0: a contact that never looked
}

}  // namespace

TriangleEdges triangle_edges(const b2Fixture& fixture) {
  if (!triangle_of(fixture)) return {};
  const b2Body& body = *fixture.GetBody();
  BodyIndex& index = bodies()[&body];
  Signature now = quick_signature(body);
  if (!index.built || now.proxies != index.signature.proxies || !now.same_head(index.signature)) {
    now.count = count_fixtures(body);
    if (!index.built || now.count != index.signature.count || !now.same_head(index.signature)) {
      build(body, index);
      index.built = true;
      advance_generation();
    }
    index.signature = now;
  }
  const auto found = index.triangles.find(&fixture);
  return found == index.triangles.end() ? TriangleEdges{} : found->second;
}

void forget_body(const b2Body& body) {
  if (bodies().erase(&body) > 0) advance_generation();
}

void forget_bodies() {
  bodies().clear();
  advance_generation();
}

int indexed_bodies() { return static_cast<int>(bodies().size()); }

}  // namespace dyop::box2d::detail
