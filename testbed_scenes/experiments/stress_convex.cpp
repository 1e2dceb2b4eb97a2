#include "experiments/stress_convex.hpp"

#include <algorithm>
#include <cmath>
#include <ostream>
#include <type_traits>

#include "dyop/convex_pair.hpp"
#include "exact_reference/exact_reference.hpp"
#include "experiments/error_figures.hpp"
#include "workloads/finite_fields.hpp"

namespace dyop::experiments {
namespace {

using workloads::ConvexClass;
using workloads::Precision;
using workloads::RawCircle;
using workloads::RawCirclePair;
using workloads::RawPolygon;
using workloads::RawPolygonPair;

// `p` with its vertices in the other order (the same polygon, the other winding).
RawPolygon rewound(const RawPolygon& p) {
  RawPolygon out = p;
  std::reverse(out.v.begin(), out.v.begin() + p.count);
  return out;
}

RawPolygonPair rewound(const RawPolygonPair& p) { return {rewound(p.a), rewound(p.b)}; }
RawCirclePair rewound(const RawCirclePair& p) { return {rewound(p.a), p.b}; }

template <class T, class Pair>
Result<T> solve(const Pair& p, const ConvexQuery<T>& q) {
  return workloads::collide_raw(p, q);
}

template <class T, class Pair>
ConvexStressRecord measure(ConvexFamily family, ConvexClass c, const std::vector<Pair>& pairs) {
  const Precision precision = std::is_same_v<T, float> ? Precision::Float : Precision::Double;
  ConvexStressRecord rec;
  rec.family = family;
  rec.cls = c;
  rec.precision = precision;
  rec.pairs = static_cast<int>(pairs.size());
  const double bound = workloads::exact_bound(precision);
  std::vector<double> errors;
  for (const Pair& p : pairs) {
    ConvexQuery<T> q;
    q.level = Level::Manifold;
    q.margin = T(0.01) * T(workloads::pair_size(p));
    const Result<T> r = solve<T>(p, q);
    const bool all_finite =
        workloads::finite_at(r, Level::Manifold) &&
        workloads::finite_at(solve<T>(p, ConvexQuery<T>{Level::Contact}), Level::Contact);
    rec.nonfinite += !all_finite;
    if (!all_finite) continue;
    const double size = workloads::pair_size(p);
    const double exact = workloads::exact_separation(p).separation;
    errors.push_back(std::abs(double(r.separation) - exact) / size);
    const double band = 4 * touching_tolerance<T>() * size;
    if (std::abs(exact) > band &&
        r.status != (exact < 0 ? Status::Penetrating : Status::Separated)) {
      ++rec.misclassified;
    }
    const Result<T> w = solve<T>(rewound(p), q);
    rec.winding += !(std::abs(double(w.separation) - double(r.separation)) <= bound * size);
  }
  const ErrorFigures figures = error_figures(errors);
  rec.err_max = figures.max;
  rec.err_p99 = figures.p99;
  return rec;
}

template <class T>
void run_precision(const StressOptions& o, std::vector<ConvexStressRecord>& records,
                   std::ostream& progress) {
  const Precision precision = std::is_same_v<T, float> ? Precision::Float : Precision::Double;
  for (ConvexClass c : workloads::convex_classes) {
    records.push_back(measure<T>(ConvexFamily::Polygons, c,
                                 workloads::make_polygon_pairs(c, o.pairs, o.seed, precision)));
    records.push_back(measure<T>(ConvexFamily::PolygonCircle, c,
                                 workloads::make_circle_pairs(c, o.pairs, o.seed, precision)));
    records.push_back(measure<T>(ConvexFamily::SegmentPolygon, c,
                                 workloads::make_segment_pairs(c, o.pairs, o.seed, precision)));
    records.push_back(
        measure<T>(ConvexFamily::SegmentCircle, c,
                   workloads::make_segment_circle_pairs(c, o.pairs, o.seed, precision)));
    progress << "dyop stress: convex pairs, " << workloads::name(c) << ", "
             << workloads::name(precision) << " done\n";
  }
}

}  // namespace

const char* name(ConvexFamily f) {
  switch (f) {
    case ConvexFamily::Polygons:
      return "polygon-polygon";
    case ConvexFamily::PolygonCircle:
      return "polygon-circle";
    case ConvexFamily::SegmentPolygon:
      return "segment-polygon";
    case ConvexFamily::SegmentCircle:
      return "segment-circle";
  }
  return "unknown";
}

std::vector<ConvexStressRecord> run_convex_stress(const StressOptions& options,
                                                  std::ostream& progress) {
  std::vector<ConvexStressRecord> records;
  if (options.run_double) run_precision<double>(options, records, progress);
  if (options.run_float) run_precision<float>(options, records, progress);
  return records;
}

std::vector<std::string> broken_convex_promises(const std::vector<ConvexStressRecord>& records) {
  std::vector<std::string> out;
  for (const ConvexStressRecord& r : records) {
    const std::string where = std::string(name(r.family)) + " on " + workloads::name(r.cls) +
                              " in " + workloads::name(r.precision);
    if (r.err_max > workloads::exact_bound(r.precision)) {
      out.push_back(where + ": error " + std::to_string(r.err_max) + " beyond the exact bound");
    }
    if (r.misclassified > 0) out.push_back(where + ": misclassified pairs");
    if (r.nonfinite > 0) out.push_back(where + ": NaN or inf");
    if (r.winding > 0) out.push_back(where + ": the other winding moved the answer");
  }
  return out;
}

}  // namespace dyop::experiments
