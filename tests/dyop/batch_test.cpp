// The batch kernel against `sat`, per class of input, for float and double and for each kernel
// (portable, AVX2 and AVX-512, each forced): statuses, separations, normals, tails, invalid rows,
// levels.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

#include "dyop/batch.hpp"
#include "dyop/dyop.hpp"
#include "dyop/sat.hpp"
#include "workloads/batch_arrays.hpp"
#include "exact_reference/exact_reference.hpp"
#include "workloads/input_classes.hpp"
#include "support/overlap_along.hpp"

namespace dyop {
namespace {

using test_support::overlap_along;
using workloads::RawPair;
using V2 = Vec2<double>;

template <class Scalar, BatchKernel K>
struct Config {
  using T = Scalar;
  static constexpr BatchKernel kernel = K;
};

// Separation bound against sat, relative to the pair's size (the figures): float is
// compared on float-rounded input with sat<float>.
template <class T>
double separation_tolerance() {
  return std::is_same_v<T, float> ? 1e-5 : 1e-12;
}

// The pairs as T sees them, one column per coordinate.
template <class T>
struct Columns {
  std::vector<T> c[12];  // ax0 ay0 ax1 ay1 ax2 ay2 bx0 by0 bx1 by1 bx2 by2

  void push(const RawPair& p) {
    for (int i = 0; i < 3; ++i) {
      c[2 * i].push_back(static_cast<T>(p.a[i].x()));
      c[2 * i + 1].push_back(static_cast<T>(p.a[i].y()));
      c[6 + 2 * i].push_back(static_cast<T>(p.b[i].x()));
      c[7 + 2 * i].push_back(static_cast<T>(p.b[i].y()));
    }
  }
  std::size_t size() const { return c[0].size(); }
  PairBatch<T> batch(std::size_t count) const {
    return {c[0].data(),  c[1].data(),  c[2].data(), c[3].data(), c[4].data(),
            c[5].data(),  c[6].data(),  c[7].data(), c[8].data(), c[9].data(),
            c[10].data(), c[11].data(), count};
  }
  PairBatch<T> batch() const { return batch(size()); }
  // Row k as the caller gave it, in double (exact: T → double).
  RawPair row(std::size_t k) const {
    RawPair p;
    for (int i = 0; i < 3; ++i) {
      p.a[i] = V2(c[2 * i][k], c[2 * i + 1][k]);
      p.b[i] = V2(c[6 + 2 * i][k], c[7 + 2 * i][k]);
    }
    return p;
  }
};

template <class T>
Columns<T> columns(const std::vector<RawPair>& pairs) {
  Columns<T> out;
  for (const RawPair& p : pairs) out.push(p);
  return out;
}

// Outputs with `guard` extra entries past the end, filled with a sentinel to catch any write.
template <class T>
struct Outputs {
  static constexpr std::size_t guard = 9;
  static constexpr T sentinel = T(-12345.5);
  std::size_t count;
  std::vector<Status> status;
  std::vector<T> separation, normal_x, normal_y;

  explicit Outputs(std::size_t n)
      : count(n),
        status(n + guard, static_cast<Status>(0xAB)),
        separation(n + guard, sentinel),
        normal_x(n + guard, sentinel),
        normal_y(n + guard, sentinel) {}
  BatchOutput<T> out() {
    return {status.data(), separation.data(), normal_x.data(), normal_y.data()};
  }
  bool guard_intact() const {
    for (std::size_t k = count; k < count + guard; ++k) {
      if (static_cast<std::uint8_t>(status[k]) != 0xAB || separation[k] != sentinel ||
          normal_x[k] != sentinel || normal_y[k] != sentinel) {
        return false;
      }
    }
    return true;
  }
};

double to_segment(const V2& x, const V2& q0, const V2& q1) {
  const V2 e = q1 - q0;
  const double t = std::clamp(e.dot(x - q0) / e.squaredNorm(), 0.0, 1.0);
  return (x - (q0 + t * e)).norm();
}

// For a pair apart: how far the distance vector `separation · n` misses being a vertex-to-boundary
// witness pair (a vertex of A moved by it lands on B's boundary, or one of B moved back lands on
// A's). Zero for the true closest features, and for either side of a tie between them.
double witness_miss(const RawPair& p, const V2& n, double separation) {
  double miss = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      const int k = (j + 1) % 3;
      miss = std::min(
          miss, to_segment(p.a[i] - p.a[0] + separation * n, p.b[j] - p.a[0], p.b[k] - p.a[0]));
      miss = std::min(
          miss, to_segment(p.b[i] - p.a[0] - separation * n, p.a[j] - p.a[0], p.a[k] - p.a[0]));
    }
  }
  return miss;
}

// Each test below is a function of the precision and the kernel, called by the typed suite for
// every pair of them: its body is compiled once per precision, the kernel being a run-time
// argument of `penetrate_batch`.
template <class C>
class Batch : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!batch_kernel_available(C::kernel))
      GTEST_SKIP() << name(C::kernel) << " not available here";
  }
};

// The batch of the first `count` rows of `cols` through `kernel`.
template <class T>
BatchError run_batch(BatchKernel kernel, const Columns<T>& cols, std::size_t count, Level level,
                     Outputs<T>& out) {
  return penetrate_batch(cols.batch(count), level, out.out(), kernel);
}

struct ConfigNames {
  template <class C>
  static std::string GetName(int) {
    return std::string(std::is_same_v<typename C::T, float> ? "float_" : "double_") +
           name(C::kernel);
  }
};

using Configs =
    ::testing::Types<Config<float, BatchKernel::Portable>, Config<float, BatchKernel::Avx2>,
                     Config<float, BatchKernel::Avx512>, Config<double, BatchKernel::Portable>,
                     Config<double, BatchKernel::Avx2>, Config<double, BatchKernel::Avx512>>;
TYPED_TEST_SUITE(Batch, Configs, ConfigNames);

// 10 classes × 2,500 = 25,000 seeded pairs, each row checked against sat on the same T input,
// and its separation against the exact rational reference on that input.
template <class T>
void agrees_with_sat_on_every_pair_class(BatchKernel kernel) {
  constexpr int kPerClass = 2500;
  const double tol = separation_tolerance<T>();
  std::ostringstream figures;
  for (const auto c : workloads::test_classes) {
    const auto pairs = workloads::make_valid_pairs(c, kPerClass, 5);
    const Columns<T> cols = columns<T>(pairs);
    Outputs<T> out(cols.size());
    ASSERT_EQ(run_batch(kernel, cols, cols.size(), Level::Depth, out), BatchError::None);
    ASSERT_TRUE(out.guard_intact());
    double worst = 0, worst_exact = 0;
    int band_edge = 0, other_axis = 0, invalid = 0;
    for (std::size_t k = 0; k < cols.size(); ++k) {
      SCOPED_TRACE(::testing::Message() << workloads::name(c) << " row " << k);
      const RawPair p = cols.row(k);
      const auto t = workloads::build<T>(p);
      const Status got = out.status[k];
      if (!t.a.ok() || !t.b.ok()) {  // float-rounded slivers can be degenerate in float
        ++invalid;
        EXPECT_EQ(got, Status::Invalid);
        EXPECT_FALSE(batch_row_error(cols.batch(), k).ok());
        continue;
      }
      const Result<T> want = sat(t.a.triangle, t.b.triangle, {Level::Depth});
      const double size = workloads::pair_size(p);
      const double sep = out.separation[k];
      const V2 n(out.normal_x[k], out.normal_y[k]);
      ASSERT_NE(got, Status::Invalid);
      if (got != want.status) {
        // Only across the edge of the touching band, where rounding decides: the Touching side's
        // separation (−overlap) is then near ±band.
        ++band_edge;
        const double band =
            touching_tolerance<T>() * std::max(t.a.triangle.size(), t.b.triangle.size());
        const double touching_sep = got == Status::Touching ? sep : double(want.separation);
        EXPECT_TRUE(got == Status::Touching || want.status == Status::Touching);
        EXPECT_GE(std::abs(touching_sep), 0.5 * band);
        continue;
      }
      const double err = std::abs(sep - double(want.separation)) / size;
      worst = std::max(worst, err);
      EXPECT_LE(err, tol) << "batch " << sep << " sat " << want.separation;
      const double exact = workloads::exact_separation(p).separation;
      worst_exact = std::max(worst_exact, std::abs(sep - exact) / size);
      EXPECT_NEAR(sep, exact, tol * size);
      EXPECT_NEAR(n.norm(), 1.0, (std::is_same_v<T, float> ? 1e-6 : 1e-14));
      // The normal realises the separation (either side of a tie allowed); it is sat's unless tied.
      if (got == Status::Separated) {
        EXPECT_LE(witness_miss(p, n, sep), tol * size) << "normal " << n.transpose();
      } else {
        EXPECT_NEAR(-overlap_along(p, n), sep, tol * size) << "normal " << n.transpose();
      }
      if ((n - want.normal.template cast<double>()).norm() > 1e-3) ++other_axis;
    }
    figures << workloads::name(c) << ": max |Δsep|/size vs sat " << worst << ", vs exact "
            << worst_exact << ", band-edge statuses " << band_edge << ", tied other axis "
            << other_axis << ", invalid in T " << invalid << "; ";
    EXPECT_LE(band_edge, kPerClass / 1000) << workloads::name(c);
  }
  ::testing::Test::RecordProperty("figures", figures.str());
  std::printf("[ figures  ] %s\n", figures.str().c_str());
}
TYPED_TEST(Batch, AgreesWithSatOnEveryPairClass) {
  agrees_with_sat_on_every_pair_class<typename TypeParam::T>(TypeParam::kernel);
}

// Overlap computes the same statuses and writes nothing else (null arrays are then allowed).
template <class T>
void overlap_level_writes_the_same_statuses_and_nothing_else(BatchKernel kernel) {
  const auto pairs = workloads::make_valid_pairs(workloads::InputClass::General, 1000, 11);
  const Columns<T> cols = columns<T>(pairs);
  Outputs<T> depth(cols.size()), overlap(cols.size());
  ASSERT_EQ(run_batch(kernel, cols, cols.size(), Level::Depth, depth), BatchError::None);
  ASSERT_EQ(run_batch(kernel, cols, cols.size(), Level::Overlap, overlap), BatchError::None);
  EXPECT_EQ(depth.status, overlap.status);
  for (std::size_t k = 0; k < cols.size() + Outputs<T>::guard; ++k) {
    ASSERT_EQ(overlap.separation[k], Outputs<T>::sentinel);
    ASSERT_EQ(overlap.normal_x[k], Outputs<T>::sentinel);
    ASSERT_EQ(overlap.normal_y[k], Outputs<T>::sentinel);
  }
  std::vector<Status> status(cols.size());
  EXPECT_EQ(penetrate_batch(cols.batch(), Level::Overlap, {status.data()}, kernel),
            BatchError::None);
  EXPECT_EQ(status, std::vector<Status>(depth.status.begin(), depth.status.begin() + cols.size()));
}
TYPED_TEST(Batch, OverlapLevelWritesTheSameStatusesAndNothingElse) {
  overlap_level_writes_the_same_statuses_and_nothing_else<typename TypeParam::T>(TypeParam::kernel);
}

// Any count, multiple of the width or not, gives every row exactly as a long batch does, and
// writes nothing past the end; count 0 writes nothing and needs no arrays.
template <class T>
void any_count_gives_the_same_rows_and_writes_nothing_past_the_end(BatchKernel kernel) {
  const auto pairs = workloads::make_valid_pairs(workloads::InputClass::General, 203, 3);
  const Columns<T> cols = columns<T>(pairs);
  Outputs<T> full(cols.size());
  ASSERT_EQ(run_batch(kernel, cols, cols.size(), Level::Depth, full), BatchError::None);
  for (std::size_t count : {0, 1, 2, 3, 4, 5, 7, 8, 9, 11, 15, 16, 17, 31, 33, 100, 203}) {
    SCOPED_TRACE(::testing::Message() << "count " << count);
    Outputs<T> out(count);
    ASSERT_EQ(run_batch(kernel, cols, count, Level::Depth, out), BatchError::None);
    EXPECT_TRUE(out.guard_intact());
    for (std::size_t k = 0; k < count; ++k) {
      EXPECT_EQ(out.status[k], full.status[k]);
      EXPECT_EQ(out.separation[k], full.separation[k]);
      EXPECT_EQ(out.normal_x[k], full.normal_x[k]);
      EXPECT_EQ(out.normal_y[k], full.normal_y[k]);
    }
  }
  EXPECT_EQ(penetrate_batch(PairBatch<T>{}, Level::Depth, BatchOutput<T>{}, kernel),
            BatchError::None);
}
TYPED_TEST(Batch, AnyCountGivesTheSameRowsAndWritesNothingPastTheEnd) {
  any_count_gives_the_same_rows_and_writes_nothing_past_the_end<typename TypeParam::T>(
      TypeParam::kernel);
}

// Rows that Triangle<T>::make rejects are Invalid (separation and normal 0), at every lane
// position and in the tail, batch_row_error names the problem, and the other rows are untouched.
template <class T>
void invalid_rows_are_marked_and_the_other_rows_unaffected(BatchKernel kernel) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const double huge = 4.0 * double(max_coordinate<T>());
  const RawPair good{{V2(0, 0), V2(2, 0), V2(0, 2)}, {V2(1, 1), V2(3, 1), V2(1, 3)}};
  struct Bad {
    RawPair pair;
    TriangleError a, b;
  };
  const std::vector<Bad> bad = {
      {{{V2(nan, 0), V2(2, 0), V2(0, 2)}, good.b}, TriangleError::NonFinite, TriangleError::None},
      {{good.a, {V2(1, 1), V2(inf, 1), V2(1, 3)}}, TriangleError::None, TriangleError::NonFinite},
      {{good.a, {V2(1, 1), V2(3, -inf), V2(1, 3)}}, TriangleError::None, TriangleError::NonFinite},
      {{{V2(huge, 0), V2(2, 0), V2(0, 2)}, good.b}, TriangleError::TooLarge, TriangleError::None},
      {{good.a, {V2(1, 1), V2(1, 1), V2(1, 3)}},
       TriangleError::None,
       TriangleError::RepeatedVertex},
      {{{V2(0, 0), V2(1, 1), V2(2, 2)}, good.b}, TriangleError::Degenerate, TriangleError::None},
      {{good.a, {V2(0, 0), V2(1, 1e-9), V2(2, 0)}},
       TriangleError::None,
       std::is_same_v<T, float> ? TriangleError::Degenerate : TriangleError::None},
      {{{V2(nan, nan), V2(nan, 0), V2(0, 2)}, {V2(0, 0), V2(0, 0), V2(0, 0)}},
       TriangleError::NonFinite,
       TriangleError::RepeatedVertex},
  };
  const auto valid = workloads::make_valid_pairs(workloads::InputClass::General, 40, 9);
  for (std::size_t at : {0, 3, 7, 12, 37}) {  // lane 0, 3, 7, 4 of a block; 37: the tail
    SCOPED_TRACE(::testing::Message() << "bad rows from " << at);
    std::vector<RawPair> rows(valid.begin(), valid.end());
    rows.resize(at);
    std::vector<std::size_t> bad_rows;
    for (const Bad& b : bad) {
      bad_rows.push_back(rows.size());
      rows.push_back(b.pair);
    }
    rows.insert(rows.end(), valid.begin() + static_cast<long>(at), valid.end());
    const Columns<T> mixed = columns<T>(rows);
    const Columns<T> clean = columns<T>(valid);
    Outputs<T> got(mixed.size()), want(clean.size());
    ASSERT_EQ(run_batch(kernel, mixed, mixed.size(), Level::Depth, got), BatchError::None);
    ASSERT_EQ(run_batch(kernel, clean, clean.size(), Level::Depth, want), BatchError::None);
    for (std::size_t i = 0; i < bad.size(); ++i) {
      const std::size_t k = bad_rows[i];
      const bool expect_invalid =
          bad[i].a != TriangleError::None || bad[i].b != TriangleError::None;
      const BatchRowError e = batch_row_error(mixed.batch(), k);
      EXPECT_EQ(e.a, bad[i].a) << "case " << i;
      EXPECT_EQ(e.b, bad[i].b) << "case " << i;
      if (!expect_invalid) continue;
      EXPECT_EQ(got.status[k], Status::Invalid) << "case " << i;
      EXPECT_EQ(got.separation[k], T(0));
      EXPECT_EQ(got.normal_x[k], T(0));
      EXPECT_EQ(got.normal_y[k], T(0));
    }
    for (std::size_t k = 0, j = 0; k < mixed.size(); ++k) {
      if (std::find(bad_rows.begin(), bad_rows.end(), k) != bad_rows.end()) continue;
      EXPECT_EQ(got.status[k], want.status[j]);
      EXPECT_EQ(got.separation[k], want.separation[j]);
      EXPECT_EQ(got.normal_x[k], want.normal_x[j]);
      EXPECT_EQ(got.normal_y[k], want.normal_y[j]);
      ++j;
    }
  }
}
TYPED_TEST(Batch, InvalidRowsAreMarkedAndTheOtherRowsUnaffected) {
  invalid_rows_are_marked_and_the_other_rows_unaffected<typename TypeParam::T>(TypeParam::kernel);
}

// Squared edge lengths beyond the range of the vector lanes' reciprocal square root estimate (below
// the smallest normal float, or above the largest float in double) send their rows to the portable
// code: every kernel then gives the same bits for them, and sat's answer. Such rows sit at several
// lanes and in the tail, among ordinary ones.
template <class T>
void rows_beyond_the_fast_range_are_redone_portably(BatchKernel kernel) {
  const bool is_float = std::is_same_v<T, float>;
  // Double: squared lengths below and beyond float's range, where the estimate (taken in
  // float) cannot go. Float: min_size (9.1e-13) leaves no square out of range, so no row is redone.
  const double tiny = is_float ? 1e-11 : 1e-25;
  const double huge = is_float ? 1e17 : 1e25;
  std::vector<RawPair> rows = workloads::make_valid_pairs(workloads::InputClass::General, 21, 4);
  const auto extra = workloads::make_valid_pairs(workloads::InputClass::General, 6, 8);
  std::vector<bool> beyond(rows.size(), false);
  for (std::size_t i = 0; i < extra.size(); ++i) {  // rows 1, 6, 11, 16, 21 and the last (tail)
    RawPair p = extra[i];
    const double unit = i % 2 == 0 ? tiny : huge;
    for (V2& v : p.a) v *= unit;
    for (V2& v : p.b) v *= unit;
    const std::size_t at = i + 1 == extra.size() ? rows.size() : 5 * i + 1;
    rows.insert(rows.begin() + static_cast<long>(at), p);
    beyond.insert(beyond.begin() + static_cast<long>(at), !is_float);
  }
  const Columns<T> cols = columns<T>(rows);
  Outputs<T> got(cols.size()), portable(cols.size());
  ASSERT_EQ(run_batch(kernel, cols, cols.size(), Level::Depth, got), BatchError::None);
  ASSERT_EQ(penetrate_batch(cols.batch(), Level::Depth, portable.out(), BatchKernel::Portable),
            BatchError::None);
  int checked = 0;
  for (std::size_t k = 0; k < cols.size(); ++k) {
    SCOPED_TRACE(::testing::Message() << "row " << k);
    if (beyond[k]) {
      EXPECT_EQ(got.status[k], portable.status[k]);
      EXPECT_EQ(got.separation[k], portable.separation[k]);
      EXPECT_EQ(got.normal_x[k], portable.normal_x[k]);
      EXPECT_EQ(got.normal_y[k], portable.normal_y[k]);
    }
    const auto t = workloads::build<T>(cols.row(k));
    ASSERT_TRUE(t.a.ok() && t.b.ok());
    const Result<T> want = sat(t.a.triangle, t.b.triangle, {Level::Depth});
    EXPECT_EQ(got.status[k], want.status);
    // Subnormal squares keep fewer bits (in sat too): a looser bound than for normal inputs.
    EXPECT_NEAR(double(got.separation[k]), double(want.separation),
                1e-3 * workloads::pair_size(cols.row(k)));
    ++checked;
  }
  EXPECT_EQ(checked, 27);
}
TYPED_TEST(Batch, RowsBeyondTheFastRangeAreRedonePortably) {
  rows_beyond_the_fast_range_are_redone_portably<typename TypeParam::T>(TypeParam::kernel);
}

// Worked cases (sat_test's), in every winding of both triangles and at any lane.
template <class T>
void worked_cases_in_every_winding(BatchKernel kernel) {
  struct Case {
    RawPair pair;
    Status status;
    double separation;
    V2 normal;
  };
  const std::vector<Case> cases = {
      // A's bottom edge (y = 0) pierced 0.5 deep by B's top vertex: B moves down.
      {{{V2(0, 0), V2(4, 0), V2(2, 4)}, {V2(2, 0.5), V2(1, -2), V2(3, -2)}},
       Status::Penetrating,
       -0.5,
       V2(0, -1)},
      // Apart by 1 along x, edge to edge.
      {{{V2(0, 0), V2(1, 0), V2(0, 1)}, {V2(2, 0), V2(3, 0), V2(2, 1)}},
       Status::Separated,
       1,
       V2(1, 0)},
      // B's lowest vertex 0.25 above A's top edge: distance along the edge normal.
      {{{V2(0, 0), V2(2, 0), V2(1, -1)}, {V2(1, 0.25), V2(2, 2), V2(0, 2)}},
       Status::Separated,
       0.25,
       V2(0, 1)},
      // Vertex to vertex at distance sqrt(2), along the diagonal.
      {{{V2(0, 0), V2(-1, 0), V2(0, -1)}, {V2(1, 1), V2(2, 1), V2(1, 2)}},
       Status::Separated,
       std::sqrt(2.0),
       V2(std::sqrt(0.5), std::sqrt(0.5))},
      // B resting on A's top edge: touching, separation 0.
      {{{V2(-5, 0), V2(0, -5), V2(5, 0)}, {V2(-1, 0), V2(1, 0), V2(0, 1)}},
       Status::Touching,
       0,
       V2(0, 1)},
  };
  std::vector<RawPair> rows;
  std::vector<std::size_t> which;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    for (int w = 0; w < 4; ++w) {  // both windings of A and of B
      RawPair p = cases[i].pair;
      if (w & 1) std::swap(p.a[1], p.a[2]);
      if (w & 2) std::swap(p.b[1], p.b[2]);
      rows.push_back(p);
      which.push_back(i);
    }
  }
  const Columns<T> cols = columns<T>(rows);
  Outputs<T> out(cols.size());
  ASSERT_EQ(run_batch(kernel, cols, cols.size(), Level::Depth, out), BatchError::None);
  const double tol = 100 * double(std::numeric_limits<T>::epsilon());
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const Case& c = cases[which[k]];
    SCOPED_TRACE(::testing::Message() << "case " << which[k] << " winding " << k % 4);
    EXPECT_EQ(out.status[k], c.status);
    EXPECT_NEAR(out.separation[k], c.separation, tol);
    EXPECT_NEAR(out.normal_x[k], c.normal.x(), tol);
    EXPECT_NEAR(out.normal_y[k], c.normal.y(), tol);
  }
}
TYPED_TEST(Batch, WorkedCasesInEveryWinding) {
  worked_cases_in_every_winding<typename TypeParam::T>(TypeParam::kernel);
}

// Found by fuzz_batch (float). Two slivers end to end, 24 apart: the widest gap along an edge
// normal (0.094) is inside float's touching band (0.14), yet the pair is apart by 24. The
// distance decides, at both levels, as it does for sat (DegenerateInFrame in degenerate_test).
template <class T>
void slivers_end_to_end_are_apart_by_their_distance_not_by_their_widest_edge_gap(
    BatchKernel kernel) {
  const RawPair pair{{V2(0, 0), V2(0, 4), V2(4, -1020)}, {V2(-4, 36908), V2(4, 1032), V2(0, 28)}};
  const Columns<T> cols = columns<T>(std::vector<RawPair>(11, pair));  // a block and a tail
  for (Level level : {Level::Overlap, Level::Depth}) {
    Outputs<T> out(cols.size());
    ASSERT_EQ(run_batch(kernel, cols, cols.size(), level, out), BatchError::None);
    for (std::size_t k = 0; k < cols.size(); ++k) {
      EXPECT_EQ(out.status[k], Status::Separated) << "row " << k;
      if (level == Level::Depth) {
        EXPECT_NEAR(out.separation[k], 24.0, separation_tolerance<T>() * 36908) << "row " << k;
      }
    }
  }
}
TYPED_TEST(Batch, SliversEndToEndAreApartByTheirDistanceNotByTheirWidestEdgeGap) {
  slivers_end_to_end_are_apart_by_their_distance_not_by_their_widest_edge_gap<
      typename TypeParam::T>(TypeParam::kernel);
}

// Contact and Manifold are refused, as are missing arrays; nothing is written then.
template <class T>
void rejects_unsupported_levels_and_missing_arrays_writing_nothing(BatchKernel kernel) {
  const Columns<T> cols =
      columns<T>(workloads::make_valid_pairs(workloads::InputClass::General, 10, 1));
  Outputs<T> out(cols.size());
  EXPECT_EQ(run_batch(kernel, cols, cols.size(), Level::Contact, out),
            BatchError::UnsupportedLevel);
  EXPECT_EQ(run_batch(kernel, cols, cols.size(), Level::Manifold, out),
            BatchError::UnsupportedLevel);
  PairBatch<T> missing = cols.batch();
  missing.by2 = nullptr;
  EXPECT_EQ(penetrate_batch(missing, Level::Overlap, out.out(), kernel), BatchError::NullArray);
  BatchOutput<T> no_normal = out.out();
  no_normal.normal_y = nullptr;
  EXPECT_EQ(penetrate_batch(cols.batch(), Level::Depth, no_normal, kernel), BatchError::NullArray);
  EXPECT_EQ(penetrate_batch(cols.batch(), Level::Depth, BatchOutput<T>{}, kernel),
            BatchError::NullArray);
  for (std::size_t k = 0; k < out.status.size(); ++k) {
    EXPECT_EQ(static_cast<std::uint8_t>(out.status[k]), 0xAB);
    EXPECT_EQ(out.separation[k], Outputs<T>::sentinel);
  }
  EXPECT_NE(std::string(describe(BatchError::UnsupportedLevel)).find("Contact"), std::string::npos);
}
TYPED_TEST(Batch, RejectsUnsupportedLevelsAndMissingArraysWritingNothing) {
  rejects_unsupported_levels_and_missing_arrays_writing_nothing<typename TypeParam::T>(
      TypeParam::kernel);
}

}  // namespace
}  // namespace dyop

namespace dyop {
namespace {

// Two slivers along one diagonal, the small one 3e139 beyond the tip of one 1.4e149 long (found by
// fuzz_batch and fuzz_sat; fuzz/corpus/methods/regress_sliver_tip_*_double): the gap along the
// separating edge normal is far below the coordinates' rounding and comes out as a least overlap
// of 0 or a little more, inside the touching band, so the distance must decide. `sat`, `dyop` and
// the batch kernel all call the pair apart at its distance, with the tip on the diagonal (overlap
// rounded to 0) and moved off it by one part in 3e13 (a small positive overlap).
TEST(SliversEndToEnd, ALeastOverlapInsideTheBandIsDecidedByTheDistanceInEveryExactMethod) {
  for (const double tip_x : {-2.1482046286569577e+139, -2.1482046286570254e+139}) {
    const double c[12] = {-6.2531702115077586e-269,
                          1.3403042625207296e-84,
                          8.1968741050497943e+107,
                          8.1968741124263195e+107,
                          8.196874112425652e+107,
                          8.1968741124263195e+107,
                          -9.8683099107386407e+148,
                          -9.8683099208633679e+148,
                          -9.8683099208633679e+148,
                          -9.8683099208633679e+148,
                          tip_x,
                          -2.1482046286569577e+139};
    const auto a = Triangle<double>::make({c[0], c[1]}, {c[2], c[3]}, {c[4], c[5]});
    const auto b = Triangle<double>::make({c[6], c[7]}, {c[8], c[9]}, {c[10], c[11]});
    ASSERT_TRUE(a.ok() && b.ok());
    const double distance = std::hypot(c[10], c[11]);  // to the tip, within 1e-30 relative
    for (const Result<double>& r :
         {sat(a.triangle, b.triangle), dyop::dyop(a.triangle, b.triangle)}) {
      EXPECT_EQ(r.status, Status::Separated) << tip_x;
      EXPECT_NEAR(r.separation, distance, 1e-9 * distance) << tip_x;
    }
    workloads::BatchArrays<double> arrays(1, [&](std::size_t, int side, int i) {
      return Vec2<double>(c[6 * side + 2 * i], c[6 * side + 2 * i + 1]);
    });
    ASSERT_EQ(penetrate_batch(arrays.pairs(), Level::Depth, arrays.out()), BatchError::None);
    EXPECT_EQ(arrays.status[0], Status::Separated) << tip_x;
    EXPECT_NEAR(arrays.separation[0], distance, 1e-9 * distance) << tip_x;
  }
}

}  // namespace
}  // namespace dyop
