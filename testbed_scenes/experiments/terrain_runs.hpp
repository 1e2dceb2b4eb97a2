#pragma once
/// \file
/// A chunked terrain (`dyop::box2d::OutlineTerrain`) played as a game plays it, for `dyop
/// compare`'s terrain section, with the plug-in installed: craters dug under and beside a crowd
/// resting and sliding on the 300 m level with caves (what each edit costs, what the step after it
/// costs, and what the bodies feel), and bodies sliding a kilometre across a level streamed around
/// them (their glide across the chunks' seams, what stays loaded, the memory beside Box2D's chain
/// and `add_outline`).
///
/// Units: metres, seconds, m/s; times in milliseconds; bytes are Box2D 2.4.1's objects on x86-64
/// (`experiments/ground_measures.hpp`) and the terrain's own estimate (`OutlineTerrain::bytes`).

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <box2d/b2_math.h>

#include "dyop/box2d.hpp"
#include "experiments/lockstep_recording.hpp"

namespace dyop::experiments {

/// True when this build has `dyop::box2d_outlines` (GEOS), which the terrain needs; the runs
/// below throw `std::runtime_error` without it.
bool terrain_available();

/// The crater scene's steps between two craters (4 a second at 60 steps a second).
inline constexpr int crater_interval_steps = 15;

/// How much the terrain section runs.
struct TerrainTiming {
  int crater_steps = 600;    ///< steps of the crater scene after the crowd settled (10 s)
  int crater_runs = 1;       ///< crater scenes run in turn (their timings pooled)
  int stream_steps = 15000;  ///< steps of each streamed slide (1,000 m at 4 m/s)
  /// Craters dug: one every `crater_interval_steps` from the first step on, at least one.
  int craters() const;
};

/// `quick`: one crater scene and slides of 256 m (the main command's run); otherwise three crater
/// scenes and slides of 1,000 m. `steps`, when given (`dyop compare --steps`), replaces the crater
/// scene's steps and the streamed slides'.
TerrainTiming terrain_timing(bool quick, std::optional<int> steps = std::nullopt);

/// The crater scene's bodies whose speeds are followed after an edit: resting (speed at most
/// `resting_speed` over the last `resting_steps` steps), not pushed, and struck by no other body
/// until the next edit.
inline constexpr double resting_speed = 0.01;  ///< m/s: the jitter of a body at rest is below it
/// Steps (0.5 s): a body at the top of a bounce or rocking in a crater is still for a step or two.
inline constexpr int resting_steps = 30;

/// Bodies resting this far or farther from an edit's rim (between the rim and the body's side)
/// count as far from it. Why 3 m: beyond the 2 m cell an edit triangulates again around its rim,
/// so a far body may rest on triangles made again but never loses support.
inline constexpr double far_from_edit = 3;

/// One crater dug under the crowd.
struct TerrainEdit {
  int run = 0;          ///< the crater scene it was dug in (0-based)
  int step = 0;         ///< dug before this step (0-based, after the crowd settled)
  b2Vec2 centre{0, 0};  ///< on the top under or beside its body (m)
  float radius = 0;     ///< m
  /// "under" a resting body's centre, "beside" it (its rim 0.5 m from the body's side) or "ahead"
  /// of a pushed body (3 m ahead of where it would be at a steady push)
  const char* placement = "";
  int destroyed = 0;       ///< triangle fixtures destroyed
  int created = 0;         ///< triangle fixtures created
  int kept = 0;            ///< triangles of the cells triangulated again kept as they were
  double edit_ms = 0;      ///< the `remove` call, wall time
  double edit_cpu_ms = 0;  ///< the same, this thread's CPU time (a preempted call shows less)
  double step_ms = 0;      ///< the `Step` right after it, wall time
  double step_cpu_ms = 0;  ///< the same, CPU time
  int far_bodies = 0;      ///< resting bodies `far_from_edit` or farther, followed
  double far_vertical_speed = 0;   ///< their largest |v_y| until the next edit (m/s)
  int near_bodies = 0;             ///< resting bodies beside the crater, nearer than that
  double near_vertical_speed = 0;  ///< their largest |v_y| until the next edit (m/s)
};

/// The crater scene: the 300 m level with caves (examples/level_outline.hpp) as an
/// `OutlineTerrain` with its defaults (triangles' friction 0.6), a crowd of the everyday bodies
/// (friction 0.6) resting along its top 1.5 m apart (balls only where the top is within 3° of
/// level: a ball rolls on any slope) and eight of them pushed along it at 2 m/s (through the
/// others: they meet only the ground), settled for 1 s, then craters of radius 1, 1.5 and 2 m in
/// turn dug every `crater_interval_steps` under or beside a resting body (seeded), or 3 m ahead
/// of a pushed one (every fourth). Sleeping off, as in every world of the report.
struct TerrainCraters {
  int bodies = 0;     ///< the crowd, pushed ones included
  int pushed = 0;     ///< bodies pushed along the top
  int chunks = 0;     ///< the level's chunks
  int triangles = 0;  ///< the level's triangles before the first crater
  int steps = 0;      ///< steps per scene after the crowd settled
  int runs = 0;
  std::vector<TerrainEdit> edits;  ///< every scene's, in order
  /// Every scene's steps with no edit before them: wall and CPU time (ms).
  std::vector<double> plain_step_ms, plain_step_cpu_ms;
  /// Body positions checked (every crowd body after every step) and how many had their centre
  /// inside the ground (`OutlineTerrain::solid`): a body fallen through, or pushed in.
  std::int64_t checks = 0;
  std::int64_t inside = 0;
  int below = 0;               ///< bodies that ended below the level's bottom (y = -20 m)
  double deepest_overlap = 0;  ///< the largest overlap of a crowd body with the ground (m)
  int fell_in = 0;  ///< bodies that ended 0.2 m or more below where they rested (in a crater)
};

/// Runs the crater scene `timing.crater_runs` times with the plug-in (`Backend::Dyop`, `config`)
/// installed, seeded by `seed` (the craters' places). Throws `std::runtime_error` without
/// `terrain_available()` or when the terrain refuses the level or a crater.
TerrainCraters run_terrain_craters(const TerrainTiming& timing, const box2d::Config& config,
                                   std::uint64_t seed);

/// The name the crater scene's recording goes by: "terrain-craters".
inline constexpr const char* terrain_recording_name = "terrain-craters";

/// The crater scene (settled first, not recorded) recorded for `steps` (≥ 1) steps with its
/// craters for a viewer page (`record_edited`): side A under `runners[0]` with `configs[0]`, B
/// under `runners[1]` with `configs[1]`; the terrain's triangles come and go with the craters.
/// Throws as `run_terrain_craters` and `record_edited`.
LockstepRecording record_terrain_craters(const std::array<scenes::Runner, 2>& runners, int steps,
                                         const std::array<box2d::Config, 2>& configs,
                                         std::uint64_t seed);

/// One body's slide across a streamed level.
struct TerrainGlide {
  std::string level;  ///< "flat" or "undulating"
  std::string body;   ///< e.g. "`SetAsBox` box"
  /// Largest speed across the ground under it (|v·n|, n the normal of the top's segment under
  /// its centre: its vertical speed on a flat top), after the first step (m/s; a glide: 0).
  double max_off_ground_speed = 0;
  double travel = 0;  ///< distance along x over push speed × time (a frictionless glide: ≈ 1)
};

/// What a level's ground holds in memory, one way of making it.
struct TerrainMemory {
  std::string ground;  ///< e.g. "b2ChainShape loop"
  double bodies = 0;   ///< its bodies (a mean over a streamed run)
  double fixtures = 0;
  double proxies = 0;        ///< broad-phase proxies (a chain: one per edge)
  double box2d_bytes = 0;    ///< bodies, fixtures, shapes, chain vertices, proxies
  double own_bytes = 0;      ///< the terrain's own (every chunk's, loaded or not); 0 for the others
  double loaded_chunks = 0;  ///< chunks with a body (0: not a terrain)
};

/// The streamed slides: two kilometres of ground (1,024 m, 20 m deep, a vertex of the top every
/// 8 m) as `OutlineTerrain`s with their defaults: a flat one, its top the side y = 0 between two
/// rows of chunks; a gently undulating one, its top's slope turning by 1/512 at each vertex, ±0.5 m
/// around that side. On each, each everyday body alone (frictionless) launched at 4 m/s along the
/// top and pushed along it against gravity's pull down its slopes, so that a free glide keeps its
/// speed, only the chunks near a camera following it loaded: a 24 × 16 m view around it with a
/// 10 m margin, `load` after every step. The counts and the memory are the undulating level's.
struct TerrainStream {
  double length = 0;    ///< the level's length along x (m)
  double boundary = 0;  ///< its outline's length (m)
  int chunks = 0;       ///< the level's chunks
  int triangles = 0;    ///< the level's triangles
  int steps = 0;
  double distance = 0;  ///< push speed × time (m)
  /// The flat level's, then the undulating one's, each in `EverydayShapes::all()` order.
  std::vector<TerrainGlide> glides;
  /// Over every body's steps, after each `load`: the world's bodies, fixtures and proxies (the
  /// body's own included) and the loaded chunks, largest and mean.
  int loaded_max = 0, bodies_max = 0, fixtures_max = 0, proxies_max = 0;
  double loaded_mean = 0, bodies_mean = 0, fixtures_mean = 0, proxies_mean = 0;
  std::int64_t load_calls = 0;                 ///< `load` calls timed
  double load_ms_median = 0, load_ms_max = 0;  ///< their wall time
  /// The undulating outline as Box2D's chain loop and through `add_outline`, whole in a world;
  /// the terrain with every chunk loaded; streamed, mean and largest over the runs.
  std::vector<TerrainMemory> memory;
};

/// Runs the streamed slides for `timing.stream_steps` steps each with the plug-in (`Backend::Dyop`,
/// `config`) installed. Throws as `run_terrain_craters`.
TerrainStream run_terrain_stream(const TerrainTiming& timing, const box2d::Config& config);

}  // namespace dyop::experiments
