// The paper experiment's data: the ten triangle types, their paths and the frames they make.
#include <algorithm>
#include <cmath>

#include "scenes/paper.hpp"

namespace dyop::scenes::paper {
namespace {

using V = Vec2<double>;

// Raw vertices; triangle_types() moves each to its centroid. Longest edges 0.5 … 3 units.
constexpr double kRawTypes[type_count][6] = {
    {-0.25, -0.10, 0.25, -0.05, -0.05, 0.18},  //  1: small, acute
    {-0.35, -0.20, 0.40, -0.15, 0.10, 0.30},   //  2: acute
    {-0.50, 0.00, 0.50, -0.05, 0.15, 0.25},    //  3: obtuse, flat
    {-0.45, -0.40, 0.55, -0.40, -0.45, 0.35},  //  4: right-angled, axis-aligned legs
    {-0.75, -0.05, 0.75, 0.05, 0.10, 0.20},    //  5: thin
    {-0.80, -0.50, 0.90, -0.30, -0.10, 0.80},  //  6: acute
    {-1.00, -0.30, 1.00, -0.20, -0.50, 0.50},  //  7: obtuse
    {-1.10, -0.70, 1.20, -0.40, 0.20, 1.00},   //  8: acute
    {-1.35, 0.00, 1.35, 0.20, 0.60, 0.45},     //  9: thin, obtuse
    {-1.40, -1.00, 1.60, -0.80, -0.30, 1.40},  // 10: large, acute
};

// Columns as `Path`: cx, cy, ax, ay, wx, wy, phase, angle0, spin. Centres on a circle of radius
// 1.6 (k·36°), amplitudes ~2, frequencies spread so that no two types move in step.
constexpr Path kPaths[type_count] = {
    {1.60, 0.00, 2.00, 1.80, 0.90, 1.30, 0.00, 0.00, 0.50},
    {1.29, 0.94, 2.10, 1.90, 1.03, 1.23, 0.60, 0.40, -0.65},
    {0.49, 1.52, 2.20, 2.00, 1.16, 1.16, 1.20, 0.80, 0.80},
    {-0.49, 1.52, 2.00, 2.10, 1.29, 1.09, 1.80, 1.20, -0.95},
    {-1.29, 0.94, 2.10, 1.80, 1.42, 1.02, 2.40, 1.60, 1.10},
    {-1.60, 0.00, 2.20, 1.90, 1.55, 0.95, 3.00, 2.00, -1.25},
    {-1.29, -0.94, 2.00, 2.00, 1.68, 0.88, 3.60, 2.40, 1.40},
    {-0.49, -1.52, 2.10, 2.10, 1.81, 0.81, 4.20, 2.80, -1.55},
    {0.49, -1.52, 2.20, 1.80, 1.94, 0.74, 4.80, 3.20, 1.70},
    {1.29, -0.94, 2.00, 1.90, 2.07, 0.67, 5.40, 3.60, -1.85},
};

}  // namespace

const std::array<TriangleType, type_count>& triangle_types() {
  static const std::array<TriangleType, type_count> types = [] {
    std::array<TriangleType, type_count> out;
    for (int k = 0; k < type_count; ++k) {
      const double* r = kRawTypes[k];
      const V c((r[0] + r[2] + r[4]) / 3, (r[1] + r[3] + r[5]) / 3);
      for (int i = 0; i < 3; ++i) out[k][i] = V(r[2 * i], r[2 * i + 1]) - c;
    }
    return out;
  }();
  return types;
}

const std::array<Path, type_count>& paths() {
  static const std::array<Path, type_count> out = [] {
    std::array<Path, type_count> p;
    std::copy(std::begin(kPaths), std::end(kPaths), p.begin());
    return p;
  }();
  return out;
}

double start_time(std::uint64_t seed) { return static_cast<double>(seed % 1000) * 3.0; }

Pose pose(int k, double t) {
  const Path& p = paths()[k];
  Pose out;
  out.position = V(p.cx + p.ax * std::sin(p.wx * t + p.phase), p.cy + p.ay * std::sin(p.wy * t));
  out.velocity = V(p.ax * p.wx * std::cos(p.wx * t + p.phase), p.ay * p.wy * std::cos(p.wy * t));
  out.angle = p.angle0 + p.spin * t;
  out.spin = p.spin;
  return out;
}

Frame frame_at(double t) {
  Frame f;
  std::array<Vec2<float>, type_count> lo, hi;
  for (int k = 0; k < type_count; ++k) {
    const Pose p = pose(k, t);
    const double c = std::cos(p.angle), s = std::sin(p.angle);
    Vec2<float> v[3];
    for (int i = 0; i < 3; ++i) {
      const V& u = triangle_types()[k][i];
      v[i] = (p.position + V(c * u.x() - s * u.y(), s * u.x() + c * u.y())).cast<float>();
    }
    const TriangleOrError<float> tri = Triangle<float>::make(v[0], v[1], v[2]);
    if (!tri.ok())
      throw std::logic_error("paper: triangle type " + std::to_string(k + 1) + ": " +
                             describe(tri.error));
    f.triangles.push_back(tri.triangle);
    lo[k] = v[0].cwiseMin(v[1]).cwiseMin(v[2]);
    hi[k] = v[0].cwiseMax(v[1]).cwiseMax(v[2]);
  }
  for (int i = 0; i < type_count; ++i) {
    for (int j = i + 1; j < type_count; ++j) {
      if ((lo[i].array() <= hi[j].array()).all() && (lo[j].array() <= hi[i].array()).all()) {
        f.pairs.emplace_back(i, j);
      }
    }
  }
  return f;
}

}  // namespace dyop::scenes::paper
