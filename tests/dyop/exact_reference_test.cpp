// The exact rational reference on polygons and circles, against answers worked by hand: the
// figure every convex accuracy test is measured against.
#include <gtest/gtest.h>

#include <cmath>
#include <initializer_list>

#include "exact_reference/exact_reference.hpp"
#include "workloads/convex_classes.hpp"

namespace dyop::workloads {
namespace {

using V = Vec2<double>;

RawPolygon raw_polygon(std::initializer_list<V> points) {
  RawPolygon p;
  for (const V& v : points) p.v[static_cast<std::size_t>(p.count++)] = v;
  return p;
}

// [x0, x1] × [y0, y1], counter-clockwise from the lower left, as `SetAsBox` orders it.
RawPolygon box(double x0, double y0, double x1, double y1) {
  return raw_polygon({V(x0, y0), V(x1, y0), V(x1, y1), V(x0, y1)});
}

TEST(ExactReference, PolygonPairsGiveHandWorkedDepthsDistancesAndContacts) {
  const RawPolygon a = box(0, 0, 2, 2);
  // Overlapping by 0.5 in x and 1 in y: depth 0.5.
  ExactAnswer e = exact_separation(RawPolygonPair{a, box(1.5, 1, 3, 2.5)});
  EXPECT_EQ(e.sign, -1);
  EXPECT_EQ(e.separation, -0.5);
  // Corner to corner, (2, 2) to (3, 3).
  e = exact_separation(RawPolygonPair{a, box(3, 3, 4, 4)});
  EXPECT_EQ(e.sign, 1);
  EXPECT_EQ(e.separation, std::sqrt(2.0));
  // Edge on edge.
  e = exact_separation(RawPolygonPair{a, box(2, 0.5, 3, 1)});
  EXPECT_EQ(e.sign, 0);
  EXPECT_EQ(e.separation, 0.0);
  // Two octagons side by side, in either winding: the x axis is the least (the diagonals' overlap
  // is 1.5/√2).
  const RawPolygon octagon =
      raw_polygon({V(1, 0), V(2, 0), V(3, 1), V(3, 2), V(2, 3), V(1, 3), V(0, 2), V(0, 1)});
  RawPolygon shifted = octagon;
  for (V& v : shifted.v) v += V(2.5, 0);
  e = exact_separation(RawPolygonPair{octagon, reversed(shifted)});
  EXPECT_EQ(e.sign, -1);
  EXPECT_EQ(e.separation, -0.5);
}

TEST(ExactReference, PolygonCirclePairsGiveHandWorkedSeparations) {
  const RawPolygon a = box(0, 0, 2, 2);
  // Centre 0.5 above the top face, radius 1.
  ExactAnswer e = exact_separation(RawCirclePair{a, RawCircle{V(1, 2.5), 1}});
  EXPECT_EQ(e.sign, -1);
  EXPECT_EQ(e.separation, -0.5);
  // Centre inside, 0.5 below the top face: −(0.5 + r).
  e = exact_separation(RawCirclePair{a, RawCircle{V(1, 1.5), 0.25}});
  EXPECT_EQ(e.sign, -1);
  EXPECT_EQ(e.separation, -0.75);
  // Beyond the corner (2, 2) by (3, 4): 5 away, so radius 5 touches and radius 4 leaves 1.
  e = exact_separation(RawCirclePair{a, RawCircle{V(5, 6), 5}});
  EXPECT_EQ(e.sign, 0);
  EXPECT_EQ(e.separation, 0.0);
  e = exact_separation(RawCirclePair{reversed(a), RawCircle{V(5, 6), 4}});
  EXPECT_EQ(e.sign, 1);
  EXPECT_EQ(e.separation, 1.0);
}

TEST(ExactReference, EdgeOverlapIsHowFarTheOtherShapeReachesPastThatEdge) {
  const RawPolygon a = box(0, 0, 2, 2);
  const RawPolygonPair pair{a, box(1.5, 1, 3, 2.5)};
  EXPECT_EQ(exact_edge_overlap(pair, true, 1), 0.5);   // A's right edge, normal (1, 0)
  EXPECT_EQ(exact_edge_overlap(pair, true, 2), 1.0);   // A's top edge, normal (0, 1)
  EXPECT_EQ(exact_edge_overlap(pair, false, 3), 0.5);  // B's left edge, normal (−1, 0)
  // Clockwise, caller's edge 2 runs from (2, 2) to (2, 0): the right edge.
  EXPECT_EQ(exact_edge_overlap(RawPolygonPair{reversed(a), pair.b}, true, 2), 0.5);
  // A circle of radius 1 centred 0.5 above the top face: 0.5 past it, 2 past the right edge's line.
  const RawCirclePair circle{a, RawCircle{V(1, 2.5), 1}};
  EXPECT_EQ(exact_edge_overlap(circle, 2), 0.5);
  EXPECT_EQ(exact_edge_overlap(circle, 1), 2.0);
}

// The reference works on integers in units of the pair's least power of two: the answer of a pair
// scaled by any power of two, 2^-1000 to 2^900, is the answer scaled, exactly, wherever the scale
// loses no bit of the coordinates or of the answer (nearly every pair).
TEST(ExactReference, APairScaledByAPowerOfTwoGivesTheAnswerScaledExactly) {
  const auto keeps_bits = [](double x, int k) { return std::ldexp(std::ldexp(x, k), -k) == x; };
  const auto scaled = [&](RawPolygon p, int k, bool& kept) {
    for (int i = 0; i < p.count; ++i) {
      V& v = p.v[static_cast<std::size_t>(i)];
      kept = kept && keeps_bits(v.x(), k) && keeps_bits(v.y(), k);
      v = V(std::ldexp(v.x(), k), std::ldexp(v.y(), k));
    }
    return p;
  };
  int compared = 0;
  int pairs = 0;
  for (const ConvexClass c : {ConvexClass::Overlapping, ConvexClass::Separated,
                              ConvexClass::Touching, ConvexClass::Nested}) {
    const auto polygons = make_polygon_pairs(c, 50, 3, Precision::Double);
    const auto circles = make_circle_pairs(c, 50, 3, Precision::Double);
    for (const int k : {-1000, -60, 60, 900}) {
      for (const RawPolygonPair& p : polygons) {
        ++pairs;
        const ExactAnswer e = exact_separation(p);
        const double overlap = exact_edge_overlap(p, true, 0);
        bool kept = keeps_bits(e.separation, k) && keeps_bits(overlap, k);
        const RawPolygonPair q{scaled(p.a, k, kept), scaled(p.b, k, kept)};
        if (!kept) continue;
        ++compared;
        const ExactAnswer s = exact_separation(q);
        EXPECT_EQ(s.sign, e.sign) << name(c) << " 2^" << k;
        EXPECT_EQ(s.separation, std::ldexp(e.separation, k)) << name(c) << " 2^" << k;
        EXPECT_EQ(exact_edge_overlap(q, true, 0), std::ldexp(overlap, k)) << name(c) << " 2^" << k;
      }
      for (const RawCirclePair& p : circles) {
        ++pairs;
        const ExactAnswer e = exact_separation(p);
        bool kept = keeps_bits(e.separation, k) && keeps_bits(p.b.center.x(), k) &&
                    keeps_bits(p.b.center.y(), k) && keeps_bits(p.b.radius, k);
        const RawCircle circle{V(std::ldexp(p.b.center.x(), k), std::ldexp(p.b.center.y(), k)),
                               std::ldexp(p.b.radius, k)};
        const RawCirclePair q{scaled(p.a, k, kept), circle};
        if (!kept) continue;
        ++compared;
        const ExactAnswer s = exact_separation(q);
        EXPECT_EQ(s.sign, e.sign) << name(c) << " 2^" << k;
        EXPECT_EQ(s.separation, std::ldexp(e.separation, k)) << name(c) << " 2^" << k;
      }
    }
  }
  EXPECT_GE(compared, pairs * 9 / 10) << "pairs whose scale loses no bit";
}

}  // namespace
}  // namespace dyop::workloads
