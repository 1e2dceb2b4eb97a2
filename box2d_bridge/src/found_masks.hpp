#pragma once
// Internal: what a world's contact remembers of the internal-edge masks it holds
// (`ContactMemory::internal_edges`), and when they still hold. Fixed edge data
// (`fix_internal_edges`) needs none of it; a contact of fixtures without it finds its masks
// itself and follows the world's changes that could alter them: the install and its static
// bodies' frames (the stamp), the world's fixture count, and its own motion since that count moved.

#include <box2d/b2_settings.h>

#include <cmath>
#include <cstdint>

namespace dyop::box2d::detail {

// 8 bytes: the contact's size budget counts on it (contact.cpp).
struct FoundMasks {
  // The masks were read from the two fixtures' fixed edge data: a refresh makes the contact
  // recompute (`refresh_internal_edges`), so nothing is followed.
  static constexpr std::uint16_t fixed_stamp = 0xFFFF;
  // `motion` of masks not found under the stamp (put off: every answer under it was apart beyond
  // the margin, the same under any masks).
  static constexpr float not_found = HUGE_VALF;

  // How far (metres, a bound) the pair has moved since the world's fixture count first moved
  // from `fixtures`: below 0 while it has not; `not_found` when the masks do not hold (not found
  // under `stamp`, moved too far, or a skip lost the pose).
  float motion = not_found;
  // What the masks hold under: 0 none (never seen, or forgotten); `fixed_stamp`; else the install
  // and the frames of the pair's static bodies, folded (`Contact::internal_edges_stamp`).
  std::uint16_t stamp = 0;
  // The world's count of fixture proxies (low 16 bits) when the masks were found; for fixed
  // masks, the count of fixed records written then (`fixed_since`).
  std::uint16_t fixtures = 0;

  bool fixed() const { return stamp == fixed_stamp; }
  // Fixed masks read when the process had written `records` fixed records (low 16 bits, in
  // `fixtures`) and free of the bodies' poses (`motion` 0): they hold, nothing need be read.
  bool fixed_since(std::uint16_t records) const {
    return stamp == fixed_stamp && motion == 0 && fixtures == records;
  }
  // Fixed masks just read under `records`; `junction`: they depend on the bodies' poses.
  void fixed_now(std::uint16_t records, bool junction) {
    stamp = fixed_stamp;
    fixtures = records;
    motion = junction ? not_found : 0;
  }
  // Found under `stamp` and still holding (settled, or followed since the count moved).
  bool found() const { return motion != not_found; }
  // Found under `stamp` and not moved since the world's fixture count did: lent to the pair's
  // other contacts and read by `contact_internal_edges`.
  bool settled() const { return motion < 0; }
  void found_now(std::uint16_t world_fixtures) {
    fixtures = world_fixtures;
    motion = -1;
  }
};

// How far a pair may have moved since it first saw the world's fixture count move, before it
// finds its masks again (metres). Why this: a fixture made or destroyed with no contact to either
// body of the pair had no fattened broad-phase box overlapping theirs. Box2D fattens a box by
// `b2_aabbExtension` (0.1 m) on every side when it (re)inserts it, and a moving body may then
// travel to the edge of its own, so only the other's margin is sure: the fixture lay more than
// 0.1 m from the pair, and its edges come within the skins (2 cm) only once the pair moved
// 0.08 m. Half the margin stays clear of that.
constexpr float masks_reach = 0.5f * b2_aabbExtension;

// True while masks found may still be used: settled, or the motion followed since the count
// moved, plus twice `recycle_distance` (a kept manifold's pose may lie that far from the pose at
// the change, before it and after the last answer afresh), below `masks_reach`.
inline bool masks_hold(const FoundMasks& m, float recycle_distance) {
  return m.motion < 0 || m.motion + 2 * recycle_distance < masks_reach;
}

// The world's fixture count as it is now (`world_fixtures`): once it moved from the count the
// masks were found under, the pair's motion is followed from then on (from below 0 to 0),
// whatever the count does after (it may come back by other changes). At every evaluation that
// may read the masks: a kept manifold and an answer afresh.
inline void notice_fixture_count(FoundMasks& m, std::uint16_t world_fixtures) {
  if (m.fixtures != world_fixtures && m.motion < 0) m.motion = 0;
}

}  // namespace dyop::box2d::detail
