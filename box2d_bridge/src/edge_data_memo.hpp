#pragma once
// Internal: a static polygon fixture's edge data as last found (`polygon_edge_data`), memoised in
// its own shape with the fingerprint of everything it was found from (`Group::fingerprint` in
// internal_edges.cpp: the polygon, its body's frame, and every fixture the broad phase could give
// its group, their frames, shapes and flags). The edge data is a function of that alone, so the
// same fingerprint gives the same data however the world got there, in any world and after any
// change: nothing is invalidated, a change just fingerprints otherwise. Kept after the fixed
// record's slots (edge_data.hpp), in the shape's spare normal slots, which Box2D never reads.

#include <box2d/b2_fixture.h>
#include <box2d/b2_polygon_shape.h>

#include <cstdint>
#include <cstring>
#include <optional>

#include "edge_data.hpp"

namespace dyop::box2d::detail {

// Most vertices a polygon fixture may have to hold the memo: two normal slots past the fixed
// record's (a 7-gon's record takes its last normal slot).
constexpr int max_memo_vertices = b2_maxPolygonVertices - 2;

// The memo's slots: the fingerprint's word, then the data's word; nullptr for a polygon of more
// than `max_memo_vertices`.
inline b2Vec2* memo_slots(const b2Fixture& fixture) {
  auto& polygon = *static_cast<b2PolygonShape*>(const_cast<b2Shape*>(fixture.GetShape()));
  return polygon.m_count <= max_memo_vertices ? &polygon.m_normals[polygon.m_count] : nullptr;
}

// The edge data memoised for polygon fixture `fixture` under `fingerprint`, or nothing (another
// fingerprint, never memoised, or too many vertices).
inline std::optional<PolygonEdgeData> memoised_edge_data(const b2Fixture& fixture,
                                                         std::uint64_t fingerprint) {
  const b2Vec2* slots = memo_slots(fixture);
  if (!slots) return std::nullopt;
  std::uint64_t held;
  std::memcpy(&held, &slots[0], sizeof held);
  if (held != fingerprint) return std::nullopt;
  PackedEdgeData data;
  std::memcpy(static_cast<void*>(&data), &slots[1], sizeof data);
  return unpack(data);
}

// Memoises `data` as polygon fixture `fixture`'s edge data found under `fingerprint` (nothing for
// a polygon of more than `max_memo_vertices`). Written in the world's memory, during a step: only
// the thread stepping the fixture's world reaches it.
inline void memoise_edge_data(const b2Fixture& fixture, std::uint64_t fingerprint,
                              const PolygonEdgeData& data) {
  b2Vec2* slots = memo_slots(fixture);
  if (!slots) return;
  const PackedEdgeData packed = pack(data);
  std::memcpy(static_cast<void*>(&slots[0]), &fingerprint, sizeof fingerprint);
  std::memcpy(static_cast<void*>(&slots[1]), &packed, sizeof packed);
}

}  // namespace dyop::box2d::detail
