#include "scenes/manifold_check.hpp"

#include <box2d/box2d.h>

#include <algorithm>
#include <cmath>
#include <optional>

#include "dyop/box2d_measurement.hpp"
#include "dyop/sat.hpp"
#include "scenes/exact_pair.hpp"

namespace dyop::scenes {
namespace {

// How deep the two triangles overlap along the unit direction `u` (from A to B).
double overlap_along(const ExactPair& pair, const Vec2<double>& u) {
  double a_max = pair.a.vertex(0).dot(u);
  double b_min = pair.b.vertex(0).dot(u);
  for (int i = 1; i < 3; ++i) {
    a_max = std::max(a_max, pair.a.vertex(i).dot(u));
    b_min = std::min(b_min, pair.b.vertex(i).dot(u));
  }
  return a_max - b_min;
}

// The deepest separation of manifold `m` as the solver computes it, in A's frame, in double.
// Also gives the manifold's normal from A to B.
double deepest_separation(const b2Manifold& m, const FrameBInA& f, Vec2<double>* normal) {
  const bool face_a = m.type == b2Manifold::e_faceA;
  const Vec2<double> face_normal =
      face_a ? Vec2<double>(m.localNormal.x, m.localNormal.y) : f.direction(m.localNormal);
  const Vec2<double> plane =
      face_a ? Vec2<double>(m.localPoint.x, m.localPoint.y) : f.point(m.localPoint);
  double deepest = 0;
  for (int i = 0; i < m.pointCount; ++i) {
    const b2Vec2& p = m.points[i].localPoint;
    const Vec2<double> point = face_a ? f.point(p) : Vec2<double>(p.x, p.y);
    const double separation = (point - plane).dot(face_normal);
    deepest = i == 0 ? separation : std::min(deepest, separation);
  }
  if (normal) *normal = face_a ? face_normal : Vec2<double>(-face_normal);
  return deepest;
}

}  // namespace

void ManifoldCheck::PreSolve(b2Contact* contact, const b2Manifold*) {
  const b2Manifold& m = *contact->GetManifold();
  if (m.pointCount == 0) return;
  const std::optional<ExactPair> pair = exact_pair(*contact);
  const std::optional<ExactConvexPair> convex = pair ? std::nullopt : exact_convex_pair(*contact);
  if (!pair && !convex) return;
  const FrameBInA& frame = pair ? pair->b_in_a : convex->b_in_a;
  Vec2<double> normal;
  // A circle's point is its centre: the solver takes its radius off, and so does the check.
  const double radius = convex && !convex->b ? convex->circle.radius : 0.0;
  const double deepest = deepest_separation(m, frame, &normal) - radius;
  record_kept(*contact, frame, deepest + radius);

  const Result<double> exact = pair ? sat(pair->a, pair->b) : convex->exact(Level::Depth);
  if (!(exact.separation < 0)) return;
  ++errors_.checked;
  errors_.depth_max = std::max(errors_.depth_max, std::abs(deepest - exact.separation));
  const double along = pair ? overlap_along(*pair, normal) : convex->overlap_along(normal);
  errors_.normal_max = std::max(errors_.normal_max, std::max(0.0, along - exact.depth));
}

void ManifoldCheck::record_kept(const b2Contact& contact, const FrameBInA& frame, double deepest) {
  // What the contact computes afresh for this pose: the manifold a kept one stands for.
  b2Manifold fresh;
  box2d::measurement::evaluate_afresh(contact, &fresh);
  ++errors_.touching;
  if (fresh.pointCount == 0) {
    ++errors_.stale;
  } else {
    errors_.kept_max =
        std::max(errors_.kept_max, std::abs(deepest - deepest_separation(fresh, frame, nullptr)));
  }
}

}  // namespace dyop::scenes
