// DyOP-PD: the exact `dyop` against `sat` at every level, and the heuristic `dyop_fast`.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "dyop/dyop.hpp"
#include "dyop/method.hpp"
#include "dyop/sat.hpp"
#include "exact_reference/exact_reference.hpp"
#include "workloads/input_classes.hpp"
#include "support/make_triangle.hpp"

namespace dyop::workloads {
namespace {

using test_support::tri;

// Touching and penetrating pairs: the same six overlaps, so the same bits. Apart: dyop's pivot
// finds the closest features its own way and certifies them to within the touching band.
template <class T>
void expect_same_result(const Result<T>& d, const Result<T>& s, T size) {
  EXPECT_EQ(d.status, s.status);
  if (s.status != Status::Separated) {
    EXPECT_EQ(d.separation, s.separation);
    EXPECT_EQ(d.normal, s.normal);
    EXPECT_EQ(d.witness_a, s.witness_a);
    EXPECT_EQ(d.witness_b, s.witness_b);
    EXPECT_EQ(d.feature_a.index, s.feature_a.index);
    EXPECT_EQ(d.feature_b.index, s.feature_b.index);
  } else {
    EXPECT_NEAR(d.separation, s.separation, touching_tolerance<T>() * size);
  }
  ASSERT_EQ(d.manifold.point_count, s.manifold.point_count);
  for (int i = 0; i < d.manifold.point_count; ++i) {
    EXPECT_EQ(d.manifold.points[i].key, s.manifold.points[i].key);
    EXPECT_EQ(d.manifold.points[i].separation, s.manifold.points[i].separation);
  }
}

// The pivot changes how the answer is found, never the answer, at every level.
TEST(Dyop, EqualsSatAtEveryLevelOnEveryClass) {
  for (InputClass c : test_classes) {
    for (const RawPair& p : make_valid_pairs(c, 500, 11)) {
      const auto d = build<double>(p);
      const auto f = build<float>(p);
      for (Level level : {Level::Overlap, Level::Depth, Level::Contact, Level::Manifold}) {
        const Query<double> q{level, 0.05 * pair_size(p), 0.01 * pair_size(p)};
        expect_same_result(dyop(d.a.triangle, d.b.triangle, q), sat(d.a.triangle, d.b.triangle, q),
                           pair_size(p));
        if (f.a.ok() && f.b.ok()) {
          const Query<float> qf{level, float(q.margin), float(q.face_hysteresis)};
          expect_same_result(dyop(f.a.triangle, f.b.triangle, qf),
                             sat(f.a.triangle, f.b.triangle, qf), float(pair_size(p)));
        }
      }
    }
  }
}

// `Apart::Gap` asks for the proof of separation instead of the distance: the same status and,
// for pairs apart, a separation that never exceeds the exact distance, along a unit axis, with
// the witnesses left at their defaults; touching and penetrating pairs are answered bit for bit
// as with the distance, manifold included.
TEST(Dyop, GapForPairsApartIsALowerBoundOnTheDistanceAndChangesNothingElse) {
  int apart = 0;
  for (InputClass c : test_classes) {
    for (const RawPair& p : make_valid_pairs(c, 300, 17)) {
      const auto d = build<double>(p);
      for (Level level : {Level::Depth, Level::Contact, Level::Manifold}) {
        Query<double> q{level, 0.05 * pair_size(p), 0.01 * pair_size(p)};
        const Result<double> distance = dyop(d.a.triangle, d.b.triangle, q);
        q.apart = Apart::Gap;
        for (const Result<double>& gap :
             {dyop(d.a.triangle, d.b.triangle, q), sat(d.a.triangle, d.b.triangle, q)}) {
          ASSERT_EQ(gap.status, distance.status);
          if (gap.status != Status::Separated) {
            expect_same_result(gap, distance, pair_size(p));
            continue;
          }
          ++apart;
          EXPECT_GT(gap.separation, 0.0);
          // Equal where the closest features are a vertex and an edge; both are rounded.
          EXPECT_LE(gap.separation,
                    distance.separation + touching_tolerance<double>() * pair_size(p))
              << "a lower bound";
          EXPECT_NEAR(gap.normal.norm(), 1.0, 1e-12);
          EXPECT_EQ(gap.witness_a, Vec2<double>::Zero());
          EXPECT_EQ(gap.feature_a.type, Feature::Type::None);
          EXPECT_EQ(gap.manifold.point_count, distance.manifold.point_count);
        }
      }
    }
  }
  EXPECT_GT(apart, 100) << "the classes hold pairs apart";
}

// Every field of a manifold query but the Contact level's, bit for bit (the manifold whole).
template <class T>
void expect_same_but_witnesses(const Result<T>& bare, const Result<T>& full) {
  EXPECT_EQ(bare.status, full.status);
  EXPECT_EQ(bare.separation, full.separation);
  EXPECT_EQ(bare.depth, full.depth);
  EXPECT_EQ(bare.normal, full.normal);
  const Manifold<T>& b = bare.manifold;
  const Manifold<T>& f = full.manifold;
  EXPECT_EQ(b.reference_is_a, f.reference_is_a);
  EXPECT_EQ(b.reference_edge, f.reference_edge);
  EXPECT_EQ(b.incident_edge, f.incident_edge);
  EXPECT_EQ(b.normal, f.normal);
  ASSERT_EQ(b.point_count, f.point_count);
  for (int i = 0; i < b.point_count; ++i) {
    EXPECT_EQ(b.points[i].point, f.points[i].point);
    EXPECT_EQ(b.points[i].separation, f.points[i].separation);
    EXPECT_EQ(b.points[i].key, f.points[i].key);
  }
  EXPECT_EQ(bare.witness_a, Vec2<T>::Zero());
  EXPECT_EQ(bare.witness_b, Vec2<T>::Zero());
  EXPECT_EQ(bare.feature_a.type, Feature::Type::None);
  EXPECT_EQ(bare.feature_b.type, Feature::Type::None);
}

// A manifold without witnesses (`Query::witnesses` false, as the Box2D plug-in asks) is the
// manifold with them, and the same status, depth and normal: only the Contact level's fields are
// left out. Every method of the registry that claims it (`MethodInfo::manifold_only`), over every
// class, both precisions, both answers for pairs apart and with internal-edge masks, which take
// the rule's own path.
TEST(Dyop, ManifoldWithoutWitnessesIsTheManifoldWithThemBitForBit) {
  int with_points = 0;
  int methods = 0;
  const InternalEdges masks[] = {{}, {0b000101, 0b000010}, {0b111000, 0b000111}};
  for (const MethodInfo& row : method_table) {
    if (!row.manifold_only()) continue;
    ++methods;
    for (InputClass c : test_classes) {
      for (const RawPair& p : make_valid_pairs(c, 200, 23)) {
        const auto d = build<double>(p);
        const auto f = build<float>(p);
        for (Apart apart : {Apart::Distance, Apart::Gap}) {
          for (const InternalEdges& m : masks) {
            const Query<double> q{Level::Manifold, 0.05 * pair_size(p), 0.01 * pair_size(p), apart,
                                  m};
            Query<double> bare = q;
            bare.witnesses = false;
            const Result<double> full = penetrate(row.method, d.a.triangle, d.b.triangle, q);
            expect_same_but_witnesses(penetrate(row.method, d.a.triangle, d.b.triangle, bare),
                                      full);
            with_points += full.manifold.point_count > 0;
            if (!f.a.ok() || !f.b.ok()) continue;
            const Query<float> qf{Level::Manifold, float(q.margin), float(q.face_hysteresis), apart,
                                  m};
            Query<float> bare_f = qf;
            bare_f.witnesses = false;
            expect_same_but_witnesses(penetrate(row.method, f.a.triangle, f.b.triangle, bare_f),
                                      penetrate(row.method, f.a.triangle, f.b.triangle, qf));
          }
        }
      }
    }
  }
  EXPECT_TRUE(info(Method::Dyop).manifold_only() && info(Method::Sat).manifold_only());
  EXPECT_GT(with_points, 1000 * methods) << "the classes hold touching and penetrating pairs";
}

// With `Apart::Gap` (the Box2D plug-in's query), a pair whose separation exceeds the margin is
// answered as without masks: the same status, separation, depth and normal under every
// internal-edge mask, and no manifold point. The plug-in finds a contact's masks only once an
// answer without them is not apart beyond the margin. Every method of the registry with the rule,
// over every class, both precisions, every edge mask.
template <class T>
int expect_apart_beyond_margin_ignores_masks(Method m, const Triangle<T>& a, const Triangle<T>& b,
                                             Query<T> q) {
  const Result<T> plain = penetrate(m, a, b, q);
  if (plain.status == Status::Separated) {
    EXPECT_GE(plain.separation, 0) << "a gap, at least 0";
  }
  if (!(plain.status == Status::Separated && plain.separation > q.margin)) return 0;
  EXPECT_EQ(plain.manifold.point_count, 0);
  for (unsigned edges = 1; edges < 64; ++edges) {
    for (const unsigned vertices : {0u, 63u, edges ^ 63u}) {
      q.internal_edges = {static_cast<std::uint8_t>(edges), static_cast<std::uint8_t>(vertices)};
      const Result<T> r = penetrate(m, a, b, q);
      EXPECT_EQ(r.status, plain.status);
      EXPECT_EQ(r.separation, plain.separation);
      EXPECT_EQ(r.depth, plain.depth);
      EXPECT_EQ(r.normal, plain.normal);
      EXPECT_EQ(r.manifold.point_count, 0) << "edges " << edges << " vertices " << vertices;
    }
  }
  return 1;
}

TEST(InternalEdgesRule, APairApartBeyondTheMarginIsAnsweredAsWithoutMasks) {
  int apart = 0;
  for (const MethodInfo& row : method_table) {
    if (!row.internal_edges()) continue;
    for (InputClass c : test_classes) {
      for (const RawPair& p : make_valid_pairs(c, 100, 29)) {
        const auto d = build<double>(p);
        const auto f = build<float>(p);
        const Query<double> q{Level::Manifold, 0.05 * pair_size(p), 0.01 * pair_size(p),
                              Apart::Gap};
        apart +=
            expect_apart_beyond_margin_ignores_masks(row.method, d.a.triangle, d.b.triangle, q);
        if (!f.a.ok() || !f.b.ok()) continue;
        const Query<float> qf{Level::Manifold, float(q.margin), float(q.face_hysteresis),
                              Apart::Gap};
        apart +=
            expect_apart_beyond_margin_ignores_masks(row.method, f.a.triangle, f.b.triangle, qf);
      }
    }
  }
  EXPECT_GT(apart, 500) << "the classes hold pairs apart beyond the margin";
}

// Two slivers end to end, 24 apart (found by fuzz_sat, see tests/testbed/degenerate_test.cpp): in
// float every edge normal's gap lies in the touching band (the widest, 0.094, against 0.14), so the
// distance decides that they are apart. With `Apart::Gap` the answer is still the gap along its
// axis, as for any pair apart, so that `separation > margin` means the masks are not read (checked
// under every edge mask); with `Apart::Distance`, the distance.
TEST(InternalEdgesRule, APairApartByItsDistanceInTheTouchingBandIsAnsweredWithItsGap) {
  using V = Vec2<double>;
  const RawPair p{{V(0, 0), V(0, 4), V(4, -1020)}, {V(-4, 36908), V(4, 1032), V(0, 28)}};
  const auto t = build<float>(p);
  ASSERT_TRUE(t.a.ok() && t.b.ok());
  for (const Method m : {Method::Dyop, Method::Sat}) {
    SCOPED_TRACE(name(m));
    Query<float> q{Level::Manifold, 0.05f, 0, Apart::Gap};
    const Result<float> gap = penetrate(m, t.a.triangle, t.b.triangle, q);
    EXPECT_EQ(gap.status, Status::Separated);
    EXPECT_GE(gap.separation, 0.05f);
    EXPECT_LE(gap.separation, 0.14f);
    EXPECT_EQ(expect_apart_beyond_margin_ignores_masks(m, t.a.triangle, t.b.triangle, q), 1);
    q.apart = Apart::Distance;
    const Result<float> distance = penetrate(m, t.a.triangle, t.b.triangle, q);
    EXPECT_EQ(distance.status, Status::Separated);
    EXPECT_NEAR(distance.separation, 24.0f, 1e-3f * 36908);
  }
}

TEST(DyopFast, FindsAVertexIntoFaceDepthLikeThePaper) {
  const auto a = tri<double>(0, 0, 4, 0, 2, 4);
  const auto b = tri<double>(2, 0.5, 1, -2, 3, -2);
  const Result<double> r = dyop_fast(a, b, {Level::Contact});
  EXPECT_EQ(r.status, Status::Penetrating);
  EXPECT_DOUBLE_EQ(r.depth, 0.5);
  EXPECT_EQ(r.normal, Vec2<double>(0, -1));
  EXPECT_EQ(r.feature_b.type, Feature::Type::Vertex);
  EXPECT_EQ(r.feature_b.index, 0);
}

// Documented weakness of the heuristic: two triangles crossing like a star, no vertex of either
// inside the other, penetrate; dyop_fast (only pivot vertices inside count) does not see it.
TEST(DyopFast, MissesCrossingsWhereNoPivotVertexIsInside) {
  const auto a = tri<double>(0, 0, 6, 0, 3, 5);
  const auto b = tri<double>(0, 3.5, 6, 3.5, 3, -1.5);
  EXPECT_EQ(sat(a, b).status, Status::Penetrating);
  EXPECT_NE(dyop_fast(a, b).status, Status::Penetrating);
}

// A pivot vertex strictly inside the other triangle is a proof of overlap: no false positives.
TEST(DyopFast, NeverCallsAnApartPairPenetratingAndNeverReturnsNaN) {
  std::ostringstream figures;
  for (InputClass c : test_classes) {
    int penetrating = 0, found = 0;
    double worst = 0;
    for (const RawPair& p : make_valid_pairs(c, 2000, 5)) {
      const auto t = build<double>(p);
      const Result<double> fast = dyop_fast(t.a.triangle, t.b.triangle, {Level::Manifold});
      const ExactAnswer exact = exact_separation(p);
      ASSERT_TRUE(std::isfinite(fast.separation) && fast.normal.allFinite());
      ASSERT_GE(fast.depth, 0);
      if (fast.status == Status::Penetrating) {
        EXPECT_EQ(exact.sign, -1) << name(c);
      }
      if (exact.sign < 0) {
        ++penetrating;
        if (fast.status == Status::Penetrating) {
          ++found;
          worst = std::max(worst, std::abs(fast.separation - exact.separation) / pair_size(p));
        }
      }
    }
    figures << name(c) << ": found " << found << "/" << penetrating
            << " penetrations, max depth error/size " << worst << "; ";
  }
  RecordProperty("figures", figures.str());
}

}  // namespace
}  // namespace dyop::workloads
