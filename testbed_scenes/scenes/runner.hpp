#pragma once
/// \file
/// What answers a scene's pairs (a runner: a backend of the plug-in, or Box2D's own contact with
/// the plug-in not installed), its one spelling, and how the testbed runs a backend on single
/// pairs.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "adapters/narrow_phase.hpp"
#include "dyop/box2d.hpp"

namespace dyop::scenes {

/// The name of Box2D's own contact with the plug-in not installed, the reference of every
/// in-world ratio: in tables, CSV and JSON wherever a runner is named.
inline constexpr const char* box2d_own = "box2d-own";

/// What answers a Box2D scene's polygon pairs: a backend of the plug-in, or nothing: Box2D's own
/// contact, the plug-in not installed (`box2d_own`).
using Runner = std::optional<box2d::Backend>;

/// `box2d::name(*runner)`, or `box2d_own`.
inline const char* name(const Runner& runner) { return runner ? box2d::name(*runner) : box2d_own; }

/// Every backend's name in `box2d::all_backends`' order, then `box2d_own` when `with_box2d_own`:
/// what a command line accepts.
inline std::vector<std::string> runner_names(bool with_box2d_own) {
  std::vector<std::string> out;
  for (box2d::Backend b : box2d::all_backends) out.push_back(box2d::name(b));
  if (with_box2d_own) out.push_back(box2d_own);
  return out;
}

/// The runner spelt `s` (a backend's name or `box2d_own`), or nothing.
inline std::optional<Runner> parse_runner(std::string_view s) {
  if (s == box2d_own) return Runner{};
  const std::optional<box2d::Backend> b = box2d::parse_backend(s);
  return b ? std::optional<Runner>(b) : std::nullopt;
}

/// A backend as the testbed runs it on single pairs (depth checks, the paper scene): its method,
/// warm-started where it keeps state as the plug-in runs it (one state per contact), or Box2D's
/// `b2CollidePolygons` for `Backend::Box2D`.
inline adapters::NarrowPhase narrow_phase_of(box2d::Backend backend) {
  const std::optional<Method> m = box2d::method_of(backend);
  return m ? adapters::NarrowPhase{adapters::Variant{*m, box2d::warm_start(backend)}}
           : adapters::NarrowPhase::box2d();
}

}  // namespace dyop::scenes
