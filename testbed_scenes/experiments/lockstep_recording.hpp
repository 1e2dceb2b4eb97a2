#pragma once
/// \file
/// One scene recorded under two runners, step by step, for `dyop view`: the bodies' poses and
/// the contacts (points, normals, separations, reference faces, feature keys) after every step,
/// side by side, with what the two runners agree on and where the plug-in's manifold differs from
/// `b2CollidePolygons` on the same pose.
///
/// Box2D's contact registry is process-wide, so the two worlds are not stepped at once: runner
/// A's world is built and run for every step, then runner B's from the same seed. Both are
/// deterministic, so frame `i` of each is its world after step `i + 1` exactly as if they had
/// been stepped in turn (and without re-installing a backend between their steps, which would
/// make the plug-in find its internal-edge masks again every step).
///
/// Conventions (as Box2D's `b2WorldManifold`): positions in world metres, y up; a contact's
/// normal is a unit vector from fixture A to fixture B; a point is the midpoint between the two
/// surfaces and its separation is negative when they overlap. Points are drawn at the poses after
/// the step, from the manifold the step's `Collide` made at the poses before it (as Box2D's
/// samples draw them).

#include <box2d/b2_math.h>

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "dyop/box2d.hpp"
#include "scenes/drawing.hpp"
#include "scenes/runner.hpp"
#include "scenes/world.hpp"

namespace dyop::experiments {

/// Two runners' contacts on the same pair agree when their deepest separations differ by at
/// most this (metres). Why: a millimetre is a fifth of Box2D's linear slop (5 mm, the overlap the
/// solver leaves on purpose), far below what a trip or a ghost collision shows, far above float
/// rounding of a separation in the scenes' worlds.
inline constexpr double agreement_tolerance = 1e-3;

/// The plug-in's normal counts as redirected from `b2CollidePolygons`' when they differ by more
/// than this (radians, about 0.6°). Why: the exact backends choose the same face as Box2D but
/// for the internal-edge rule, and float rounding turns a normal by about 1e-7.
inline constexpr double redirect_angle = 0.01;

/// One fixture, in its body's frame (metres).
struct ViewFixture {
  int body = 0;  ///< index in `LockstepRecording::bodies`
  scenes::DrawShape::Kind kind = scenes::DrawShape::Kind::Polygon;
  /// Polygon: its vertices in Box2D's order (`m_vertices`: its edge i runs from vertex i to
  /// i + 1, the reference edge's numbering); circle: its centre; segment: its two ends.
  std::vector<b2Vec2> points;
  float radius = 0;  ///< `b2Shape::m_radius`: a circle's radius, a polygon's or edge's skin
  /// Whose world holds it: -1 both runners' (a scene), 0 or 1 runner A's or B's alone (a level
  /// built two ways: `record_sides`), drawn on that runner's side only.
  int side = -1;
  /// The frames it is in (frame i: the world after step i + 1): from `appears` to before
  /// `disappears` (-1: to the last). Only a ground edited while it is recorded (`record_edited`)
  /// has fixtures that come and go.
  int appears = 0;
  int disappears = -1;
};

/// Where a body is after a step.
struct BodyPose {
  float x = 0, y = 0;  ///< its origin (m)
  float angle = 0;     ///< radians
};

/// One manifold as `b2WorldManifold` gives it, with the manifold's own bookkeeping.
struct ViewManifold {
  enum class Reference : std::uint8_t { Circles, FaceA, FaceB };
  int points = 0;  ///< 0, 1 or 2: the fields below are valid for `points` > 0
  Reference reference = Reference::Circles;  ///< `b2Manifold::type`
  /// Faces: the reference polygon's edge (`reference_edge`); circles: 0.
  int reference_edge = 0;
  b2Vec2 normal{0, 0};  ///< unit, from A to B (world)
  /// `b2Manifold::localNormal` and `localPoint`: in the reference body's frame (circles: A's
  /// frame, the normal unused), so that the page can place them from the poses.
  b2Vec2 local_normal{0, 0};
  b2Vec2 local_point{0, 0};
  struct Point {
    b2Vec2 position{0, 0};  ///< midpoint between the surfaces (world, m)
    float separation = 0;   ///< negative when overlapping (m)
    std::uint32_t key = 0;  ///< `b2ContactID::key`: the feature pair warm starting matches on
    /// `b2ManifoldPoint::localPoint`: the clip point in the incident body's frame (faces), B's
    /// centre in B's frame (circles).
    b2Vec2 local{0, 0};
  };
  std::array<Point, 2> point{};
  /// The least separation of its points (m); 0 without points.
  float deepest() const;
};

/// How the plug-in's manifold differs from `b2CollidePolygons` on the same pose (polygon pairs
/// of a plug-in runner; with `dyop` and `sat` this is the internal-edge rule at work).
enum class EdgeMark : std::uint8_t {
  None,        ///< the same points or both none, normals within `redirect_angle`
  Removed,     ///< Box2D's code has points, the plug-in none
  Redirected,  ///< both have points, normals more than `redirect_angle` apart
};

/// One contact after a step: a touching one (points), or one the plug-in removed.
struct ViewContact {
  int fixture_a = 0;  ///< index in `LockstepRecording::fixtures`
  int fixture_b = 0;
  ViewManifold manifold;  ///< the runner's
  EdgeMark mark = EdgeMark::None;
  ViewManifold box2d;  ///< `b2CollidePolygons` on the same pose; valid when `mark` is not None
  /// The other runner has the same pair touching, deepest separations within
  /// `agreement_tolerance`.
  bool agrees = false;
};

/// One runner's world after one step.
struct ViewFrame {
  std::vector<BodyPose> poses;        ///< every body, in `LockstepRecording::bodies` order
  std::vector<ViewContact> contacts;  ///< sorted by (fixture_a, fixture_b)
  double collide_ms = 0;  ///< Box2D's `b2Profile::collide` of the step (paper: the calls, timed)
  int touching = 0;       ///< contacts with points
  int agreeing = 0;       ///< of those, the ones that agree
  double max_penetration = 0;  ///< the largest −separation of any point, ≥ 0 (m)
};

/// A scene under two runners.
struct LockstepRecording {
  std::string scene;
  std::uint64_t seed = 0;
  int steps = 0;
  double time_step = 0;  ///< seconds per step
  std::array<scenes::Runner, 2> runners;
  /// Each runner's skips and internal-edge rule (`box2d::Config`; nothing to Box2D's own contact).
  std::array<box2d::Config, 2> configs;
  std::vector<scenes::DrawShape::Role> bodies;  ///< each body's role (its colour)
  std::vector<ViewFixture> fixtures;
  std::array<std::vector<ViewFrame>, 2> frames;  ///< per runner, one per step
};

/// One side's world for `record_sides`, built under that side's runner: the first `own_bodies`
/// of `world->bodies()` are this side's alone (its ground), the others the moving bodies, made in
/// the same order with the same fixtures on both sides. `owner` keeps the world and what its
/// ground needs alive while it is recorded.
struct SideWorld {
  std::shared_ptr<void> owner;
  scenes::World* world = nullptr;
  int own_bodies = 0;
};

/// Records two worlds that differ in their grounds (`dyop compare`'s grounds section: a level as
/// Box2D's chains and through the plug-in's builders): `build(side)` makes side 0's world under
/// `runners[0]` with `configs[0]`, then side 1's; each is stepped `steps` (≥ 1) times. Bodies and
/// fixtures: A's own, B's own, then the shared ones (`ViewFixture::side`); a chain is drawn as its
/// edges, one segment fixture per child, and its contacts name their child's. Only the shared
/// bodies' contacts can agree. Throws `std::invalid_argument` for `steps` < 1 and
/// `std::logic_error` when a side builds no world or the sides' moving bodies differ.
LockstepRecording record_sides(std::string name, const std::array<scenes::Runner, 2>& runners,
                               int steps, const std::array<box2d::Config, 2>& configs,
                               const std::function<SideWorld(int side)>& build);

/// A world whose ground is edited while it is recorded, for `record_edited`: `bodies` every body
/// drawn (the ground's and the moving ones, in that order; none is created or destroyed while it
/// runs); `before_step(step)` called before step `step` (0-based) edits the ground and may push
/// bodies, true when it changed fixtures. `owner` keeps the world and its ground alive while it is
/// recorded.
struct EditedWorld {
  std::shared_ptr<void> owner;
  scenes::World* world = nullptr;
  std::vector<b2Body*> bodies;
  std::function<bool(int step)> before_step;
};

/// Records one world whose ground changes between steps (`dyop compare`'s terrain section: craters
/// dug under a crowd), built by `build(side)` under `runners[side]` with `configs[side]` and
/// stepped `steps` (≥ 1) times. A fixture an edit destroyed (or whose shape it changed) ends there
/// (`ViewFixture::disappears`); one it created takes the next index (`ViewFixture::appears`), in
/// body order, then each body's fixture-list order. Both sides must make the same fixtures at the
/// same steps: edits that depend on nothing the runner changes. Throws `std::invalid_argument` for
/// `steps` < 1 and `std::logic_error` when a side builds no world or the two sides' fixtures
/// differ.
LockstepRecording record_edited(std::string name, const std::array<scenes::Runner, 2>& runners,
                                int steps, const std::array<box2d::Config, 2>& configs,
                                const std::function<EditedWorld(int side)>& build);

/// Records scene `name` of the catalogue for `steps` steps (≥ 1) under `runners[0]` with
/// `configs[0]` and then `runners[1]` with `configs[1]` (the same runner twice with two configs
/// sets skips, recycling or the internal-edge rule against each other). `paper` has no Box2D
/// world: its triangles follow their paths and each step's overlapping pairs go to the runner's
/// collide function directly (`box2d-own`: `b2CollidePolygons`). Throws `std::invalid_argument`
/// for an unknown scene or `steps` < 1, `std::runtime_error` for a refused installation.
LockstepRecording record_lockstep(std::string_view name,
                                  const std::array<scenes::Runner, 2>& runners, int steps,
                                  std::uint64_t seed,
                                  const std::array<box2d::Config, 2>& configs = {
                                      box2d::Config::all(), box2d::Config::all()});

}  // namespace dyop::experiments
