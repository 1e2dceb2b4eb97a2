#pragma once
// Internal: manifold recycling (`Config::recycle_distance`). A world's contact keeps the manifold
// Box2D hands back to it while the relative pose of its two shapes has moved less than a
// tolerance since the manifold was computed.
//
// Why keeping is sound in Box2D 2.4: `b2Manifold` is in the bodies' own frames, and the solver
// recomputes every separation from the current transforms (`b2WorldManifold`,
// `b2PositionSolverManifold`); a kept manifold keeps its anchors and gets its separations anew,
// and `b2Contact::Update` carries the impulses over by `id.key` as for any manifold. What a kept
// manifold misses is a change of features (a vertex coming within the skins, a point sliding off
// a face's end): bounded by how far the pose moved.
//
// The motion, in A's frame, of B against A since the manifold was computed: every vertex of B
// moved by at most |Δc| + 2·sin(Δθ/2)·r_B (c: B's centroid, Δθ: the relative turn, r_B: B's
// radius about c), and every face normal of either triangle turned by Δθ against the other
// triangle, which moves a separation by at most 2·sin(Δθ/2) times the distance from the face to
// the other triangle's vertex, at most 2·radius_sum + reach while the pair is within reach. With
// the turn bounded (cos Δθ ≥ `recycle_cosine`, so 2·sin(Δθ/2) ≤ 1.006·|sin Δθ|), every face
// separation of the pair moved by at most
//     motion = |Δc| + |sin Δθ| · lever,   lever = 1.01 · (3·radius_sum + reach).
// No square root: |Δc| is compared squared.

#include <box2d/b2_math.h>

#include <cmath>
#include <cstdint>

#include "dyop/box2d.hpp"

namespace dyop::box2d::detail {

// A relative turn with a cosine below this always recomputes (about 11.5°). Why: Box2D v3.2's
// recycling uses the same bound; beyond it |sin| no longer bounds the turn's chord well, and a
// pair turning that much in a step is no resting pair.
constexpr float recycle_cosine = 0.98f;

// A pair with a static body keeps its manifold within this share of `Config::recycle_distance`
// only. Why: a kept manifold misses a vertex coming within the skins until the pose has moved the
// distance, and a body that sinks that much deeper into static ground meets Box2D 2.4's
// time-of-impact pass, which sweeps moving bodies against static ones (and rescans the contact
// list for every event); not keeping static pairs at all costs resting piles more (measured:
// docs/measurements.md, "Choices in the code").
constexpr float static_pair_share = 0.2f;

// What a world's contact remembers of the manifold it keeps: 24 bytes.
struct ManifoldRecycling {
  b2Rot q;                // B's body frame in A's when the manifold was computed: rotation
  b2Vec2 centroid{0, 0};  // ... and B's centroid then, in A's frame (b2MulT(xf_a, xf_b) applied)
  // How far (motion, metres) the pose may move before a recompute; 0: never; below 0: an
  // evaluation since was skipped (`lose_pose`), so the pose is not the pair's last.
  float slack = 0;
  std::uint8_t epoch = 0;  // the install the manifold was computed under (`Setting::epoch`)

  // An evaluation skipped the pair (nothing computed, nothing kept): where it went since the pose
  // is unknown.
  void lose_pose() { slack = -1; }

  // Remembers the pose (`turn`: B's body frame's rotation in A's; `centroid_in_a`: B's centroid
  // in A's frame) of a manifold just computed under install `epoch`, which may be kept while it
  // moves less than `slack` (≤ 0: never).
  void remember(const b2Rot& turn, const b2Vec2& centroid_in_a, float keep_within,
                std::uint8_t install_epoch) {
    q = turn;
    centroid = centroid_in_a;
    slack = keep_within;
    epoch = install_epoch;
  }

  // True when the manifold computed at the remembered pose may be kept at the pose now (`turn`,
  // `centroid_in_a`, as `remember` takes them): computed under this install, the turn within
  // `recycle_cosine`, and the motion (see the file's head) below the slack. `lever`: see the
  // file's head.
  bool keeps(const b2Rot& turn, const b2Vec2& centroid_in_a, float lever,
             std::uint8_t install_epoch) const {
    if (!(slack > 0) || epoch != install_epoch) return false;
    const float cos_turn = q.c * turn.c + q.s * turn.s;
    if (!(cos_turn >= recycle_cosine)) return false;
    const float sin_turn = q.c * turn.s - q.s * turn.c;
    const float room = slack - std::abs(sin_turn) * lever;
    if (!(room > 0)) return false;
    return (centroid_in_a - centroid).LengthSquared() < room * room;
  }

  // How far the pair has moved from the remembered pose to the pose now (`turn`,
  // `centroid_in_a`) at most (the motion of the file's head), or infinity when no pose was
  // remembered under install `install_epoch`, an evaluation since was skipped, or the turn is
  // beyond `recycle_cosine` (where the lever no longer bounds it).
  float motion(const b2Rot& turn, const b2Vec2& centroid_in_a, float lever,
               std::uint8_t install_epoch) const {
    const float cos_turn = q.c * turn.c + q.s * turn.s;
    if (slack < 0 || epoch != install_epoch || !(cos_turn >= recycle_cosine)) return HUGE_VALF;
    const float sin_turn = q.c * turn.s - q.s * turn.c;
    return (centroid_in_a - centroid).Length() + std::abs(sin_turn) * lever;
  }
};

// The lever of the motion bound (see the file's head) for a pair of `radius_sum`
// (`ContactMemory::radius_sum`) and skins summing to `margin`.
inline float recycle_lever(float radius_sum, float margin) {
  return 1.01f * (3 * radius_sum + reach(margin));
}

}  // namespace dyop::box2d::detail
