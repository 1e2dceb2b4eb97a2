#pragma once
// Test support: what the sliding scenes' tests (`slide`, `tiles`) call a glide and a trip, and one
// slider's figures.

#include <stdexcept>
#include <string>

#include "scenes/metrics.hpp"

namespace dyop::scenes::testing {

// The bounds for a glide: largest vertical speed (m/s) and smallest travel fraction.
inline constexpr double kGlideVerticalSpeed = 0.05;
inline constexpr double kGlideTravel = 0.98;
// A ghost collision: a trip that throws the box up faster than this (m/s).
inline constexpr double kTripVerticalSpeed = 0.5;
// Relative spread of the wheel's travel between grounds and launch points (`slide`, seeds 0-11:
// 0.87 to 1.06 of its one-piece travel with the rule on; `tiles`, seeds 0-5: 0.87 to 1.07).
inline constexpr double kWheelTravelSpread = 0.2;

// The figures of `body` on `ground` in `m` (throws when the scene has no such slider).
inline const SliderFigures& slider(const SceneMetrics& m, const std::string& body,
                                   const std::string& ground) {
  for (const SliderFigures& s : m.slide->sliders) {
    if (s.body == body && s.ground == ground) return s;
  }
  throw std::invalid_argument("no " + body + " on " + ground);
}

}  // namespace dyop::scenes::testing
