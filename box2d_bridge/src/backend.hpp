#pragma once
// Internal: the correspondence between the plug-in's backends and the library's methods.

#include <optional>

#include "dyop/box2d.hpp"

namespace dyop::box2d::detail {

// The library method behind `b`; nothing for `Backend::Box2D`, which is Box2D's own code.
std::optional<Method> method_of(Backend b);

// The backend that runs `m`; nothing for `Method::DyopPaper`, which is not offered to Box2D.
std::optional<Backend> backend_of(Method m);

}  // namespace dyop::box2d::detail
