// Near-degenerate triangles: every method either answers them (the exact ones exactly) or the
// validation rejects them through `degenerate_tolerance` with an error that names the problem.
// Never a NaN, never a silently wrong answer, and a rejected row never takes another row with it
// (batch kernel, CSV).
//
// The sweep: triangles of flatness (twice the area over the longest edge squared) from 1 down to
// 1e-20, in both precisions, turned, moved from the origin and with the apex beyond either end of
// the base, each against partners that cross it, rest near it, contain it, lie apart or are thin
// themselves.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "dyop/batch.hpp"
#include "dyop/method.hpp"
#include "exact_reference/exact_reference.hpp"
#include "program/pair_csv.hpp"
#include "program/pairs_command.hpp"
#include "workloads/raw_pair.hpp"
#include "support/result_checks.hpp"
#include "support/scalars.hpp"

namespace dyop::workloads {
namespace {

using test_support::all_finite;

using V = Vec2<double>;
using Tri = std::array<V, 3>;

// The bound of "exact", relative to the pair's size.
template <class T>
constexpr double exact_bound() {
  return std::is_same_v<T, float> ? 1e-5 : 1e-12;
}

template <class T>
Precision precision_of() {
  return std::is_same_v<T, float> ? Precision::Float : Precision::Double;
}

// Twice the area over the longest edge squared, from T's coordinates, in long double: the
// quantity `Triangle<T>::make` compares with the tolerance, without T's rounding.
double flatness(const Tri& t) {
  using L = long double;
  const L ux = L(t[1].x()) - t[0].x(), uy = L(t[1].y()) - t[0].y();
  const L wx = L(t[2].x()) - t[0].x(), wy = L(t[2].y()) - t[0].y();
  const L vx = L(t[2].x()) - t[1].x(), vy = L(t[2].y()) - t[1].y();
  const L longest = std::max({ux * ux + uy * uy, wx * wx + wy * wy, vx * vx + vy * vy});
  return static_cast<double>(std::abs(ux * wy - uy * wx) / longest);
}

// A triangle with a base of length 1 from `origin` at `angle`, the apex's foot at `foot` along the
// base (outside [0, 1]: beyond an end) and the height that gives `flat`.
Tri thin(const V& origin, double angle, double foot, double flat) {
  const V d(std::cos(angle), std::sin(angle));
  const V n(-d.y(), d.x());
  const double longest = std::max({1.0, std::abs(foot), std::abs(1 - foot)});
  return {origin, origin + d, origin + foot * d + flat * longest * longest * n};
}

// Partners of a thin triangle along `d` from `o` (normal `n`): crossing it, resting 1e-3 above
// it, containing it, far apart, and a sliver (flatness 2e-4, valid in float) crossing it at 1e-3
// rad.
std::vector<Tri> partners(const V& o, double angle) {
  const V d(std::cos(angle), std::sin(angle));
  const V n(-d.y(), d.x());
  const V mid = o + 0.5 * d;
  const V d2(std::cos(angle + 1e-3), std::sin(angle + 1e-3));
  return {
      {mid - 0.3 * n, mid + 0.4 * d + 0.3 * n, mid - 0.4 * d + 0.2 * n},
      {mid + 1e-3 * n, mid + 0.4 * d + 0.5 * n, mid - 0.4 * d + 0.5 * n},
      {o - 1.0 * d - 1.0 * n, o + 2.0 * d - 1.0 * n, mid + 2.0 * n},
      {o + 3.0 * n, o + 3.5 * n + d, o + 4.0 * n},
      {mid - 0.5 * d2 - 1e-4 * n, mid + 0.5 * d2 - 1e-4 * n, mid + 1e-4 * n},
  };
}

Tri rounded_tri(Precision p, const Tri& t) { return rounded_to(p, RawPair{t, t}).a; }

template <class T>
class Degenerate : public ::testing::Test {};
using test_support::ScalarNames;
using test_support::Scalars;
TYPED_TEST_SUITE(Degenerate, Scalars, ScalarNames);

// What one sweep saw, for the figures and for the checks that need the whole sweep.
struct Sweep {
  int triangles = 0;
  int rejected = 0;
  int pairs = 0;
  double thinnest_accepted = 1;
  double worst_exact_error = 0;
};

// Runs every method on (thin, partner) and (partner, thin) and checks them against the exact
// reference; the batch kernel gets the same rows.
template <class T>
void check_pairs(const std::vector<RawPair>& rows, Sweep& sweep) {
  const double bound = exact_bound<T>();
  for (const RawPair& p : rows) {
    const auto t = build<T>(p);
    ASSERT_TRUE(t.a.ok() && t.b.ok());
    const ExactAnswer exact = exact_separation(p);
    const double size = pair_size(p);
    const double band = 4 * touching_tolerance<T>() * size;
    ++sweep.pairs;
    for (Method m : pair_methods) {
      Query<T> q{Level::Manifold};
      q.margin = T(0.01);
      const Result<T> r = penetrate(m, t.a.triangle, t.b.triangle, q);
      if (r.status == Status::Invalid) {
        EXPECT_EQ(m, Method::DyopPaper) << name(m) << " refused a valid pair";
        EXPECT_NE(r.reason, InvalidReason::None);
        continue;
      }
      ASSERT_TRUE(all_finite(r)) << name(m) << " on " << p.a[2].transpose() << " / "
                                 << p.b[0].transpose();
      if (m != Method::Sat && m != Method::Dyop) continue;
      const double error = std::abs(double(r.separation) - exact.separation) / size;
      sweep.worst_exact_error = std::max(sweep.worst_exact_error, error);
      EXPECT_LE(error, bound) << name(m);
      if (std::abs(exact.separation) > band) {
        EXPECT_EQ(r.status, exact.separation < 0 ? Status::Penetrating : Status::Separated)
            << name(m);
      }
    }
  }
}

// Every row of `rows` (valid or not) through the batch kernel(s): a row is Invalid exactly when
// `Triangle<T>::make` rejects a triangle of it, with the same error, and every valid row is sat's
// answer to rounding.
template <class T>
void check_batch(const std::vector<RawPair>& rows) {
  const std::size_t n = rows.size();
  std::vector<T> c[12];
  for (auto& v : c) v.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    for (int i = 0; i < 3; ++i) {
      c[2 * i][k] = T(rows[k].a[i].x());
      c[2 * i + 1][k] = T(rows[k].a[i].y());
      c[6 + 2 * i][k] = T(rows[k].b[i].x());
      c[7 + 2 * i][k] = T(rows[k].b[i].y());
    }
  }
  const PairBatch<T> batch{c[0].data(),
                           c[1].data(),
                           c[2].data(),
                           c[3].data(),
                           c[4].data(),
                           c[5].data(),
                           c[6].data(),
                           c[7].data(),
                           c[8].data(),
                           c[9].data(),
                           c[10].data(),
                           c[11].data(),
                           n};
  for (BatchKernel kernel : batch_kernels) {
    if (!batch_kernel_available(kernel)) continue;
    std::vector<Status> status(n);
    std::vector<T> sep(n), nx(n), ny(n);
    ASSERT_EQ(
        penetrate_batch(batch, Level::Depth,
                        BatchOutput<T>{status.data(), sep.data(), nx.data(), ny.data()}, kernel),
        BatchError::None);
    for (std::size_t k = 0; k < n; ++k) {
      const auto t = build<T>(rows[k]);
      const BatchRowError e = batch_row_error(batch, k);
      EXPECT_EQ(e.a, t.a.error) << "row " << k;
      EXPECT_EQ(e.b, t.b.error) << "row " << k;
      if (!t.a.ok() || !t.b.ok()) {
        EXPECT_EQ(status[k], Status::Invalid) << "row " << k;
        continue;
      }
      ASSERT_NE(status[k], Status::Invalid) << "valid row " << k << " lost";
      const Result<T> s = sat(t.a.triangle, t.b.triangle);
      EXPECT_NEAR(double(sep[k]), double(s.separation), exact_bound<T>() * pair_size(rows[k]));
    }
  }
}

TYPED_TEST(Degenerate, FlatnessSweepIsRejectedAsDegenerateOrAnsweredExactly) {
  using T = TypeParam;
  const double tolerance = degenerate_tolerance<T>();
  const Precision precision = precision_of<T>();
  const double far = std::is_same_v<T, float> ? 10.0 : 1e3;
  Sweep sweep;
  std::vector<RawPair> batch_rows;
  for (double angle : {0.0, 0.3, 1.5707963267948966, 2.5}) {
    for (const V& origin : {V(0, 0), V(far, -far / 3)}) {
      for (double foot : {0.5, -0.5, 1.5}) {
        for (int tenth = 0; tenth <= 80; ++tenth) {  // flatness 1 down to 1e-20, 4 per decade
          const double flat = std::pow(10.0, -0.25 * tenth);
          const Tri a = rounded_tri(precision, thin(origin, angle, foot, flat));
          const auto t = Triangle<T>::make(a[0].cast<T>(), a[1].cast<T>(), a[2].cast<T>());
          ++sweep.triangles;
          const double f = flatness(a);
          std::vector<RawPair> rows;
          for (const Tri& b : partners(origin, angle)) {
            const Tri partner = rounded_tri(precision, b);
            rows.push_back({a, partner});
            rows.push_back({partner, a});
          }
          batch_rows.insert(batch_rows.end(), rows.begin(), rows.end());
          if (!t.ok()) {
            ++sweep.rejected;
            // Rounding may have put two vertices on one point; otherwise it is the flatness.
            EXPECT_TRUE(t.error == TriangleError::Degenerate ||
                        t.error == TriangleError::RepeatedVertex)
                << describe(t.error);
            EXPECT_NE(std::string(describe(t.error))
                          .find(t.error == TriangleError::Degenerate ? "degenerate" : "repeated"),
                      std::string::npos);
            EXPECT_LT(f, 2 * tolerance) << "rejected a triangle clearly flatter than needed";
            continue;
          }
          EXPECT_GT(f, 0.5 * tolerance) << "accepted a triangle clearly below the tolerance";
          sweep.thinnest_accepted = std::min(sweep.thinnest_accepted, f);
          check_pairs<T>(rows, sweep);
        }
      }
    }
  }
  check_batch<T>(batch_rows);
  // The sweep crosses the tolerance: both verdicts occur, and the thinnest accepted triangle is
  // within a factor of the tolerance of it.
  EXPECT_GT(sweep.rejected, 0);
  EXPECT_LT(sweep.rejected, sweep.triangles);
  EXPECT_LT(sweep.thinnest_accepted, 4 * tolerance);
  std::ostringstream figures;
  figures << sweep.triangles << " triangles, " << sweep.rejected << " rejected, thinnest accepted "
          << sweep.thinnest_accepted << " (tolerance " << tolerance << "), " << sweep.pairs
          << " pairs, worst sat/dyop error / size " << sweep.worst_exact_error;
  ::testing::Test::RecordProperty("figures", figures.str());
}

// Tiny triangles: below `min_size` squared lengths underflow (an edge's normal would be NaN), so
// they are rejected as too small; from it on every method answers, the exact ones exactly.
TYPED_TEST(Degenerate, TinyTrianglesAreRejectedAsTooSmallOrAnsweredExactly) {
  using T = TypeParam;
  const Precision precision = precision_of<T>();
  int rejected = 0;
  int answered = 0;
  Sweep sweep;
  for (int step = -24; step <= 24; ++step) {  // sizes from 1/16 to 16 times min_size
    const double scale = double(min_size<T>()) * std::pow(2.0, step / 6.0);
    for (double flat : {0.5, 1e-2, 40 * double(degenerate_tolerance<T>())}) {
      for (double foot : {0.5, 1.5}) {
        const Tri a = rounded_tri(precision, thin(V(0, 0), 0.4, foot, flat));
        Tri small;
        for (int i = 0; i < 3; ++i) small[i] = scale * a[i];
        small = rounded_tri(precision, small);
        const auto t =
            Triangle<T>::make(small[0].cast<T>(), small[1].cast<T>(), small[2].cast<T>());
        const double longest = std::max({(small[1] - small[0]).norm(), (small[2] - small[1]).norm(),
                                         (small[0] - small[2]).norm()});
        if (!t.ok()) {
          ++rejected;
          EXPECT_LT(longest, 1.01 * double(min_size<T>())) << describe(t.error);
          EXPECT_TRUE(t.error == TriangleError::TooSmall || t.error == TriangleError::Degenerate ||
                      t.error == TriangleError::RepeatedVertex)
              << describe(t.error);
          continue;
        }
        ++answered;
        EXPECT_GE(longest, 0.99 * double(min_size<T>()));
        std::vector<RawPair> rows;
        for (const Tri& b : partners(V(0, 0), 0.4)) {
          Tri partner;
          for (int i = 0; i < 3; ++i) partner[i] = scale * b[i];
          partner = rounded_tri(precision, partner);
          if (!build<T>(RawPair{partner, partner}).a.ok()) continue;
          rows.push_back({small, partner});
          rows.push_back({partner, small});
        }
        check_pairs<T>(rows, sweep);
      }
    }
  }
  EXPECT_GT(rejected, 0);
  EXPECT_GT(answered, 0);
  EXPECT_NE(std::string(describe(TriangleError::TooSmall)).find("too small"), std::string::npos);
}

// Found by fuzz_sat and fuzz_dyop. A triangle smaller than the rounding of the pair's frame
// (eps × its distance from A's first vertex: here 1e-84 at 1e6) collapses there; its vertex–edge
// distances must still be to its segments, not to their lines.
TEST(DegenerateInFrame, ATriangleSmallerThanTheFramesRoundingKeepsItsDistance) {
  const RawPair p{{V(1000000, 1.9115286622823839e-307), V(1000002.2500000105, 1000000),
                   V(1000000.0000610352, 1.3207012695185919e-84)},
                  {V(1.3200670146428902e-84, -1.240440735873755e-259),
                   V(1.3200670146428902e-84, 1.3210723969845832e-84),
                   V(1.3210723969845818e-84, 3.2114266979681025e-322)}};
  const auto t = build<double>(p);
  ASSERT_TRUE(t.a.ok() && t.b.ok());
  const ExactAnswer exact = exact_separation(p);
  for (Method m : {Method::Sat, Method::Dyop, Method::Epa, Method::LinCanny}) {
    const Result<double> r = penetrate(m, t.a.triangle, t.b.triangle);
    EXPECT_EQ(r.status, Status::Separated) << name(m);
    EXPECT_NEAR(r.separation, exact.separation, 1e-12 * pair_size(p)) << name(m);
  }
}

// Found by fuzz_sat (float). Two slivers end to end, 24 apart: every edge normal is nearly
// perpendicular to the gap, so the widest gap along one (0.094) is inside float's touching band
// (0.14). Not touching: the distance decides.
TEST(DegenerateInFrame, SliversEndToEndAreApartByTheirDistanceNotByTheirWidestEdgeGap) {
  const RawPair p{{V(0, 0), V(0, 4), V(4, -1020)}, {V(-4, 36908), V(4, 1032), V(0, 28)}};
  const auto t = build<float>(p);
  ASSERT_TRUE(t.a.ok() && t.b.ok());
  for (Method m : {Method::Sat, Method::Dyop, Method::Epa, Method::LinCanny}) {
    for (Level level : {Level::Overlap, Level::Depth}) {
      const Result<float> r = penetrate(m, t.a.triangle, t.b.triangle, Query<float>{level});
      EXPECT_EQ(r.status, Status::Separated) << name(m);
      if (level == Level::Depth) {
        EXPECT_NEAR(r.separation, 24.0, 1e-5 * pair_size(p)) << name(m);
      }
    }
  }
}

// Rejected input names what is wrong, in either precision.
TYPED_TEST(Degenerate, EveryRejectionNamesItsProblem) {
  using T = TypeParam;
  using W = Vec2<T>;
  const T nan = std::numeric_limits<T>::quiet_NaN();
  const T inf = std::numeric_limits<T>::infinity();
  const T huge = T(2) * max_coordinate<T>();
  const struct {
    W p0, p1, p2;
    TriangleError error;
    const char* says;
  } cases[] = {
      {W(nan, 0), W(1, 0), W(0, 1), TriangleError::NonFinite, "non-finite"},
      {W(0, 0), W(1, -inf), W(0, 1), TriangleError::NonFinite, "non-finite"},
      {W(0, 0), W(huge, 0), W(0, 1), TriangleError::TooLarge, "too large"},
      {W(0, 1), W(1, 0), W(0, 1), TriangleError::RepeatedVertex, "repeated"},
      {W(0, 0), W(1, 1), W(3, 3), TriangleError::Degenerate, "degenerate"},
      // Collinear with the apex past the end of the base: the longest edge is not the base.
      {W(0, 0), W(1, 0), W(5, 0), TriangleError::Degenerate, "degenerate"},
      {W(0, 0), W(1, 0), W(T(0.5), T(0.1) * degenerate_tolerance<T>()), TriangleError::Degenerate,
       "degenerate"},
  };
  for (const auto& c : cases) {
    const TriangleOrError<T> t = Triangle<T>::make(c.p0, c.p1, c.p2);
    EXPECT_EQ(t.error, c.error) << c.says;
    EXPECT_NE(std::string(describe(t.error)).find(c.says), std::string::npos) << describe(t.error);
  }
}

// The CSV path: lines that are degenerate in float only, degenerate in both, or out of float's
// range are error lines naming the triangle and the problem; every other line is answered by every
// backend, and no line is lost.
TEST(DegenerateCsv, RejectedLinesNameTheProblemAndEveryOtherLineIsAnswered) {
  const std::string good = "0,0,1,0,0,1,0.2,0.2,1.2,0.2,0.2,1.2";
  const std::string lines[] = {
      good,
      "0,0,1,0,0.5,1e-7,0.2,-0.5,0.8,-0.5,0.5,0.5",  // flatness 1e-7: valid double, float no
      good,
      "0,0,1,0,0.5,1e-16,0.2,-0.5,0.8,-0.5,0.5,0.5",  // flatness 1e-16: degenerate in both
      "0,0,1,0,0,1,1e300,0,0,1e300,0.2,0.2",          // beyond float, and too large for double
      "0,0,1,0,0,1,0.5,0.5,0.5,0.5,2,2",              // repeated vertex in PQR
      good,
  };
  std::string text = "# near-degenerate lines among good ones\n";
  for (const std::string& l : lines) text += l + "\n";
  for (bool use_float : {false, true}) {
    cli::PairsOptions options;
    options.methods = cli::pairs_methods();
    options.use_float = use_float;
    std::istringstream input(text);
    std::ostringstream output;
    const cli::PairsSummary s = cli::run_pairs(options, input, output);
    const int backends = static_cast<int>(options.methods.size());
    EXPECT_EQ(s.rows, 7 * backends);
    std::istringstream out(output.str());
    std::string line;
    std::getline(out, line);  // header
    int ok = 0;
    int errors = 0;
    while (std::getline(out, line)) {
      const bool error = line.find(",error,") != std::string::npos;
      if (!error) {
        ++ok;
        EXPECT_EQ(line.find("nan"), std::string::npos) << line;
        EXPECT_EQ(line.find("inf"), std::string::npos) << line;
        continue;
      }
      ++errors;
      const bool named = line.find("degenerate") != std::string::npos ||
                         line.find("out of range") != std::string::npos ||
                         line.find("too large") != std::string::npos ||
                         line.find("repeated") != std::string::npos ||
                         line.find("vertical") != std::string::npos ||  // dyop-paper, by design
                         line.find("origin") != std::string::npos;
      EXPECT_TRUE(named) << line;
    }
    EXPECT_EQ(ok + errors, 7 * backends);
    // Good lines (3) answered by every backend but dyop-paper, which may refuse by design.
    EXPECT_GE(ok, 3 * (backends - 1)) << output.str();
  }
}

}  // namespace
}  // namespace dyop::workloads
