#pragma once
/// \file
/// Real contact streams: what a Box2D world asks of its narrow phase, recorded once and replayed
/// through every backend (the "Contact streams" section of `dyop bench`).
///
/// Recording runs a catalogue scene under Box2D's own polygon contact (the plug-in uninstalled)
/// and, before each `b2World::Step` from step 2 on, walks the contact list and keeps every
/// polygon–polygon contact the step's `Collide` will update (`collide_action`): the two shapes as
/// Box2D holds them and the two body transforms `Collide` will use. Step 1 is left out: its
/// contacts are created inside `Step`. Circle and edge contacts are not recorded (the plug-in never
/// sees them); polygon pairs with a side of more than 3 vertices are, as the plug-in receives them
/// too (and passes them to `b2CollidePolygons`). Not in the stream: the re-evaluations of
/// Box2D's continuous collision (`b2World::SolveTOI` updates a contact again, bodies moved to the
/// time of impact, when the step's motion would carry a dynamic body into a static or kinematic
/// one); they cannot be seen from outside `Step` without replacing Box2D's contact. A world whose
/// bodies fall onto static ground (rain) makes a few per cent more evaluations than its stream
/// holds (`world_evaluations` counts them).
///
/// Replaying feeds the calls, in order, to `dyop::box2d::collide_polygons` with one
/// `ContactMemory` per recorded contact kept across the stream, as a contact keeps it in a world,
/// and to `b2CollidePolygons` directly (the reference, "box2d-own"). The first recorded call of a
/// contact starts from an empty memory; in the world it had already seen the evaluation of the step
/// that created it when that was step 1.

#include <box2d/b2_collision.h>
#include <box2d/b2_math.h>
#include <box2d/b2_polygon_shape.h>

#include <cstdint>
#include <iosfwd>
#include <string>
#include <string_view>
#include <vector>

#include "dyop/box2d.hpp"
#include "scenes/runner.hpp"
#include "scenes/scene.hpp"

namespace dyop::experiments {

/// One contact of a stream: the two shapes exactly as Box2D held them (`m_count`, `m_vertices`,
/// `m_normals`, `m_centroid`, `m_radius`, body frames, metres). A fixture's shape never changes,
/// so the shapes are recorded once per contact, not per call.
struct StreamContact {
  b2PolygonShape shape_a;  ///< fixture A's polygon
  b2PolygonShape shape_b;  ///< fixture B's polygon
  /// True when both are triangles (`m_count == 3`): the pairs the plug-in's backend answers.
  bool triangles = false;
  /// The pair's internal-edge masks in the world (`triangle_internal_edges` of each fixture,
  /// A's bits then B's) when it was made; none for polygons of more vertices.
  InternalEdges internal_edges{};
};

/// One contact update: an `Evaluate` of a step.
struct StreamCall {
  /// Index in `ContactStream::contacts`. One id per contact lifetime: a contact that Box2D
  /// destroys and later creates again (fat AABBs apart, then overlapping) gets a new id, as the
  /// new contact starts with a new memory in the world.
  std::int32_t contact = 0;
  std::int32_t step = 0;  ///< the step (1-based) whose `Collide` made the call; ≥ 2
  b2Transform xf_a;       ///< body A's transform (position in metres)
  b2Transform xf_b;       ///< body B's transform (position in metres)
};

/// A recorded stream.
struct ContactStream {
  std::string scene;                    ///< catalogue name
  std::uint64_t seed = 0;               ///< the scene's seed
  int steps = 0;                        ///< steps run (calls come from steps 2..steps)
  std::vector<StreamContact> contacts;  ///< by id
  std::vector<StreamCall> calls;        ///< in the order the steps' `Collide` made them
  /// Calls whose contact is a triangle pair.
  std::uint64_t triangle_calls() const;
};

/// The Box2D scenes of the catalogue (every scene but `paper`), in catalogue order.
std::vector<std::string> stream_scenes();

/// Uninstalls the plug-in (Box2D's own contact for every pair), builds scene `name` with `seed`
/// as the catalogue does, runs `steps` steps and returns every polygon-pair update of steps
/// 2..steps. Throws `std::invalid_argument` for an unknown scene, `paper` (no Box2D world) or
/// fewer than 2 steps.
ContactStream record_stream(std::string_view name, int steps, std::uint64_t seed);

/// The polygon-pair evaluations the world of scene `name` makes in steps 2..`steps`, counted by
/// the plug-in answering with `b2CollidePolygons` (`Backend::Box2D`, bit-identical to Box2D's own
/// contact): the stream's calls plus Box2D's time-of-impact re-evaluations. Throws as
/// `record_stream`, and `std::runtime_error` when the plug-in cannot be installed.
std::uint64_t world_evaluations(std::string_view name, int steps, std::uint64_t seed);

/// How one replay of a stream agrees with `b2CollidePolygons`, call by call. World quantities
/// come from `b2WorldManifold` on both manifolds with the recorded transforms and skins.
struct StreamAgreement {
  std::uint64_t calls = 0;             ///< calls compared (the whole stream)
  std::uint64_t same_point_count = 0;  ///< calls with as many points as the reference
  /// Calls where both manifolds have points: those where the face, the normal and the separation
  /// are compared.
  std::uint64_t both_points = 0;
  /// Of `both_points`, calls with the same reference side (`e_faceA` / `e_faceB`) and edge (the
  /// reference polygon's normal nearest `localNormal`).
  std::uint64_t same_face = 0;
  double normal_angle_max = 0;     ///< largest angle between the world normals (rad)
  double separation_diff_max = 0;  ///< largest |deepest separation − reference's| (metres)
};

/// The figures of one runner on one stream.
struct StreamRunnerResult {
  /// A backend of the plug-in (through `collide_polygons`), or nothing: `b2CollidePolygons`
  /// called directly (the reference, spelt `box2d_own`).
  scenes::Runner runner;
  double ns_per_call = 0;         ///< best pass, ns per call over the whole stream
  double ratio_vs_box2d_own = 0;  ///< `ns_per_call` / box2d-own's, same run
  StreamAgreement agreement;      ///< against `b2CollidePolygons` (box2d-own: with itself)
};

/// The figures of one scene's stream.
struct StreamResult {
  std::string scene;                    ///< catalogue name
  int steps = 0;                        ///< steps recorded
  std::uint64_t contacts = 0;           ///< contact lifetimes met
  std::uint64_t calls = 0;              ///< recorded calls
  std::uint64_t triangle_calls = 0;     ///< calls on triangle pairs
  std::uint64_t calls_with_points = 0;  ///< calls where `b2CollidePolygons` gives points
  /// Polygon-pair evaluations the world itself made in the same steps (`world_evaluations`): the
  /// recorded calls plus the time-of-impact re-evaluations; 0 when not counted.
  std::uint64_t world_evaluations = 0;
  std::vector<StreamRunnerResult>
      runners;  ///< every backend in `all_backends` order, then box2d-own
};

/// What `run_streams` records and how it times the replays.
struct StreamOptions {
  std::vector<std::string> scenes = stream_scenes();  ///< recorded and replayed in this order
  /// Steps per scene. 600 (10 s): falling, landing and resting, as the catalogue's full runs;
  /// `dyop bench --quick` uses 120.
  int steps = 600;
  std::uint64_t seed = 1;  ///< the scenes' seed, as `dyop bench`'s scaling runs
  /// Timed passes per runner, the best kept; runners alternate pass by pass so that a noisy
  /// moment of the shared machine hurts one pass of each, not one runner.
  int passes = 5;
  /// A pass repeats the stream until it has run this long (ms): shorter timings are dominated by
  /// the clock's resolution and the scheduler.
  double min_pass_ms = 20;
  box2d::Config config = box2d::Config::all();  ///< the plug-in's skips
};

/// Replays `stream` through `backend` once, untimed, with fresh memories and `config`, and
/// compares every call with `b2CollidePolygons`. Throws `std::invalid_argument` for an empty
/// stream.
StreamAgreement compare_with_box2d(const ContactStream& stream, box2d::Backend backend,
                                   const box2d::Config& config = box2d::Config::all());

/// Replays `stream` through `backend` once, untimed, with fresh memories and `config`: the
/// manifold of every call, in order. Throws `std::invalid_argument` for an empty stream.
std::vector<b2Manifold> replay_manifolds(const ContactStream& stream, box2d::Backend backend,
                                         const box2d::Config& config = box2d::Config::all());

/// Times and compares every backend and box2d-own on `stream`. Throws `std::invalid_argument` for
/// an empty stream or `options.passes` < 1.
StreamResult measure_stream(const ContactStream& stream, const StreamOptions& options);

/// Records and measures every scene of `options`; progress lines on `progress`. Throws as
/// `record_stream` and `measure_stream`.
std::vector<StreamResult> run_streams(const StreamOptions& options, std::ostream& progress);

}  // namespace dyop::experiments
