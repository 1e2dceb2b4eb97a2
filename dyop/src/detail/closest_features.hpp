#pragma once
// Internal: the exact distance between two disjoint triangles and its closest features.
//
// Two disjoint convex polygons have their closest points on a vertex of one and an edge (or
// vertex) of the other, so the distance is the least of the 18 vertex–edge distances. When the
// closest point lies inside the edge, the distance is taken along the edge's unit normal (no
// subtraction of nearly equal points), which keeps it accurate relative to the pair's size.

#include <cmath>
#include <limits>

#include "detail/pair_frame.hpp"
#include "dyop/result.hpp"

namespace dyop::detail {

template <class T>
struct Closest {
  T distance = 0;
  Vec2<T> point_a = Vec2<T>::Zero();  // local
  Vec2<T> point_b = Vec2<T>::Zero();  // local
  Vec2<T> normal = Vec2<T>::Zero();   // unit, A to B
  Feature feature_a;                  // CCW indices (mapped by the caller)
  Feature feature_b;
};

// Closest point to `p` on edge `j` of triangle `verts` with unit outward normal `n`. Returns the
// squared distance; `feature` is the edge or the vertex the closest point falls on.
template <class T>
inline T closest_on_edge(const std::array<Vec2<T>, 3>& verts, int j, const Vec2<T>& n,
                         const Vec2<T>& p, Vec2<T>& closest, Feature& feature) {
  const Vec2<T>& q0 = verts[j];
  const Vec2<T>& q1 = verts[next3(j)];
  const Vec2<T> e = q1 - q0;
  const T t = e.dot(p - q0);
  if (t <= 0) {
    closest = q0;
    feature = {Feature::Type::Vertex, static_cast<std::uint8_t>(j)};
    return (p - q0).squaredNorm();
  }
  const T ee = e.squaredNorm();
  if (t >= ee) {
    closest = q1;
    feature = {Feature::Type::Vertex, static_cast<std::uint8_t>(next3(j))};
    return (p - q1).squaredNorm();
  }
  const T h = n.dot(p - q0);
  closest = p - h * n;
  feature = {Feature::Type::Edge, static_cast<std::uint8_t>(j)};
  return h * h;
}

// closest_on_edge in a frame at the edge's own start, from world coordinates: the vertex's offset
// from the edge is rounded once, relative to their distance, and the edge keeps its own shape. In
// the pair's frame a triangle smaller than that frame's rounding (eps × its distance from A's
// first vertex) collapses, and the edge's exact normal then measures the distance to its line,
// not to the segment. `c` comes back in the pair's frame (`local`: the triangle's vertices there).
template <class T>
inline T closest_on_world_edge(const Triangle<T>& t, const std::array<Vec2<T>, 3>& local, int j,
                               const Vec2<T>& p, Vec2<T>& c, Feature& fe) {
  const Vec2<T>& q = t.vertex(j);
  const std::array<Vec2<T>, 3> v = {t.vertex(0) - q, t.vertex(1) - q, t.vertex(2) - q};
  const T d = closest_on_edge(v, j, t.normal(j), Vec2<T>(p - q), c, fe);
  c += local[j];
  return d;
}

// Keeps in `best` the nearer of its current pair and A's vertex `i` against B's edge `j`.
template <class T>
inline void consider_a_vertex(const PairFrame<T>& f, int i, int j, Closest<T>& best, T& best_sq) {
  Vec2<T> c;
  Feature fe;
  const T d = closest_on_world_edge(f.tb, f.b, j, f.ta.vertex(i), c, fe);
  if (d < best_sq) {
    best_sq = d;
    best.point_a = f.a[i];
    best.point_b = c;
    best.feature_a = {Feature::Type::Vertex, static_cast<std::uint8_t>(i)};
    best.feature_b = fe;
    best.normal = fe.type == Feature::Type::Edge ? Vec2<T>(-f.tb.normal(j)) : Vec2<T>::Zero();
  }
}

// Keeps in `best` the nearer of its current pair and B's vertex `i` against A's edge `j`.
template <class T>
inline void consider_b_vertex(const PairFrame<T>& f, int i, int j, Closest<T>& best, T& best_sq) {
  Vec2<T> c;
  Feature fe;
  const T d = closest_on_world_edge(f.ta, f.a, j, f.tb.vertex(i), c, fe);
  if (d < best_sq) {
    best_sq = d;
    best.point_a = c;
    best.point_b = f.b[i];
    best.feature_a = fe;
    best.feature_b = {Feature::Type::Vertex, static_cast<std::uint8_t>(i)};
    best.normal = fe.type == Feature::Type::Edge ? f.ta.normal(j) : Vec2<T>::Zero();
  }
}

// The distance and, for a vertex–vertex pair, the normal along the joining line.
template <class T>
inline void finish_closest(Closest<T>& best, T best_sq) {
  best.distance = std::sqrt(best_sq);
  if (best.normal.isZero() && best.distance > 0) {
    best.normal = (best.point_b - best.point_a) / best.distance;
  }
}

// Distance of two triangles known to be apart (callers have a separating axis).
template <class T>
Closest<T> closest_features(const PairFrame<T>& f) {
  Closest<T> best;
  T best_sq = std::numeric_limits<T>::infinity();
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      consider_a_vertex(f, i, j, best, best_sq);
      consider_b_vertex(f, i, j, best, best_sq);
    }
  }
  finish_closest(best, best_sq);
  return best;
}

// Callers that choose how to find the closest features pass one of these to the shared steps.
template <class T>
struct AllFeatures {
  Closest<T> operator()(const PairFrame<T>& f) const { return closest_features(f); }
};

}  // namespace dyop::detail
