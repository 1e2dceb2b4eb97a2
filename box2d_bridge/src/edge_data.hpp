#pragma once
// Internal: a polygon fixture's fixed edge data (`fix_internal_edges`), kept in the fixture's own
// shape. A triangle `b2PolygonShape` uses 3 of its 8 vertex slots; Box2D copies the whole shape
// into the fixture (`b2PolygonShape::Clone`) and reads only `m_count` of them, so slots 3 and 4
// hold the record (a box's 4 and 5, up to a 7-gon's last vertex and normal slots): freed with the
// fixture, in the world's own memory, read where the contact already reads the vertices. Why there
// and when it is refreshed: docs/design.md, section 5
// ("Fixed edge data").

#include <box2d/b2_fixture.h>
#include <box2d/b2_polygon_shape.h>
#include <box2d/b2_world.h>

#include <cstdint>
#include <cstring>
#include <optional>
#include <vector>

#include "dyop/convex_pair.hpp"
#include "dyop/result.hpp"

namespace dyop::box2d::detail {

// The record: a key naming the fixture it was written for, and the polygon's masks (bits
// 0..count−1 each, Box2D's vertex order).
struct EdgeRecord {
  std::uint64_t key = 0;
  std::uint8_t edges = 0;
  std::uint8_t closed_vertices = 0;
  std::uint8_t unused[6] = {};
};
static_assert(sizeof(EdgeRecord) == 2 * sizeof(b2Vec2), "the record fills two vertex slots");
static_assert(b2_maxPolygonVertices == 8, "a 7-gon leaves vertex slot 7 and normal slot 7 free");
static_assert(sizeof(b2Vec2) == sizeof(std::uint64_t), "a vertex mixes into the key as one word");

// Most vertices a polygon fixture may have to hold fixed edge data: an 8-gon has no slot left
// (its contacts find its masks, as for a fixture never fixed).
constexpr int max_fixed_vertices = b2_maxPolygonVertices - 1;

// The key of polygon fixture `fixture`'s record: its address, its body's and its vertices mixed.
// Why: a shape copied out of a fixture (`GetShape`) carries the record along, and a
// default-constructed `b2PolygonShape` leaves the slots uninitialised; neither may read as edge
// data. Box2D's allocators hand a destroyed fixture's address to the next one, so the address
// alone would accept a copy recreated in its place; with the body and the vertices, a copy is
// accepted only as the same polygon on the same body, where the record still describes it.
// The constant makes a key unlike the float coordinates the slots hold otherwise. Never 0.
inline std::uint64_t edge_record_key(const b2Fixture& fixture) {
  constexpr std::uint64_t mix = 0x9E37'79B9'7F4A'7C15u;
  const auto& polygon = *static_cast<const b2PolygonShape*>(fixture.GetShape());
  std::uint64_t key = static_cast<std::uint64_t>(reinterpret_cast<std::uintptr_t>(&fixture));
  key = (key ^ 0x5EED'ED6E'DA7A'0001u) * mix;
  key = (key ^ reinterpret_cast<std::uintptr_t>(fixture.GetBody())) * mix;
  for (int i = 0; i < polygon.m_count; ++i) {
    std::uint64_t vertex;
    std::memcpy(&vertex, &polygon.m_vertices[i], sizeof vertex);
    key = (key ^ vertex) * mix;
  }
  return key | 1;
}

// Where a polygon's record lives: the two vertex slots after its last vertex (up to 6 vertices),
// or a 7-gon's last vertex slot (the key) and last normal slot (the masks); Box2D reads only
// `m_count` of each. The key's word, then the masks' word.
inline void* record_key_slot(b2PolygonShape& p) { return &p.m_vertices[p.m_count]; }
inline void* record_masks_slot(b2PolygonShape& p) {
  return p.m_count + 1 < b2_maxPolygonVertices ? static_cast<void*>(&p.m_vertices[p.m_count + 1])
                                               : static_cast<void*>(&p.m_normals[p.m_count]);
}

// The fixed edge data of polygon fixture `fixture` (bits 0..count−1), or nothing: none written,
// or a polygon with no slot for it. The caller knows the shape is a polygon.
inline std::optional<ShapeMasks> fixed_polygon_edges(const b2Fixture& fixture) {
  auto& polygon = *static_cast<b2PolygonShape*>(const_cast<b2Shape*>(fixture.GetShape()));
  if (polygon.m_count > max_fixed_vertices) return std::nullopt;
  std::uint64_t key;
  std::memcpy(&key, record_key_slot(polygon), sizeof key);
  if (key != edge_record_key(fixture)) return std::nullopt;
  std::uint8_t masks[2];
  std::memcpy(masks, record_masks_slot(polygon), sizeof masks);
  return ShapeMasks{masks[0], masks[1]};
}

// The fixed edge data of triangle fixture `fixture` (bits 0..2), or nothing: none written. Every
// evaluation with the rule on asks, so the shape is not checked again: the caller knows it is a
// triangle.
inline std::optional<InternalEdges> fixed_triangle_edges(const b2Fixture& fixture) {
  const std::optional<ShapeMasks> m = fixed_polygon_edges(fixture);
  if (!m) return std::nullopt;
  return InternalEdges{m->edges, m->closed_vertices};
}

// The fixed edge data of any fixture: nothing for a shape other than a triangle.
inline std::optional<InternalEdges> fixed_edges(const b2Fixture& fixture) {
  const b2Shape* shape = fixture.GetShape();
  if (shape->m_type != b2Shape::e_polygon ||
      static_cast<const b2PolygonShape*>(shape)->m_count != 3) {
    return std::nullopt;
  }
  return fixed_triangle_edges(fixture);
}

// True when `fixture` is a polygon that can hold fixed edge data.
inline bool holds_edge_data(const b2Fixture& fixture) {
  return fixture.GetType() == b2Shape::e_polygon &&
         static_cast<const b2PolygonShape*>(fixture.GetShape())->m_count <= max_fixed_vertices;
}

// Writes `masks` as the fixed edge data of polygon fixture `fixture` (`holds_edge_data`).
inline void write_fixed_edges(b2Fixture& fixture, ShapeMasks masks) {
  auto& polygon = *static_cast<b2PolygonShape*>(fixture.GetShape());
  const std::uint64_t key = edge_record_key(fixture);
  const std::uint8_t bytes[2] = {masks.edges, masks.closed_vertices};
  std::memcpy(record_key_slot(polygon), &key, sizeof key);
  std::memcpy(record_masks_slot(polygon), bytes, sizeof bytes);
}

// Gives `fixtures` (triangles of `world`) fixed edge data and finds it again for every fixed
// triangle next to them: `fix_internal_edges` and `add_triangles`.
void fix_fixtures(b2World& world, const std::vector<b2Fixture*>& fixtures);

}  // namespace dyop::box2d::detail
