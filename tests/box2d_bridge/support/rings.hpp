#pragma once
// Polygons as rings of points, as the outline builder and the terrain take them (metres).

#include <box2d/b2_math.h>

#include <vector>

namespace dyop::box2d::testing {

using Ring = std::vector<b2Vec2>;

// The rectangle [x0, x1] × [y0, y1], counter-clockwise.
inline Ring rectangle(float x0, float y0, float x1, float y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

// The rings' total length (metres).
inline double perimeter(const std::vector<Ring>& rings) {
  double sum = 0;
  for (const Ring& ring : rings) {
    for (std::size_t i = 0; i < ring.size(); ++i)
      sum += (ring[(i + 1) % ring.size()] - ring[i]).Length();
  }
  return sum;
}

}  // namespace dyop::box2d::testing
