#include "experiments/ground_measures.hpp"

#include <algorithm>

namespace dyop::experiments {
double signed_area(const std::vector<b2Vec2>& ring) {
  double a = 0;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const b2Vec2& p = ring[i];
    const b2Vec2& q = ring[(i + 1) % ring.size()];
    a += static_cast<double>(p.x) * q.y - static_cast<double>(q.x) * p.y;
  }
  return a / 2;
}

double chain_bytes(const b2ChainShape& chain) {
  return static_cast<double>(sizeof(b2Fixture) + sizeof(b2ChainShape) +
                             static_cast<std::size_t>(chain.m_count) * sizeof(b2Vec2) +
                             static_cast<std::size_t>(chain.GetChildCount()) * proxy_bytes);
}

std::vector<std::vector<b2Vec2>> chain_loops_of(std::vector<std::vector<b2Vec2>> rings) {
  for (std::size_t i = 0; i < rings.size(); ++i) {
    if ((signed_area(rings[i]) > 0) != (i == 0)) std::reverse(rings[i].begin(), rings[i].end());
  }
  return rings;
}

double boundary_length(const std::vector<std::vector<b2Vec2>>& loops) {
  double length = 0;
  for (const std::vector<b2Vec2>& ring : loops) {
    for (std::size_t i = 0; i < ring.size(); ++i) {
      length += b2Distance(ring[i], ring[(i + 1) % ring.size()]);
    }
  }
  return length;
}

}  // namespace dyop::experiments
