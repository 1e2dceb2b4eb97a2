#pragma once
// The examples' level: 300 m of ground whose top runs flat for 40 m and then over hills, with ten
// caves under it and an overhang at its end, as the rings a Box2D user would feed `b2ChainShape`.

#include <box2d/b2_math.h>
#include <box2d/b2_settings.h>

#include <cmath>
#include <vector>

// The rings: the outline counter-clockwise (the top from x = 300 back to 0, a vertex every
// 0.25 m, then the bottom at y = -20, with a notch cut into the right side under an overhang),
// then the caves, ellipses of 24 vertices.
inline std::vector<std::vector<b2Vec2>> level_outline() {
  std::vector<b2Vec2> outline;
  for (int i = 1200; i >= 0; --i) {
    const float x = 0.25f * static_cast<float>(i);
    const float hills = x < 40 ? 0 : 3 * std::sin((x - 40) / 12) * std::sin((x - 40) / 31);
    outline.push_back({x, hills});
  }
  outline.insert(outline.end(),
                 {{0, -20}, {300, -20}, {300, -12}, {292, -12}, {292, -6}, {300, -6}});
  std::vector<std::vector<b2Vec2>> rings = {outline};
  for (int k = 0; k < 10; ++k) {
    std::vector<b2Vec2> cave;
    for (int i = 0; i < 24; ++i) {
      const float a = static_cast<float>(i) * 2 * b2_pi / 24;
      cave.push_back({20 + 27 * static_cast<float>(k) + 6 * std::cos(a), -10 + 3 * std::sin(a)});
    }
    rings.push_back(cave);
  }
  return rings;
}
