#pragma once
/// \file
/// Measurement only: what the plug-in's narrow phase could cost at the least inside Box2D 2.4.
/// Not a backend, never offered as one (`parse_backend` does not know it): a world stepped under
/// it is physically wrong.

#include <box2d/b2_polygon_shape.h>

#include <vector>

#include "dyop/box2d.hpp"

class b2Contact;

namespace dyop::box2d::measurement {

/// Installs `backend` with `config` as `install` does, except that every contact made from now on
/// keeps its first answer for good (a manifold with points, an empty one, a skip): its `Evaluate`
/// returns at once after that. What is left of a step's narrow phase is Box2D's own walk of its
/// contact list, the fat-AABB tests and `b2Contact::Update`'s bookkeeping: the floor any narrow
/// phase plugged into Box2D 2.4 pays. Bodies fall through each other once their first answers are
/// stale; measure the narrow phase of a few hundred steps, not what the world does. `installed()`
/// reports `backend`; `install` or `uninstall` ends it. Same threading rules as `install`.
InstallResult install_never_recompute(Backend backend, const Config& config = Config::all());

/// The manifold `contact` (a contact of a world, of any pair family the plug-in answers) would get
/// now if it kept nothing: the plug-in's contact evaluated afresh at its bodies' current transforms
/// with the installed setting and its own internal-edge masks (`Config::recycle_distance`
/// ignored), without changing the contact; a contact Box2D's own code made, or any contact while
/// uninstalled, Box2D's own function for its pair. Counted in `stats` like any evaluation. What a
/// kept manifold is measured against. For a circle–circle contact, `manifold` gets no points.
void evaluate_afresh(const b2Contact& contact, b2Manifold* manifold);

/// One answer afresh of a triangle pair as a world's contact of the plug-in made it: the shapes,
/// the bodies' transforms, and the pair's memory as the answer began with the masks its solver
/// read in `internal_edges` (none where it answered without: apart beyond the skins).
struct RecordedAnswer {
  b2PolygonShape a;      ///< fixture A's triangle, as Box2D holds it
  b2PolygonShape b;      ///< fixture B's triangle
  b2Transform xf_a;      ///< A's body transform the answer used (world frame)
  b2Transform xf_b;      ///< B's body transform
  ContactMemory memory;  ///< as the answer began, `internal_edges` the masks its solver read
};

/// From now on, every answer afresh of a triangle pair made on the calling thread is appended to
/// `into` (nullptr: no more): replayed through `collide_polygons` (with a copy of its `memory`:
/// the same skips fail, the same masks are read) and through `b2CollidePolygons`, the same pairs
/// cost what the world's answers cost, act by act. Costs the evaluation one test while off.
void record_answers(std::vector<RecordedAnswer>* into);

}  // namespace dyop::box2d::measurement
