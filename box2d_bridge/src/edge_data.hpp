#pragma once
// Internal: a triangle fixture's fixed edge data (`fix_internal_edges`), kept in the fixture's own
// shape. A triangle `b2PolygonShape` uses 3 of its 8 vertex slots; Box2D copies the whole shape
// into the fixture (`b2PolygonShape::Clone`) and reads only `m_count` of them, so slots 3 and 4
// hold the record: freed with the fixture, in the world's own memory, read where the contact
// already reads the vertices. Why there and when it is refreshed: docs/design.md, section 5
// ("Fixed edge data").

#include <box2d/b2_fixture.h>
#include <box2d/b2_polygon_shape.h>
#include <box2d/b2_world.h>

#include <cstdint>
#include <cstring>
#include <optional>
#include <vector>

#include "dyop/result.hpp"

namespace dyop::box2d::detail {

// The record: a key naming the fixture it was written for, and the triangle's masks
// (`InternalEdges`, bits 0..2 each, Box2D's vertex order).
struct EdgeRecord {
  std::uint64_t key = 0;
  std::uint8_t edges = 0;
  std::uint8_t closed_vertices = 0;
  std::uint8_t unused[6] = {};
};
static_assert(sizeof(EdgeRecord) == 2 * sizeof(b2Vec2), "the record fills vertex slots 3 and 4");
static_assert(b2_maxPolygonVertices >= 5, "a triangle leaves vertex slots 3 and 4 free");
static_assert(sizeof(b2Vec2) == sizeof(std::uint64_t), "a vertex mixes into the key as one word");

// The key of triangle fixture `fixture`'s record: its address, its body's and its three vertices
// mixed. Why: a shape copied out of a fixture (`GetShape`) carries the record along, and a
// default-constructed `b2PolygonShape` leaves the slots uninitialised; neither may read as edge
// data. Box2D's allocators hand a destroyed fixture's address to the next one, so the address
// alone would accept a copy recreated in its place; with the body and the vertices, a copy is
// accepted only as the same triangle on the same body, where the record still describes it.
// The constant makes a key unlike the float coordinates the slots hold otherwise. Never 0.
inline std::uint64_t edge_record_key(const b2Fixture& fixture) {
  constexpr std::uint64_t mix = 0x9E37'79B9'7F4A'7C15u;
  const auto& polygon = *static_cast<const b2PolygonShape*>(fixture.GetShape());
  std::uint64_t key = static_cast<std::uint64_t>(reinterpret_cast<std::uintptr_t>(&fixture));
  key = (key ^ 0x5EED'ED6E'DA7A'0001u) * mix;
  key = (key ^ reinterpret_cast<std::uintptr_t>(fixture.GetBody())) * mix;
  for (int i = 0; i < 3; ++i) {
    std::uint64_t vertex;
    std::memcpy(&vertex, &polygon.m_vertices[i], sizeof vertex);
    key = (key ^ vertex) * mix;
  }
  return key | 1;
}

// The fixed edge data of triangle fixture `fixture` (bits 0..2), or nothing: none written. Every
// evaluation with the rule on asks, so the shape is not checked again: the caller knows it is a
// triangle.
inline std::optional<InternalEdges> fixed_triangle_edges(const b2Fixture& fixture) {
  const auto& polygon = *static_cast<const b2PolygonShape*>(fixture.GetShape());
  EdgeRecord record;
  std::memcpy(static_cast<void*>(&record), static_cast<const void*>(&polygon.m_vertices[3]),
              sizeof record);
  if (record.key != edge_record_key(fixture)) return std::nullopt;
  return InternalEdges{record.edges, record.closed_vertices};
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

// Writes `masks` as the fixed edge data of triangle fixture `fixture`.
inline void write_fixed_edges(b2Fixture& fixture, InternalEdges masks) {
  auto& polygon = *static_cast<b2PolygonShape*>(fixture.GetShape());
  EdgeRecord record;
  record.key = edge_record_key(fixture);
  record.edges = masks.edges;
  record.closed_vertices = masks.closed_vertices;
  std::memcpy(static_cast<void*>(&polygon.m_vertices[3]), static_cast<const void*>(&record),
              sizeof record);
}

// Gives `fixtures` (triangles of `world`) fixed edge data and finds it again for every fixed
// triangle next to them: `fix_internal_edges` and `add_triangles`.
void fix_fixtures(b2World& world, const std::vector<b2Fixture*>& fixtures);

}  // namespace dyop::box2d::detail
