#pragma once
/// \file
/// `paper`: the experiment of the DyOP-PD paper (its Figure 7), rebuilt. The paper moves 10
/// pre-defined irregular triangle types of several sizes on pre-defined paths for 90 simulation
/// steps, tests them against each other (n-body), and plots per triangle type the time DyOP-PD
/// and Lin–Canny take to find the penetration depths. It publishes neither the triangles nor the
/// paths; ours are below (and printed in every report from these same tables).
///
/// Triangles: `triangle_types()`, vertices about each one's centroid, longest edges from 0.5 to
/// 3 units: acute, right-angled, obtuse and thin ones. Paths: `paths()`; type k at time t sits at
/// (cx + ax·sin(wx·t + phase), cy + ay·sin(wy·t)) turned by angle0 + spin·t (radians, seconds),
/// the centres (cx, cy) on a circle of radius 1.6 and amplitudes of about 2 units, so that all
/// ten sweep one 8 × 8 arena and cross often. Steps are 1/30 s; the seed picks which 90-step
/// window of these endless paths is run (`start_time`), seed 0 being t = 0 … 3 s.
///
/// Each step, the pairs whose (tight) bounding boxes overlap are what a narrow phase would get
/// from a broad phase; every method gets each of those pairs, in float, at `Level::Depth` with
/// `Apart::Gap` (the paper asks for depths: a pair apart needs only the proof that it is; the
/// methods that find the distance on their way, Lin–Canny and EPA, still do). The
/// paper's "n-body" literally tests all 45 pairs; that figure is also reported.
/// Errors are against the exact rational reference (`exact_reference/exact_reference.hpp`) on the
/// same float vertices.

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "dyop/box2d.hpp"
#include "scenes/metrics.hpp"
#include "scenes/scene.hpp"

namespace dyop::scenes::paper {

inline constexpr int type_count = 10;
inline constexpr int pair_count = type_count * (type_count - 1) / 2;
inline constexpr int experiment_steps = 90;       ///< the paper's 90 simulation steps
inline constexpr double step_seconds = 1.0 / 30;  ///< time between steps

/// A triangle type: vertices about its centroid (units of length).
using TriangleType = std::array<Vec2<double>, 3>;

/// A path, see the file comment.
struct Path {
  double cx, cy;  ///< centre of the motion
  double ax, ay;  ///< amplitudes
  double wx, wy;  ///< angular frequencies (rad/s)
  double phase;   ///< phase of x (rad)
  double angle0;  ///< orientation at t = 0 (rad)
  double spin;    ///< rotation rate (rad/s)
};

const std::array<TriangleType, type_count>& triangle_types();
const std::array<Path, type_count>& paths();

/// Time of the first step for `seed`: (seed mod 1000) × 3 s, one 90-step window per seed.
double start_time(std::uint64_t seed);

/// Where type `k` is at time `t`, and how fast it moves.
struct Pose {
  Vec2<double> position = Vec2<double>::Zero();
  double angle = 0;
  Vec2<double> velocity = Vec2<double>::Zero();
  double spin = 0;
};
Pose pose(int k, double t);

/// The ten triangles at time `t` as every method gets them (world vertices rounded to float),
/// and the pairs (i < j) whose bounding boxes overlap.
struct Frame {
  std::vector<Triangle<float>> triangles;
  std::vector<std::pair<int, int>> pairs;
};
Frame frame_at(double t);

/// `paper` under one backend, step by step, for `dyop scene paper`: each step times the
/// backend once over that step's pairs (steady_clock around the calls; repeating a step's few
/// pairs would let the branch predictor learn them) and checks it against the exact reference.
std::unique_ptr<Scene> make_scene(box2d::Backend backend, std::uint64_t seed);

}  // namespace dyop::scenes::paper
