#pragma once
// Internal: what answers the plug-in's pairs, decided once by `install` and read by every
// evaluation of the plug-in's contacts.
//
// Process-wide, as Box2D's contact registry is: written only by `install` and `uninstall`, which
// must not run while another thread steps a world (see `dyop/box2d.hpp`), so that evaluations on
// any number of threads only read it.

#include <array>
#include <cstdint>
#include <optional>

#include "contact_registry.hpp"
#include "dyop/box2d.hpp"
#include "dyop/method.hpp"

namespace dyop::box2d::detail {

// What a pair is evaluated with. Made by `install` (or per call by `collide_polygons`).
struct Setting {
  // The backend; nothing: uninstalled, the plug-in's contacts answer as Box2D's own contact.
  std::optional<Backend> backend;
  Config config;  // the skips and the internal-edge switch
  // The library method behind `backend`; nothing for `Backend::Box2D`, which is Box2D's own code.
  std::optional<Method> method;
  // `method`'s per-pair entry (`MethodInfo::run`), looked up once; nullptr with no method.
  PairFunction<float> run = nullptr;
  // The internal-edge rule, decided here once: `config.internal_edges` and a method that honours
  // the masks (`MethodInfo::internal_edges()`). Off: no contact ever looks for its masks.
  bool internal_edges = false;
  // Which install this is, counted modulo 255 and never 0: a contact's masks found under another
  // install are found again (fixtures may have changed while the plug-in was not looking).
  std::uint8_t epoch = 0;
  // The measurement floor (`measurement::install_never_recompute`): a contact keeps its first
  // answer for good. Never part of a backend's setting.
  bool never_recompute = false;

  Setting() = default;
  Setting(Backend b, const Config& c, std::uint8_t install_epoch)
      : backend(b),
        config(c),
        method(method_of(b)),
        run(method ? info(*method).run<float>() : nullptr),
        internal_edges(c.internal_edges && method && info(*method).internal_edges()),
        epoch(install_epoch) {}

  // True when a world's contacts may keep their manifold (`Config::recycle_distance`, or the
  // floor): a method's manifolds only. `Backend::Box2D` answers afresh every time, as Box2D's
  // own contact: it stays the bit-identical reference.
  bool recycles() const {
    return method.has_value() && (config.recycle_distance > 0 || never_recompute);
  }
};

// True when the plug-in's contact takes `pair` under `config`: polygon pairs always; the others
// unless `Config::triangles_only`, and edges and chains unless `Config::edges_and_chains` is off.
inline bool takes_pair(const Config& config, ShapePair pair) {
  if (pair.b == b2Shape::e_polygon && pair.a == b2Shape::e_polygon) return true;
  if (config.triangles_only) return false;
  return pair.a == b2Shape::e_polygon || config.edges_and_chains;
}

struct Installation {
  Setting setting;
  // What was registered for each of `taken_pairs` before the first install: Box2D's own contacts
  // (b2PolygonContact, b2PolygonAndCircleContact, b2EdgeAndPolygonContact, ...: their functions
  // are not exported, so they can only be saved from the registry). Valid once `saved` is true.
  std::array<ContactFcns, taken_pair_count> box2d_own{};
  bool saved = false;
};

// The process-wide installation; inline, as every contact update reads it.
inline Installation current_installation;
inline Installation& installation() { return current_installation; }

}  // namespace dyop::box2d::detail
