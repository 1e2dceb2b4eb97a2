#pragma once
// Internal: the library method a backend runs on triangle pairs.

#include <optional>

#include "dyop/box2d.hpp"

namespace dyop::box2d::detail {

// The per-pair method behind `b`; nothing for `Backend::Box2D`, which is Box2D's own code (and
// for `Batch`, which answers no single pair). Inline: every contact update asks.
inline std::optional<Method> method_of(Backend b) {
  if (info(b).entry != Entry::PerPair) return std::nullopt;
  return b;
}

}  // namespace dyop::box2d::detail
