// `Manifold::lead` on seeded pairs of every penetrating kind: it is the next least overlap of an
// axis, but the other triangle's lying flush with the reference face, minus the face's, measured
// here apart from the solvers, and within `Query::lead_reach` only when asked; and its promise
// holds: B moved by less than (hysteresis + lead) / 2 in the direction worst for each such axis,
// no axis beats the face by more than the hysteresis.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>

#include "dyop/dyop.hpp"
#include "dyop/sat.hpp"
#include "support/overlap_along.hpp"
#include "workloads/input_classes.hpp"

namespace dyop::workloads {
namespace {

constexpr int kPairsPerClass = 2000;
constexpr double kHysteresis = 1e-3;  // of pairs about 1 unit across
constexpr double kRounding = 1e-9;    // what double arithmetic leaves on overlaps of such pairs
constexpr double kFlushCosine = 1 - 2e-4;  // the solvers' `flush_cosine`
constexpr double kFlushMargin = 1e-9;      // directions this close to that cosine are left out
constexpr double kReach = 0.05;            // a `Query::lead_reach` below many pairs' leads

// The six axes of pair `p`, each pointing from A to B: A's outward edge normals, then B's negated.
std::array<Vec2<double>, 6> axes_of(const RawPair& p) {
  std::array<Vec2<double>, 6> out;
  for (int t = 0; t < 2; ++t) {
    const std::array<Vec2<double>, 3>& v = t == 0 ? p.a : p.b;
    const double turn =
        (v[1] - v[0]).x() * (v[2] - v[0]).y() - (v[1] - v[0]).y() * (v[2] - v[0]).x();
    for (int e = 0; e < 3; ++e) {
      const Vec2<double> d = v[(e + 1) % 3] - v[e];
      const Vec2<double> outward =
          (turn > 0 ? Vec2<double>(d.y(), -d.x()) : Vec2<double>(-d.y(), d.x())).normalized();
      out[3 * t + e] = t == 0 ? outward : Vec2<double>(-outward);
    }
  }
  return out;
}

RawPair moved(RawPair p, const Vec2<double>& by) {
  for (Vec2<double>& v : p.b) v += by;
  return p;
}

template <class Solve>
void check_leads(InputClass c, const Solve& solve) {
  Query<double> q{Level::Manifold};
  q.face_hysteresis = kHysteresis;
  int checked = 0;
  for (const RawPair& p : make_valid_pairs(c, kPairsPerClass, 11)) {
    const auto t = build<double>(p);
    const Result<double> r = solve(t.a.triangle, t.b.triangle, q);
    if (r.manifold.point_count == 0) {
      EXPECT_EQ(r.manifold.lead, std::numeric_limits<double>::infinity());
      continue;
    }
    const Vec2<double> u = r.manifold.normal;
    const double face = test_support::overlap_along(p, u);
    const std::array<Vec2<double>, 6> axes = axes_of(p);
    const int other = r.manifold.reference_is_a ? 3 : 0;  // the other triangle's first axis
    const int own = (r.manifold.reference_is_a ? 0 : 3) + r.manifold.reference_edge;
    std::array<bool, 6> counted{};
    double next = std::numeric_limits<double>::infinity();
    bool borderline = false;
    for (int k = 0; k < 6; ++k) {
      const double cosine = axes[k].dot(u);
      const bool of_other = k >= other && k < other + 3;
      borderline |= of_other && std::abs(cosine - kFlushCosine) < kFlushMargin;
      counted[k] = k != own && !(of_other && cosine >= kFlushCosine);
      if (counted[k]) next = std::min(next, test_support::overlap_along(p, axes[k]));
    }
    if (borderline) continue;
    ++checked;
    EXPECT_NEAR(r.manifold.lead, next - face, kRounding) << name(c);
    EXPECT_GE(r.manifold.lead, -kHysteresis - kRounding) << name(c);
    // Looked for only within a reach: the same lead below it, +infinity beyond.
    Query<double> within = q;
    within.lead_reach = kReach;
    const double reached = solve(t.a.triangle, t.b.triangle, within).manifold.lead;
    if (std::abs(r.manifold.lead - kReach) > kRounding) {
      EXPECT_EQ(reached, r.manifold.lead < kReach ? r.manifold.lead
                                                  : std::numeric_limits<double>::infinity());
    }
    const double room = 0.999 * (kHysteresis + r.manifold.lead) / 2;
    for (int k = 0; k < 6; ++k) {
      if (!counted[k]) continue;
      // Moving B along (axis − u) shrinks the axis's overlap against the face's the most.
      const RawPair m = moved(p, room * (axes[k] - u).normalized());
      EXPECT_GE(test_support::overlap_along(m, axes[k]) - test_support::overlap_along(m, u),
                -kHysteresis - kRounding)
          << name(c);
    }
  }
  EXPECT_GT(checked, kPairsPerClass / 10) << name(c);
}

TEST(ManifoldLead, IsTheNextNonFlushOverlapAndKeepsItsPromiseUnderSat) {
  for (const InputClass c : {InputClass::Overlapping, InputClass::AxisAligned,
                             InputClass::NearParallel, InputClass::Contained}) {
    check_leads(c,
                [](const auto& a, const auto& b, const Query<double>& q) { return sat(a, b, q); });
  }
}

TEST(ManifoldLead, IsTheNextNonFlushOverlapAndKeepsItsPromiseUnderDyop) {
  for (const InputClass c : {InputClass::Overlapping, InputClass::AxisAligned,
                             InputClass::NearParallel, InputClass::Contained}) {
    check_leads(c,
                [](const auto& a, const auto& b, const Query<double>& q) { return dyop(a, b, q); });
  }
}

}  // namespace
}  // namespace dyop::workloads
