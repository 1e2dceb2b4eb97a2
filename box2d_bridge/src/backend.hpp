#pragma once
// Internal: the correspondence between the plug-in's backends and the library's methods.

#include <optional>

#include "dyop/box2d.hpp"

namespace dyop::box2d::detail {

// The library method behind `b`; nothing for `Backend::Box2D`, which is Box2D's own code. Inline:
// every contact update asks.
inline std::optional<Method> method_of(Backend b) {
  switch (b) {
    case Backend::Dyop: return Method::Dyop;
    case Backend::DyopFast: return Method::DyopFast;
    case Backend::LinCanny: return Method::LinCanny;
    case Backend::Sat: return Method::Sat;
    case Backend::Epa: return Method::Epa;
    case Backend::Box2D: break;
  }
  return std::nullopt;
}

// The backend that runs `m`; nothing for `Method::DyopPaper`, which is not offered to Box2D.
std::optional<Backend> backend_of(Method m);

}  // namespace dyop::box2d::detail
