#include "experiments/slide_run.hpp"

#include "scenes/builders.hpp"
#include "scenes/world_scene.hpp"

namespace dyop::experiments {

std::vector<scenes::Runner> slide_runners(bool quick) {
  std::vector<scenes::Runner> runners = {std::nullopt};
  if (quick) {
    runners.insert(runners.end(), {box2d::Backend::Dyop, box2d::Backend::Sat});
  } else {
    runners.insert(runners.end(), std::begin(box2d::all_backends), std::end(box2d::all_backends));
  }
  return runners;
}

SlideRun run_slide(const scenes::Runner& runner, int steps, std::uint64_t seed,
                   const box2d::Config& config, const std::string& scene_name) {
  scenes::WorldScene scene(scene_name, runner, seed, config,
                           *scenes::detail::find_builder(scene_name));
  const std::vector<scenes::Slider>& sliders = scene.build().sliders;
  SlideRun run;
  std::vector<b2Vec2> start;
  for (const scenes::Slider& s : sliders) {
    run.paths.push_back({s.figures.body, s.figures.ground, {}, {}});
    start.push_back(s.body->GetWorldCenter());
  }
  for (int i = 0; i < steps; ++i) {
    scene.step();
    for (std::size_t k = 0; k < sliders.size(); ++k) {
      const b2Vec2 moved = sliders[k].body->GetWorldCenter() - start[k];
      run.paths[k].x.push_back(moved.x);
      run.paths[k].height.push_back(moved.y);
    }
  }
  run.metrics = scene.metrics();
  run.final_state = scene.drawing();
  return run;
}

}  // namespace dyop::experiments
