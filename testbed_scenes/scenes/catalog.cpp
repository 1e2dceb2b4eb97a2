#include <stdexcept>
#include <string>

#include "scenes/builders.hpp"
#include "scenes/paper.hpp"

namespace dyop::scenes {
namespace {

struct Entry {
  SceneInfo info;
  WorldBuilder build;  // nullptr: the paper scene, no Box2D world
};

const std::vector<Entry>& entries() {
  // Full runs: 10 to 15 s of simulated time (slide: 6 s, the length of its grounds at 6 m/s);
  // quick runs: 5 s, enough for everything dropped to land and for a structure that falls to
  // show it; `dyop compare --quick` (third count) runs the heaviest scenes shorter: their piles
  // formed, everything landed, not settled.
  static const std::vector<Entry> list = {
      {{"paper", "the paper's experiment: 10 triangle types on fixed paths, 90 steps, n-body", 90,
        90, 90},
       nullptr},
      {{"pyramid", "55 boxes of 2 triangle fixtures on a triangle ground (150 triangles)", 600, 300,
        300},
       detail::build_pyramid},
      {{"pyramid-rows", "100 triangle bodies in rows of alternating up and down triangles", 600,
        300, 300},
       detail::build_pyramid_rows},
      {{"stack", "3 stacks of 10 boxes of 2 triangle fixtures on a triangle ground", 600, 300, 300},
       detail::build_stack},
      {{"stack-concave", "24 L, U and star bodies (4 to 10 triangle fixtures) dropped in a bin",
        900, 300, 300},
       detail::build_stack_concave},
      {{"rain", "500 triangles of mixed sizes falling into a bin of triangle fixtures", 900, 300,
        150},
       detail::build_rain},
      {{"rain-tall",
        "1,500 triangles falling from up to 40 m into a bin of triangle fixtures: fast impacts, "
        "time of impact at work",
        250, 150, 120},
       detail::build_rain_tall},
      {{"tumbler", "300 triangles in a kinematic drum of triangle fixtures turning at 0.3 rad/s",
        900, 300, 150},
       detail::build_tumbler},
      {{"slivers", "thin (1/20 to 1/140), tiny (1-5 cm) and large (2-3 m) triangles in a bin", 600,
        300, 300},
       detail::build_slivers},
      {{"slivers-far", "the slivers scene moved 10 km from the origin", 600, 300, 300},
       detail::build_slivers_far},
      {{"mixed",
        "triangles, boxes and circles on an edge ground: every pair family but circle-circle", 600,
        300, 300},
       detail::build_mixed},
      {{"crowd",
        "600 SetAsBox boxes, hexagons, circles and triangles poured into a bin of triangle "
        "fixtures: every pair family on a triangulated ground",
        600, 300, 150},
       detail::build_crowd},
      {{"slide",
        "boxes, L bodies and wheels launched along grounds of triangulated cells, a box resting "
        "across a junction",
        360, 300, 300},
       detail::build_slide},
      {{"tiles",
        "boxes, L bodies and wheels launched along grounds of 0.5 m tiles: one body, a body per "
        "tile, 8x8 chunks, T-junctions, tiles added and removed under the sliders",
        360, 300, 300},
       detail::build_tiles},
      {{"tile-map",
        "a crowd on a tile map: 48 boxes and L bodies sliding at 3 m/s along 4 lanes of 0.5 m "
        "tiles as bodies, 60 triangles of debris falling onto a fifth",
        360, 300, 300},
       detail::build_tile_map},
      {{"tile-map-unfixed",
        "the tile map of tile-map as most loaders bring it over: edge data never fixed "
        "(fix_internal_edges not called), every contact finds its masks",
        360, 300, 300},
       detail::build_tile_map_unfixed},
  };
  return list;
}

const Entry* find_entry(std::string_view name) {
  for (const Entry& e : entries()) {
    if (name == e.info.name) return &e;
  }
  return nullptr;
}

}  // namespace

const WorldBuilder* detail::find_builder(std::string_view name) {
  const Entry* e = find_entry(name);
  return e != nullptr && e->build != nullptr ? &e->build : nullptr;
}

const std::vector<SceneInfo>& scene_catalog() {
  static const std::vector<SceneInfo> infos = [] {
    std::vector<SceneInfo> out;
    for (const Entry& e : entries()) out.push_back(e.info);
    return out;
  }();
  return infos;
}

const SceneInfo* find_scene(std::string_view name) {
  const Entry* e = find_entry(name);
  return e ? &e->info : nullptr;
}

std::unique_ptr<Scene> make_scene(std::string_view name, const Runner& runner, std::uint64_t seed,
                                  const box2d::Config& skips) {
  const Entry* e = find_entry(name);
  if (e == nullptr) throw std::invalid_argument("unknown scene '" + std::string(name) + "'");
  if (e->build == nullptr) {
    if (!runner) {
      throw std::invalid_argument("scene 'paper' has no Box2D world to run Box2D's own contact in");
    }
    return paper::make_scene(*runner, seed);
  }
  return std::make_unique<WorldScene>(e->info.name, runner, seed, skips, e->build);
}

std::unique_ptr<Scene> make_rain(int falling, const Runner& runner, std::uint64_t seed,
                                 const box2d::Config& skips) {
  if (falling < 1) throw std::invalid_argument("rain needs at least one falling triangle");
  return std::make_unique<WorldScene>("rain", runner, seed, skips,
                                      [falling](World& world, workloads::Random& rng) {
                                        return detail::build_rain_of(world, rng, falling);
                                      });
}

SceneMetrics run_scene(std::string_view name, const Runner& runner, int steps, std::uint64_t seed,
                       const box2d::Config& skips, Drawing* final_state) {
  const std::unique_ptr<Scene> scene = make_scene(name, runner, seed, skips);
  for (int i = 0; i < steps; ++i) scene->step();
  if (final_state != nullptr) *final_state = scene->drawing();
  return scene->metrics();
}

}  // namespace dyop::scenes
