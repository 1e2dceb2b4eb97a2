#pragma once
// Internal: what is installed right now, read by every evaluation of the plug-in's contacts.

#include <optional>

#include "contact_registry.hpp"
#include "dyop/box2d.hpp"

namespace dyop::box2d::detail {

struct Installation {
  // The backend the plug-in's contacts answer with; nothing: uninstalled, they answer as Box2D's
  // own contact does (`b2CollidePolygons`).
  std::optional<Backend> backend;
  Config config;  // the skips of `backend`
  // `config.internal_edges` and a backend that honours it (`MethodInfo::allowed_directions`):
  // only then do contacts look for their internal edges.
  bool find_internal_edges = false;
  // What was registered for polygon pairs before the first install: Box2D's own
  // b2PolygonContact (its functions are not exported, so they can only be saved from the
  // registry). Valid once `saved` is true.
  PolygonContactFcns box2d_own;
  bool saved = false;
};

// The process-wide installation (single-threaded, like Box2D 2.4); inline, as every contact
// update reads it.
inline Installation current_installation;
inline Installation& installation() { return current_installation; }

}  // namespace dyop::box2d::detail
