#pragma once
// Internal: a polygon or two-sided edge fixture's fixed edge data (`fix_internal_edges`), kept in
// the fixture's own shape. A triangle `b2PolygonShape` uses 3 of its 8 vertex slots; Box2D copies
// the whole shape into the fixture (`b2PolygonShape::Clone`) and reads only `m_count` of them, so
// slots 3 and 4 hold the record (a box's 4 and 5, up to a 7-gon's last vertex and normal slots). A
// two-sided `b2EdgeShape` leaves its ghost vertices `m_vertex0` and `m_vertex3` unread: they hold
// its record. Freed with the fixture, in the world's own memory, read where the contact already
// reads the shape. Why there and when it is refreshed: docs/design.md, section 5 ("Fixed edge
// data").

#include <box2d/b2_edge_shape.h>
#include <box2d/b2_fixture.h>
#include <box2d/b2_polygon_shape.h>
#include <box2d/b2_world.h>

#include <atomic>
#include <cstdint>
#include <cstring>
#include <optional>
#include <vector>

#include "dyop/convex_pair.hpp"
#include "dyop/result.hpp"
#include "internal_edges.hpp"

namespace dyop::box2d::detail {

// A polygon's edge data in one word: its masks (bits 0..count−1 each, Box2D's vertex order) and
// its junction. What the fixed record and the found memo hold after their key.
struct PackedEdgeData {
  std::uint8_t edges = 0;
  std::uint8_t closed_vertices = 0;
  std::uint8_t junction_vertex = Junction::none;
  std::uint8_t junction_closed = 0;  // bit 0 `Junction::closed_in`, bit 1 `closed_out`
  std::int16_t junction_first = 0;
  std::int16_t junction_last = 0;
};
static_assert(sizeof(PackedEdgeData) == sizeof(b2Vec2), "the edge data fills one slot");

inline PackedEdgeData pack(const PolygonEdgeData& data) {
  const Junction& j = data.junction;
  return {data.masks.edges,
          data.masks.closed_vertices,
          j.vertex,
          static_cast<std::uint8_t>(static_cast<unsigned>(j.closed_in) |
                                    static_cast<unsigned>(j.closed_out) << 1),
          j.first,
          j.last};
}

inline PolygonEdgeData unpack(const PackedEdgeData& p) {
  Junction j;
  j.vertex = p.junction_vertex;
  j.closed_in = (p.junction_closed & 1u) != 0;
  j.closed_out = (p.junction_closed & 2u) != 0;
  j.first = p.junction_first;
  j.last = p.junction_last;
  return PolygonEdgeData{{p.edges, p.closed_vertices}, j};
}

static_assert(b2_maxPolygonVertices == 8, "a 7-gon leaves vertex slot 7 and normal slot 7 free");

// `h` with the word `w` mixed in: one multiplication by Knuth's multiplicative constant, widened to
// 64 bits. The record's key, a contact's stamp and the found memo's fingerprint mix with it.
inline std::uint64_t mix_word(std::uint64_t h, std::uint64_t w) {
  return (h ^ w) * 0x9E37'79B9'7F4A'7C15u;
}

// `h` with the bits of point `v` mixed in as one word.
inline std::uint64_t mix_point(std::uint64_t h, const b2Vec2& v) {
  static_assert(sizeof(b2Vec2) == sizeof(std::uint64_t), "a point mixes in as one word");
  std::uint64_t word;
  std::memcpy(&word, &v, sizeof word);
  return mix_word(h, word);
}

// Most vertices a polygon fixture may have to hold fixed edge data: an 8-gon has no slot left
// (its contacts find its masks, as for a fixture never fixed).
constexpr int max_fixed_vertices = b2_maxPolygonVertices - 1;

// The key of fixture `fixture`'s record: its address, its body's and its shape's `vertices`
// mixed.
// Why: a shape copied out of a fixture (`GetShape`) carries the record along, and a
// default-constructed `b2PolygonShape` leaves the slots uninitialised; neither may read as edge
// data. Box2D's allocators hand a destroyed fixture's address to the next one, so the address
// alone would accept a copy recreated in its place; with the body and the vertices, a copy is
// accepted only as the same polygon on the same body, where the record still describes it.
// The constant makes a key unlike the float coordinates the slots hold otherwise. Never 0.
inline std::uint64_t edge_record_key(const b2Fixture& fixture, const b2Vec2* vertices, int count) {
  std::uint64_t key = static_cast<std::uint64_t>(reinterpret_cast<std::uintptr_t>(&fixture));
  key = mix_word(key, 0x5EED'ED6E'DA7A'0001u);
  key = mix_word(key, reinterpret_cast<std::uintptr_t>(fixture.GetBody()));
  for (int i = 0; i < count; ++i) key = mix_point(key, vertices[i]);
  return key | 1;
}

// The key of polygon fixture `fixture`'s record.
inline std::uint64_t edge_record_key(const b2Fixture& fixture) {
  const auto& polygon = *static_cast<const b2PolygonShape*>(fixture.GetShape());
  return edge_record_key(fixture, polygon.m_vertices, polygon.m_count);
}

// Where a polygon's record lives: the two vertex slots after its last vertex (up to 6 vertices),
// or a 7-gon's last vertex slot (the key) and last normal slot (the data); Box2D reads only
// `m_count` of each. The key's word, then the data's word.
inline void* record_key_slot(b2PolygonShape& p) { return &p.m_vertices[p.m_count]; }
inline void* record_data_slot(b2PolygonShape& p) {
  return p.m_count + 1 < b2_maxPolygonVertices ? static_cast<void*>(&p.m_vertices[p.m_count + 1])
                                               : static_cast<void*>(&p.m_normals[p.m_count]);
}

// The fixed edge data of polygon fixture `fixture` (masks bits 0..count−1, and its junction), or
// nothing: none written, or a polygon with no slot for it. The caller knows the shape is a polygon.
inline std::optional<PolygonEdgeData> fixed_polygon_record(const b2Fixture& fixture) {
  auto& polygon = *static_cast<b2PolygonShape*>(const_cast<b2Shape*>(fixture.GetShape()));
  if (polygon.m_count > max_fixed_vertices) return std::nullopt;
  std::uint64_t key;
  std::memcpy(&key, record_key_slot(polygon), sizeof key);
  if (key != edge_record_key(fixture)) return std::nullopt;
  PackedEdgeData data;
  std::memcpy(&data, record_data_slot(polygon), sizeof data);
  return unpack(data);
}

// The masks of `fixture_record`'s polygon for a body whose centroid is at `other` (the polygon's
// body frame): its fixed masks, and what its junction hides from that body (`junction_masks`).
inline ShapeMasks masks_facing(const PolygonEdgeData& record, const b2Fixture& fixture,
                               const b2Vec2& other) {
  ShapeMasks m = record.masks;
  if (record.junction.vertex == Junction::none) return m;
  const ShapeMasks hidden = junction_masks(
      record.junction, *static_cast<const b2PolygonShape*>(fixture.GetShape()), other);
  m.edges |= hidden.edges;
  m.closed_vertices |= hidden.closed_vertices;
  return m;
}

// The fixed masks of polygon fixture `fixture` (bits 0..count−1), or nothing (see
// `fixed_polygon_record`); without what a junction would hide.
inline std::optional<ShapeMasks> fixed_polygon_edges(const b2Fixture& fixture) {
  const std::optional<PolygonEdgeData> r = fixed_polygon_record(fixture);
  if (!r) return std::nullopt;
  return r->masks;
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

// How many fixed records were written, process-wide (every world's): a contact whose masks were
// found under a count knows that no fixture of it has been fixed since (`internal_edges_stamp`).
// Written between steps only (`fix_internal_edges`, `refresh_internal_edges`, `add_triangles`),
// read by every evaluation that answers afresh with the rule, on any thread.
inline std::atomic<std::uint32_t> fixed_records_written{0};

// `fixed_records_written`'s low 16 bits (`FoundMasks::fixed_since`).
inline std::uint16_t fixed_records_stamp() {
  return static_cast<std::uint16_t>(fixed_records_written.load(std::memory_order_relaxed));
}

// Writes `data` as the fixed edge data of polygon fixture `fixture` (`holds_edge_data`).
inline void write_fixed_edges(b2Fixture& fixture, const PolygonEdgeData& data) {
  fixed_records_written.fetch_add(1, std::memory_order_relaxed);
  auto& polygon = *static_cast<b2PolygonShape*>(fixture.GetShape());
  const std::uint64_t key = edge_record_key(fixture);
  const PackedEdgeData packed = pack(data);
  std::memcpy(record_key_slot(polygon), &key, sizeof key);
  std::memcpy(record_data_slot(polygon), &packed, sizeof packed);
}

// A two-sided edge fixture's record: the key in `m_vertex0`, what its ends meet in `m_vertex3`.
static_assert(sizeof(EdgeEnds) <= sizeof(b2Vec2), "an edge's ends fit its m_vertex3");

// True when `fixture` is a two-sided edge (whose ghost vertices Box2D leaves unread).
inline bool two_sided_edge(const b2Fixture& fixture) {
  return fixture.GetType() == b2Shape::e_edge &&
         !static_cast<const b2EdgeShape*>(fixture.GetShape())->m_oneSided;
}

// The key of two-sided edge fixture `fixture`'s record: over its two vertices.
inline std::uint64_t edge_ends_key(const b2Fixture& fixture) {
  const auto& edge = *static_cast<const b2EdgeShape*>(fixture.GetShape());
  const b2Vec2 vertices[2] = {edge.m_vertex1, edge.m_vertex2};
  return edge_record_key(fixture, vertices, 2);
}

// The fixed ends of two-sided edge fixture `fixture`, or nothing: none written.
inline std::optional<EdgeEnds> fixed_edge_ends(const b2Fixture& fixture) {
  const auto& edge = *static_cast<const b2EdgeShape*>(fixture.GetShape());
  std::uint64_t key;
  std::memcpy(&key, &edge.m_vertex0, sizeof key);
  if (key != edge_ends_key(fixture)) return std::nullopt;
  EdgeEnds ends{};
  std::memcpy(static_cast<void*>(&ends), &edge.m_vertex3, sizeof ends);
  return ends;
}

// Writes `ends` as the fixed edge data of two-sided edge fixture `fixture`.
inline void write_fixed_edge_ends(b2Fixture& fixture, EdgeEnds ends) {
  fixed_records_written.fetch_add(1, std::memory_order_relaxed);
  auto& edge = *static_cast<b2EdgeShape*>(fixture.GetShape());
  const std::uint64_t key = edge_ends_key(fixture);
  std::memcpy(static_cast<void*>(&edge.m_vertex0), &key, sizeof key);
  edge.m_vertex3.SetZero();
  std::memcpy(static_cast<void*>(&edge.m_vertex3), &ends, sizeof ends);
}

// True when `fixture` holds, or can hold, fixed edge data: a polygon of up to
// `max_fixed_vertices`, or a two-sided edge.
inline bool fixes_edge_data(const b2Fixture& fixture) {
  return holds_edge_data(fixture) || two_sided_edge(fixture);
}

// Gives `fixtures` (polygons and two-sided edges of `world`, `fixes_edge_data`) fixed edge data
// and finds it again for every fixed fixture next to them: `fix_internal_edges` and
// `add_triangles`.
void fix_fixtures(b2World& world, const std::vector<b2Fixture*>& fixtures);

}  // namespace dyop::box2d::detail
