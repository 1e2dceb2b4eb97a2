#include "experiments/bench.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <ostream>

#include "dyop/sat.hpp"
#include "exact_reference/exact_reference.hpp"
#include "experiments/error_figures.hpp"
#include "experiments/pair_timing.hpp"

namespace dyop::experiments {
namespace {

constexpr std::uint64_t kSeed = 2026;
// A depth error at or below this fraction of the pair's size counts as exact: far above double
// rounding (1e-16), far below any error a heuristic makes.
constexpr double kExactRelTol = 1e-9;

// The reference answers of one class in one precision: the exact separation and sat's normal.
struct Reference {
  std::vector<double> separation;
  std::vector<int> sign;
  std::vector<Vec2<double>> normal;
  std::vector<double> size;
};

template <class T>
Reference reference_of(const workloads::PairSet<T>& set) {
  Reference ref;
  for (const workloads::RawPair& p : set.raw) {
    const workloads::ExactAnswer exact = workloads::exact_separation(p);
    ref.separation.push_back(exact.separation);
    ref.sign.push_back(exact.sign);
    const auto t = workloads::build<double>(p);
    ref.normal.push_back(sat(t.a.triangle, t.b.triangle).normal);
    ref.size.push_back(workloads::pair_size(p));
  }
  return ref;
}

template <class T>
void measure_errors(const std::vector<Answer<T>>& got, const Reference& ref, BenchRecord& rec) {
  std::vector<double> errors;
  double angle_sum = 0;
  int angles = 0;
  for (std::size_t k = 0; k < got.size(); ++k) {
    if (got[k].status == Status::Invalid) {
      ++rec.invalid;
      continue;
    }
    const double size = ref.size[k];
    const double band = 4 * touching_tolerance<T>() * size;
    const bool exact_penetrating = ref.sign[k] < 0;
    if (std::abs(ref.separation[k]) > band &&
        exact_penetrating != (got[k].status == Status::Penetrating)) {
      ++rec.misclassified;
    }
    const double depth = std::max(0.0, -static_cast<double>(got[k].separation));
    const double exact_depth = std::max(0.0, -ref.separation[k]);
    errors.push_back(std::abs(depth - exact_depth) / size);
    if (exact_penetrating && got[k].status == Status::Penetrating && exact_depth > 1e-6 * size) {
      const double c =
          std::clamp(got[k].normal.template cast<double>().dot(ref.normal[k]), -1.0, 1.0);
      const double angle = std::acos(c);
      rec.normal_err_max = std::max(rec.normal_err_max, angle);
      angle_sum += angle;
      ++angles;
    }
  }
  rec.normal_err_mean = angles ? angle_sum / angles : 0;
  if (errors.empty()) return;
  const ErrorFigures figures = error_figures(errors);
  rec.err_max = figures.max;
  double sum = 0;
  int exact = 0;
  for (double e : errors) {
    sum += e;
    exact += e <= kExactRelTol;
  }
  rec.err_mean = sum / static_cast<double>(errors.size());
  rec.err_p99 = figures.p99;
  rec.exact_fraction = static_cast<double>(exact) / static_cast<double>(errors.size());
}

template <class T>
void run_precision(const BenchOptions& options, workloads::InputClass c,
                   std::map<workloads::InputClass, double>& box2d_ns,
                   std::vector<BenchRecord>& records, std::ostream& progress) {
  constexpr bool is_float = std::is_same_v<T, float>;
  const workloads::Precision precision =
      is_float ? workloads::Precision::Float : workloads::Precision::Double;
  const int passes = options.quick ? 5 : 21;
  const workloads::PairSet<T> set = workloads::make_pair_set<T>(c, options.pairs, kSeed);
  const workloads::PairSet<T> timed = workloads::make_pair_set<T>(c, options.timing_pairs, kSeed);
  const Reference ref = reference_of(set);
  for (const NarrowPhase& v : bench_phases()) {
    BenchRecord base;
    base.method = v;
    base.cls = c;
    base.precision = precision;
    base.pairs = static_cast<int>(set.size());
    base.timed_pairs = static_cast<int>(timed.size());
    bool any = false;
    for (Level l : all_levels) {
      if (!supports(v, l, is_float)) continue;
      if (!any) measure_errors(answers(v, set), ref, base);
      any = true;
      BenchRecord rec = base;
      rec.level = l;
      rec.ns_per_pair = time_per_pair(v, timed, l, passes);
      if (v == NarrowPhase::box2d()) box2d_ns[rec.cls] = rec.ns_per_pair;
      records.push_back(rec);
    }
    if (any) {
      progress << "dyop bench: " << workloads::name(c) << " " << workloads::name(precision) << " "
               << adapters::name(v) << " done\n";
    }
  }
}

}  // namespace

std::vector<BenchRecord> run_bench(const BenchOptions& options, std::ostream& progress) {
  std::vector<BenchRecord> records;
  std::map<workloads::InputClass, double> box2d_ns;
  for (workloads::InputClass c : workloads::bench_classes) {
    run_precision<float>(options, c, box2d_ns, records, progress);
    run_precision<double>(options, c, box2d_ns, records, progress);
  }
  for (BenchRecord& r : records) {
    const auto it = box2d_ns.find(r.cls);
    r.ratio_vs_box2d = it != box2d_ns.end() && it->second > 0 ? r.ns_per_pair / it->second : 0;
  }
  return records;
}

}  // namespace dyop::experiments
