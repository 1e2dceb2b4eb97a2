// The internal-edge rule's kernel (`allowed_axes`): the axes it lets answer are the ones the rule's
// definition names, axis by axis, and its vector form gives its generic form's bits.
#include <gtest/gtest.h>

#include <algorithm>

#include "detail/allowed_axes.hpp"
#include "workloads/input_classes.hpp"
#include "workloads/raw_pair.hpp"

namespace dyop::workloads {
namespace {

// The rule as its definition reads, one axis at a time (`allowed_axes`'s head): allowed by the
// masks (`axis_allowed`), touched (the other triangle reaches the edge segment within `reach`:
// separating-axis test of the segment and the triangle), usable = both, unless one triangle
// reaches no edge of the other (then allowed alone); the least usable overlap of each triangle.
template <class T>
bool touched_by_definition(const detail::PairFrame<T>& f, int k, T reach) {
  const bool own_is_a = k < 3;
  const int i = own_is_a ? k : k - 3;
  const auto& own = own_is_a ? f.a : f.b;
  const auto& other = own_is_a ? f.b : f.a;
  const Triangle<T>& own_t = own_is_a ? f.ta : f.tb;
  const Triangle<T>& other_t = own_is_a ? f.tb : f.ta;
  const Vec2<T>& n = own_t.normal(i);
  const T line = n.dot(own[i]);
  T outside = -std::numeric_limits<T>::infinity();
  for (int w = 0; w < 3; ++w) outside = std::max(outside, n.dot(other[w]) - line);
  if (outside < -reach) return false;
  for (int j = 0; j < 3; ++j) {
    const Vec2<T>& m = other_t.normal(j);
    const T other_line = m.dot(other[j]);
    const T p = m.dot(own[i]) - other_line;
    const T q = m.dot(own[detail::next3(i)]) - other_line;
    if (std::min(p, q) > reach) return false;
  }
  return true;
}

template <class T>
void expect_rule_as_defined(const detail::PairFrame<T>& f, const Query<T>& q) {
  const std::array<T, 6> overlap = detail::all_overlaps(f);
  const detail::AllowedAxes<T> got = detail::allowed_axes(f, q, overlap);
  const T reach = q.margin + detail::touching_band(f);
  bool allowed[6];
  bool touched[6];
  for (int k = 0; k < 6; ++k) {
    allowed[k] = detail::axis_allowed(f, q, k);
    touched[k] = touched_by_definition(f, k, reach);
  }
  const bool a_reached = touched[0] || touched[1] || touched[2];
  const bool b_reached = touched[3] || touched[4] || touched[5];
  int best[2] = {-1, -1};
  for (int k = 0; k < 6; ++k) {
    const bool usable = allowed[k] && (!(a_reached && b_reached) || touched[k]);
    int& b = best[k / 3];
    if (usable && (b < 0 || overlap[k] < overlap[b])) b = k;
  }
  EXPECT_EQ(got.best_a, best[0]);
  EXPECT_EQ(got.best_b, best[1]);
}

// Every edge mask and closed-vertex mask over pairs of every test class, both precisions.
TEST(InternalEdgesRule, TheKernelLetsAnswerTheAxesTheRuleNames) {
  int pairs = 0;
  for (InputClass c : test_classes) {
    for (const RawPair& p : make_valid_pairs(c, 40, 71)) {
      const auto d = build<double>(p);
      const auto f = build<float>(p);
      const double margin = 0.05 * pair_size(p);
      for (unsigned edges = 0; edges < 64; edges += 5) {
        for (unsigned closed = 0; closed < 64; closed += 9) {
          const InternalEdges masks{static_cast<std::uint8_t>(edges),
                                    static_cast<std::uint8_t>(closed)};
          Query<double> qd{Level::Manifold, margin, 0, Apart::Gap};
          qd.internal_edges = masks;
          expect_rule_as_defined(detail::PairFrame<double>(d.a.triangle, d.b.triangle), qd);
          if (!f.a.ok() || !f.b.ok()) continue;
          Query<float> qf{Level::Manifold, float(margin), 0, Apart::Gap};
          qf.internal_edges = masks;
          expect_rule_as_defined(detail::PairFrame<float>(f.a.triangle, f.b.triangle), qf);
          ++pairs;
        }
      }
      if (HasFailure()) return;
    }
  }
  EXPECT_GT(pairs, 10000);
}

// The float kernel in SSE registers against the generic one, bit for bit, over reaches from 0
// to past the pair's size (where every bit flips at least once).
TEST(InternalEdgesRule, TheVectorKernelGivesTheGenericKernelsBits) {
  int compared = 0;
  for (InputClass c : test_classes) {
    for (const RawPair& p : make_valid_pairs(c, 60, 72)) {
      const auto f = build<float>(p);
      if (!f.a.ok() || !f.b.ok()) continue;
      const detail::PairFrame<float> frame(f.a.triangle, f.b.triangle);
      for (float reach : {0.0f, 1e-3f, 0.05f, 0.3f, 1.0f, 4.0f}) {
        reach *= float(pair_size(p));
        for (unsigned internal = 0; internal < 8; ++internal) {
          for (unsigned closed = 0; closed < 8; closed += 3) {
            const detail::EdgeBits generic =
                detail::edge_bits<float>(frame.ta, frame.a, frame.b, internal, closed, reach);
            const detail::EdgeBits vector =
                detail::edge_bits(frame.ta, frame.a, frame.b, internal, closed, reach);
            ASSERT_EQ(vector.allowed, generic.allowed);
            ASSERT_EQ(vector.wholly_inside, generic.wholly_inside);
            ASSERT_EQ(vector.cut_other, generic.cut_other);
            ++compared;
          }
        }
      }
    }
  }
  EXPECT_GT(compared, 10000);
}

}  // namespace
}  // namespace dyop::workloads
