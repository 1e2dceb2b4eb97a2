#pragma once
/// \file
/// A runner registered for as long as an object lives: its backend installed in the plug-in with
/// its skips, or the plug-in uninstalled (Box2D's own contact). Box2D's contact registry is
/// process-wide, so one such object may live at a time; whoever holds it builds and steps worlds.

#include "dyop/box2d.hpp"
#include "scenes/runner.hpp"

namespace dyop::scenes {

class Installation {
 public:
  /// Installs `runner`'s backend with `skips` (throws `std::runtime_error` if refused), or
  /// uninstalls the plug-in for Box2D's own contact; resets the plug-in's counters.
  Installation(const Runner& runner, const box2d::Config& skips);
  /// Uninstalls, also when what was built with it threw, so that the next world starts with
  /// Box2D's own contact registered.
  ~Installation();
  Installation(const Installation&) = delete;
  Installation& operator=(const Installation&) = delete;
};

}  // namespace dyop::scenes
