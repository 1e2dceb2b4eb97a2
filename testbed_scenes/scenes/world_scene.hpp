#pragma once
/// \file
/// The Box2D scenes' common machinery: install the backend with its skips, build the world, step
/// it, measure.
///
/// Per step, untimed: `ContactProbe::before_step` (counts and depth errors of the contacts the
/// step will update); timed: `World::step` (steady_clock around `b2World::Step`) and, inside it,
/// Box2D's own `GetProfile().collide`; untimed again: the exact penetration of touching triangle
/// pairs, non-finite states, the top bodies' displacement from where they were after
/// `settle_steps`, the sliders' largest speeds. Step 1 is left out of the narrow-phase
/// figures: its contacts are created inside `Step`, so the probe cannot see them beforehand.

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "scenes/contact_probe.hpp"
#include "scenes/installation.hpp"
#include "scenes/manifold_check.hpp"
#include "scenes/scene.hpp"
#include "scenes/world.hpp"
#include "workloads/random.hpp"

namespace dyop::scenes {

/// A body launched along +x (scene `slide`), measured while it goes.
struct Slider {
  b2Body* body = nullptr;
  double speed = 0;  ///< launch speed along +x (m/s): its travel's yardstick
  /// What it is and where (`body`, `ground`, `rolling`); the scene fills in the figures.
  SliderFigures figures;
};

/// What a builder says about the world it built.
struct WorldBuild {
  /// Bodies that should not move much if the structure stands (top of a pyramid or a stack, the
  /// resting box of `slide`); empty when the scene is not meant to stand.
  std::vector<b2Body*> watched;
  /// Bodies launched along +x (`slide`): the scene reports `SceneMetrics::slide` when there are.
  std::vector<Slider> sliders;
  /// Called before each step with the number of steps done, untimed (scene `tiles`: a ground whose
  /// tiles are added and removed under the sliders); empty: nothing.
  std::function<void(int steps_done)> before_step;
  /// True: the ground's and the bodies' edge data are fixed once built, as a level loader that
  /// calls `fix_internal_edges` does; false: never, every contact finds its masks itself.
  bool fix_edge_data = true;
};

/// Steps a structure is given to settle before its top bodies are watched (1 s): a pyramid of
/// wedged triangles sinks into place by centimetres per row, which is not falling.
inline constexpr int settle_steps = 60;

/// Fills an empty world (gravity −10 m/s² along y) for a seed.
using WorldBuilder = std::function<WorldBuild(World& world, workloads::Random& rng)>;

/// A Box2D scene.
class WorldScene : public Scene {
 public:
  /// Installs `runner`'s backend with the skips `skips` in the plug-in (throws
  /// `std::runtime_error` if refused), or uninstalls the plug-in for Box2D's own contact, then
  /// builds.
  WorldScene(std::string name, const Runner& runner, std::uint64_t seed, const box2d::Config& skips,
             const WorldBuilder& build);
  ~WorldScene() override;

  void step() override;
  SceneMetrics metrics() const override;
  Drawing drawing() const override;
  void check_manifolds() override;
  void spawn_far_away() override;

  /// The world, for tests that look inside.
  const World& world() const { return *world_; }
  /// What the builder said (the watched bodies, the sliders and their figures so far).
  const WorldBuild& build() const { return build_; }

 private:
  std::string name_;
  Runner runner_;
  std::uint64_t seed_;
  box2d::Config skips_;
  Installation installation_;
  std::unique_ptr<World> world_;
  WorldBuild build_;
  std::vector<b2Vec2> watched_start_;
  std::vector<float> slider_start_x_;
  std::unique_ptr<ContactProbe> probe_;
  std::unique_ptr<ManifoldCheck> manifold_check_;  // set on the world by `check_manifolds`
  bool spawning_ = false;                          // `spawn_far_away`
  b2Body* spawned_ = nullptr;  // its body while it lives (not in `World::bodies`)

  int steps_ = 0;
  std::vector<double> step_ms_;
  double step_ms_measured_ = 0;  // steps 2..N, as `collide_ms_`
  double collide_ms_ = 0;
  double solve_toi_ms_ = 0;  // steps 2..N
  ContactProbe::Updates updates_;
  std::uint64_t toi_swept_ = 0;  // SceneMetrics::toi_swept
  ErrorTally errors_;
  PenetrationTally penetration_;
  double top_displacement_ = 0;
  bool nan_ = false;
};

}  // namespace dyop::scenes
