#pragma once
/// \file
/// Levels built the ways a user builds them, for `dyop compare`'s grounds section: as Box2D's own
/// remedy for ghost collisions, one-sided `b2ChainShape` loops, and as two-sided `b2EdgeShape`
/// segments laid end to end along the same loops (the ground of most of Box2D's own testbed),
/// each under Box2D's own contact (the plug-in not installed) and under the plug-in
/// (`Backend::Dyop`); and through the plug-in's builders (`dyop::box2d::TileGround`,
/// `dyop::box2d::add_outline`) under the plug-in. The same bodies on each.
///
/// Units: metres, seconds, milliseconds for times; a level's figures per metre are per metre of
/// its boundary (every loop's length).

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <box2d/b2_math.h>

#include "dyop/box2d.hpp"
#include "experiments/lockstep_recording.hpp"

namespace dyop::experiments {

/// The levels: a 60 m flat outline with a vertex every 0.25 m (what a tile editor exports); a
/// 256 × 64 tile grid of 0.5 m cells with hills, caves and a dug pit; a 300 m outline with hills,
/// ten caves and an overhang. Each has a flat stretch on top (x from 0 to `flat_length`, y = 0)
/// where bodies glide and are placed.
enum class GroundLevel : std::uint8_t { Flat, TileGrid, Outline };
inline constexpr std::array<GroundLevel, 3> ground_levels = {
    GroundLevel::Flat, GroundLevel::TileGrid, GroundLevel::Outline};
const char* name(GroundLevel level);

/// How a level is built: chain loops, two-sided edges along the same loops, or the plug-in's
/// builders.
enum class GroundBuild : std::uint8_t { Chain, Edges, Builder };
const char* name(GroundBuild build);

/// A build and what answers its contacts: Box2D's own contact (`plugin` false) or the plug-in.
struct GroundWay {
  GroundBuild build = GroundBuild::Chain;
  bool plugin = false;
};

/// The ways every level is run, in this order: the chain and the edges under Box2D's own contact
/// and under the plug-in, then the builders under the plug-in. The first is the reference of
/// every ratio.
inline constexpr int ground_way_count = 5;
inline constexpr std::array<GroundWay, ground_way_count> ground_ways = {
    {{GroundBuild::Chain, false},
     {GroundBuild::Chain, true},
     {GroundBuild::Edges, false},
     {GroundBuild::Edges, true},
     {GroundBuild::Builder, true}}};

/// "chain, Box2D's own", "chain, plug-in", ..., "builders, plug-in".
std::string name(GroundWay way);

/// True when this build can make `level` with the builders: outlines need `dyop::box2d_outlines`
/// (GEOS); the tile grid always can.
bool builders_available(GroundLevel level);

/// A tile grid's solid cells (`cells[row · columns + column]` nonzero) as the loops of a
/// `b2ChainShape` each (`CreateLoop`), the solid on each loop's left (counter-clockwise around
/// solid, clockwise around holes: Box2D's one-sided chains collide on the right), straight runs
/// merged, cells meeting at a corner only kept apart. Cell (column, row) spans
/// [origin.x + column·cell, + cell] × [origin.y + row·cell, + cell]; outside the grid is empty.
std::vector<std::vector<b2Vec2>> tile_loops(const std::vector<std::uint8_t>& cells, int columns,
                                            int rows, float cell, const b2Vec2& origin);

/// A body pushed along the flat stretch: its largest vertical speed and how far it went.
struct GroundGlide {
  std::string body;               ///< e.g. "`SetAsBox` box"
  double max_vertical_speed = 0;  ///< m/s, after the first step (a glide: 0)
  double travel = 0;              ///< distance over push speed × time (a frictionless glide: 1)
};

/// Boxes started inside the ground or thrown at it: how many ended with their centre above the
/// top.
struct GroundPlacement {
  std::string trial;  ///< e.g. "started 0.4 m inside"
  int on_top = 0;     ///< boxes whose centre ended above the top
  int boxes = 0;      ///< boxes in the trial
};

/// One level built one way, and what the same bodies did on it.
struct GroundRun {
  GroundLevel level = GroundLevel::Flat;
  GroundWay way;
  double boundary = 0;  ///< metres of boundary (every loop), the same both ways
  int fixtures = 0;     ///< the ground's fixtures
  int proxies = 0;      ///< the ground's broad-phase proxies (a chain: one per edge)
  double bytes = 0;     ///< fixtures, shapes, chain vertices, proxies, tree nodes
  double build_ms = 0;  ///< making the ground's fixtures, median over every world built
  double refresh_ms =
      0;  ///< a cell dug (tile grid: its chunk, or every loop again) or the level again
  std::vector<GroundGlide> glides;
  std::vector<GroundPlacement> placements;
  double narrow_ms = 0;  ///< the crowd's `b2Profile::collide`, summed over its steps (median)
  double step_ms = 0;    ///< the crowd's `b2Profile::step`, summed over its steps (median)
};

/// How much the crowd runs: bodies, steps, and runs alternating between chain and builders.
struct GroundTiming {
  int bodies = 0;
  int steps = 0;
  int runs = 0;
};

/// The crowd on `level`: `quick` for the main command's figures (a couple of seconds per level);
/// `steps`, when given, replaces the step count (`dyop compare --steps`).
GroundTiming ground_timing(GroundLevel level, bool quick, std::optional<int> steps = std::nullopt);

/// `level` built every way (`ground_ways`, in that order): per way, one world for the glides
/// (every body alone on the ground), one for the placements (then a refresh), one per crowd run;
/// the crowd's runs alternate between the ways. The plug-in is installed with `config` for the
/// ways under it and uninstalled for the others, and uninstalled at the end. Throws
/// `std::runtime_error` when the builders refuse the level or this build has none for it
/// (`builders_available`).
std::array<GroundRun, ground_way_count> compare_ground(GroundLevel level,
                                                       const GroundTiming& timing,
                                                       const box2d::Config& config);

/// Steps of a level's recording by default (`record_ground`): the glides' 4 s.
inline constexpr int ground_recording_steps = 240;

/// The name a level's recording goes by: "grounds-" and the level's name ("grounds-flat").
std::string ground_recording_name(GroundLevel level);

/// The level whose recording is called `name` (`ground_recording_name`); none for another name.
std::optional<GroundLevel> ground_level_of_recording(const std::string& name);

/// `level` built as chains and by the builders, with the glides' bodies pushed along its flat
/// stretch and the boxes started 0.4 m inside it, in one world each way, recorded for `steps`
/// (≥ 1) steps for a viewer page (`record_sides`): side A the chains under `runners[0]` with
/// `configs[0]` (the comparison's: Box2D's own contact), side B the builders under `runners[1]`
/// with `configs[1]` (the plug-in).
/// Named by `ground_recording_name`. Throws as `compare_ground` and `record_sides`.
LockstepRecording record_ground(GroundLevel level, const std::array<scenes::Runner, 2>& runners,
                                int steps, const std::array<box2d::Config, 2>& configs);

}  // namespace dyop::experiments
