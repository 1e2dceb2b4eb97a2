#pragma once
// Seeded random pairs of convex polygons with random queries, and a fingerprint of an answer's
// bits: for tests that pin `collide`'s answers bit for bit (tests/dyop/convex_pair_test.cpp).

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>
#include <vector>

#include "dyop/convex_pair.hpp"

namespace dyop::test_support {

// FNV-1a over the bits of each field of an answer that the level filled (manifold points past
// `point_count` are no part of it): equal fingerprints, the same answer bit for bit.
class Fingerprint {
 public:
  template <class V>
  void add(const V& value) {
    unsigned char bytes[sizeof(V)];
    std::memcpy(bytes, &value, sizeof(V));
    for (unsigned char b : bytes) hash_ = (hash_ ^ b) * 1099511628211ull;
  }
  template <class T>
  void add_vec(const Vec2<T>& v) {
    add(v.x());
    add(v.y());
  }
  template <class T>
  void add_result(const Result<T>& r) {
    add(r.status);
    add(r.reason);
    add(r.separation);
    add(r.depth);
    add_vec(r.normal);
    add_vec(r.witness_a);
    add_vec(r.witness_b);
    add(r.feature_a.type);
    add(r.feature_a.index);
    add(r.feature_b.type);
    add(r.feature_b.index);
    add(r.iterations);
    const Manifold<T>& m = r.manifold;
    add(m.point_count);
    add(m.reference_is_a);
    add(m.reference_edge);
    add(m.incident_edge);
    add_vec(m.normal);
    for (int i = 0; i < m.point_count; ++i) {
      add_vec(m.points[i].point);
      add(m.points[i].separation);
      add(m.points[i].key);
    }
  }
  std::uint64_t value() const { return hash_; }

 private:
  std::uint64_t hash_ = 14695981039346656037ull;
};

// A pair: A in world coordinates; B in its body frame (`body_b`, any winding) and the rotation
// (cos `c`, sin `s`) and translation that place it, as a Box2D contact sees a pair; a query.
template <class T>
struct PlacedPair {
  std::vector<Vec2<T>> a;
  std::vector<Vec2<T>> body_b;
  T c = 1;
  T s = 0;
  Vec2<T> translation = Vec2<T>::Zero();
  ConvexQuery<T> query;
};

// Pairs of 3 to 8 vertices each, overlapping, touching, near and apart, from a seed (the raw
// outputs of `std::mt19937`, so that every standard library draws the same pairs). One pair in
// four is two axis-aligned boxes on a grid (faces in contact exactly, edges shared). Masks on half
// of them; every level, `Apart` and `witnesses`.
template <class T>
class RandomPlacedPairs {
 public:
  explicit RandomPlacedPairs(std::uint32_t seed) : rng_(seed) {}

  PlacedPair<T> next() {
    PlacedPair<T> p;
    if (rng_() % 4 == 0) {
      const T w = T(1 + rng_() % 3);
      const T h = T(1 + rng_() % 3);
      p.a = {{0, 0}, {w, 0}, {w, h}, {0, h}};
      const T bw = T(1 + rng_() % 3);
      const T bh = T(1 + rng_() % 3);
      p.body_b = {{0, 0}, {bw, 0}, {bw, bh}, {0, bh}};
      const int turn = static_cast<int>(rng_() % 4);
      p.c = turn == 0 ? T(1) : turn == 2 ? T(-1) : T(0);
      p.s = turn == 1 ? T(1) : turn == 3 ? T(-1) : T(0);
      p.translation = {T(static_cast<int>(rng_() % 9) - 4), T(static_cast<int>(rng_() % 9) - 4)};
    } else {
      const T scale = T(std::pow(10.0, static_cast<int>(rng_() % 5) - 2));
      p.a = outline(scale);
      p.body_b = outline(scale * T(0.3 + 1.4 * unit()));
      const double angle = 2 * 3.141592653589793 * unit();
      p.c = T(std::cos(angle));
      p.s = T(std::sin(angle));
      p.translation = {T(scale * (2.2 * unit() - 1.1)), T(scale * (2.2 * unit() - 1.1))};
    }
    if (rng_() % 3 == 0) std::reverse(p.a.begin(), p.a.end());
    if (rng_() % 3 == 0) std::reverse(p.body_b.begin(), p.body_b.end());
    ConvexQuery<T>& q = p.query;
    q.level = all_levels[rng_() % 4];
    q.margin = T(0.05 * unit());
    q.face_hysteresis = T(0.001 * (rng_() % 2));
    q.apart = rng_() % 2 ? Apart::Gap : Apart::Distance;
    q.witnesses = rng_() % 4 != 0;
    if (rng_() % 2) {
      q.masks_a = {static_cast<std::uint8_t>(rng_()),
                   static_cast<std::uint8_t>(rng_() % 4 ? 0 : rng_())};
      q.masks_b = {static_cast<std::uint8_t>(rng_() % 2 ? 0 : rng_()),
                   static_cast<std::uint8_t>(rng_() % 4 ? 0 : rng_())};
      const auto keep = [](std::uint8_t bits, std::size_t count) {
        return static_cast<std::uint8_t>(bits & ((1u << count) - 1));
      };
      q.masks_a = {keep(q.masks_a.edges, p.a.size()), keep(q.masks_a.closed_vertices, p.a.size())};
      q.masks_b = {keep(q.masks_b.edges, p.body_b.size()),
                   keep(q.masks_b.closed_vertices, p.body_b.size())};
    }
    return p;
  }

 private:
  double unit() { return rng_() / 4294967296.0; }

  // 3 to 8 points on an ellipse at sorted random angles (CCW), centred near the origin.
  std::vector<Vec2<T>> outline(T scale) {
    const int n = 3 + static_cast<int>(rng_() % 6);
    std::vector<double> angle(static_cast<std::size_t>(n));
    for (double& a : angle) a = 2 * 3.141592653589793 * unit();
    std::sort(angle.begin(), angle.end());
    const double rx = scale * (0.3 + 0.7 * unit());
    const double ry = scale * (0.3 + 0.7 * unit());
    const double cx = scale * (0.2 * unit() - 0.1);
    std::vector<Vec2<T>> out;
    for (double a : angle) out.emplace_back(T(cx + rx * std::cos(a)), T(ry * std::sin(a)));
    return out;
  }

  std::mt19937 rng_;
};

}  // namespace dyop::test_support
