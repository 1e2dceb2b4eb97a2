#pragma once
/// \file
/// Checks the manifolds a Box2D world's solver gets against the exact answer for the same pose:
/// a contact listener whose `PreSolve` runs right after `b2Contact::Update` evaluated a touching
/// contact (or kept its manifold: `box2d::Config::recycle_distance`), with the transforms that
/// evaluation saw. Per touching pair, every separation computed as the solver does
/// (`b2WorldManifold`: a point's distance from the reference face, skins left out, a circle's
/// radius taken off), in A's body frame in double; polygon pairs of more vertices and
/// polygon–circle pairs (the exact solver, `dyop::collide` in double) as triangle pairs:
/// - what keeping costs: |the manifold's deepest separation − that of the manifold the runner
///   computes afresh for the same pose| (`box2d::measurement::evaluate_afresh`), and how many kept
///   manifolds had points where the fresh one has none;
/// - for a pair whose cores penetrate exactly (`sat` in double on the float shapes, B moved into
///   A's frame in double: `exact_pair`), the depth error |deepest separation − exact separation|
///   and the normal error: how much deeper the pair overlaps along the manifold's normal than the
///   exact depth (metres, ≥ 0; 0 when the normal is a minimum-overlap axis, so ties cost nothing).
/// Slows the narrow phase (an exact query per touching pair): for accuracy runs, never for timing.

#include <box2d/b2_world_callbacks.h>

#include "scenes/exact_pair.hpp"
#include "scenes/metrics.hpp"

namespace dyop::scenes {

/// The listener: set it on a world with `SetContactListener` (it keeps no pointer to the world).
class ManifoldCheck : public b2ContactListener {
 public:
  void PreSolve(b2Contact* contact, const b2Manifold* old_manifold) override;
  /// The errors so far.
  const ManifoldErrors& errors() const { return errors_; }

 private:
  // Counts the touching pair and what keeping cost it: `deepest` against the deepest separation
  // of the manifold the contact computes afresh (both as `deepest_separation` gives them).
  void record_kept(const b2Contact& contact, const FrameBInA& frame, double deepest);

  ManifoldErrors errors_;
};

}  // namespace dyop::scenes
