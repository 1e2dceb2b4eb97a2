#pragma once
/// \file
/// The sliding scenes (`slide`, `tiles`) side by side under Box2D's own contact and the plug-in's
/// backends, for `dyop compare`'s slide section: each runner's figures, its sliders' paths and
/// its final state.

#include <cstdint>
#include <string>
#include <vector>

#include "scenes/drawing.hpp"
#include "scenes/metrics.hpp"
#include "scenes/scene.hpp"

namespace dyop::experiments {

/// The runners of the slide section: Box2D's own contact (`box2d_own`) first, then the plug-in's
/// backends: every one in a full run, the two exact ones (`dyop`, `sat`) with `quick`.
std::vector<scenes::Runner> slide_runners(bool quick);

/// One slider's path, sampled after every step.
struct SliderPath {
  std::string body;            ///< as `SliderFigures::body`
  std::string ground;          ///< as `SliderFigures::ground`
  std::vector<double> x;       ///< distance along x from its launch point (m)
  std::vector<double> height;  ///< height of its centre of mass above where it started (m)
};

/// A sliding scene run under one runner.
struct SlideRun {
  scenes::SceneMetrics metrics;   ///< its figures (`metrics.slide` holds the sliders')
  std::vector<SliderPath> paths;  ///< one per slider, in `metrics.slide->sliders` order
  scenes::Drawing final_state;    ///< the world after the last step
};

/// Runs `scene` (a scene with sliders: `slide` or `tiles`) for `steps` steps under `runner` with
/// `config`, recording the paths.
SlideRun run_slide(const scenes::Runner& runner, int steps, std::uint64_t seed,
                   const box2d::Config& config, const std::string& scene = "slide");

}  // namespace dyop::experiments
