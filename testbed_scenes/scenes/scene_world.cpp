#include "scenes/scene_world.hpp"

#include <stdexcept>
#include <string>

#include "scenes/builders.hpp"
#include "workloads/random.hpp"

namespace dyop::scenes {

SceneWorld::SceneWorld(std::string_view name, std::uint64_t seed)
    : world_(std::make_unique<World>()) {
  const WorldBuilder* build = detail::find_builder(name);
  if (build == nullptr) {
    throw std::invalid_argument("no Box2D scene called '" + std::string(name) + "'");
  }
  workloads::Random rng(seed);
  (*build)(*world_, rng);
}

}  // namespace dyop::scenes
