#pragma once
/// \file
/// A catalogue scene's Box2D world alone: built from its seed and stepped, with nothing installed,
/// uninstalled or measured. For many worlds at once (on threads, in a pool of workers, one reset
/// after another): the caller installs the plug-in's backend, or leaves Box2D's own contact, once
/// before any of them is built, and the worlds answer with whatever is installed. `WorldScene`
/// builds and steps the same world (same builder, same seed), so equal runners give equal hashes.

#include <cstdint>
#include <memory>
#include <string_view>

#include "scenes/world.hpp"

namespace dyop::scenes {

class SceneWorld {
 public:
  /// Builds scene `name` (a Box2D scene of the catalogue) for `seed`. Throws
  /// `std::invalid_argument` for an unknown name and for `paper` (no Box2D world).
  SceneWorld(std::string_view name, std::uint64_t seed);

  /// One step of `time_step`.
  void step() { world_->step(); }
  /// `state_hash` of the world now.
  std::uint64_t hash() const { return state_hash(*world_); }
  /// The world, for tests that look inside.
  World& world() { return *world_; }

 private:
  std::unique_ptr<World> world_;
};

}  // namespace dyop::scenes
