#include "experiments/stress.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <ostream>
#include <type_traits>

#include "exact_reference/exact_reference.hpp"
#include "experiments/error_figures.hpp"
#include "report/format.hpp"
#include "workloads/random.hpp"

namespace dyop::experiments {
namespace {

using report::fmt;

using workloads::ExactAnswer;
using workloads::InputClass;
using workloads::Precision;
using workloads::RawPair;
using V = Vec2<double>;

constexpr double kPi = 3.14159265358979323846;
constexpr int kVariants = 1 + invariance_count;  // the pair as generated, then each Invariance

std::string csv_line(const RawPair& p) {
  std::string out;
  for (const auto* t : {&p.a, &p.b}) {
    for (const V& v : *t) {
      out += (out.empty() ? "" : ",") + fmt("%.17g", v.x()) + "," + fmt("%.17g", v.y());
    }
  }
  return out;
}

V centre(const RawPair& p) {
  const workloads::PairBox box = workloads::pair_box(p);
  return 0.5 * (box.lo + box.hi);
}

// The pair under one Invariance, drawn from `rng`: moved by 1 to 100 times its size, turned by
// any angle about its own centre (turning about the world origin would mostly measure the rounding
// of large coordinates), reordered, or swapped. Moved pairs are rounded to the precision again.
RawPair variant(Invariance which, const RawPair& p, Precision precision, workloads::Random& rng) {
  RawPair out = p;
  switch (which) {
    case Invariance::Translation: {
      const double t = 2 * kPi * rng.unit();
      const V shift =
          workloads::pair_size(p) * std::pow(10.0, 2 * rng.unit()) * V(std::cos(t), std::sin(t));
      for (auto* tri : {&out.a, &out.b}) {
        for (V& v : *tri) v += shift;
      }
      return workloads::rounded_to(precision, out);
    }
    case Invariance::Rotation: {
      const double t = 2 * kPi * rng.unit();
      const double c = std::cos(t);
      const double s = std::sin(t);
      const V o = centre(p);
      for (auto* tri : {&out.a, &out.b}) {
        for (V& v : *tri) {
          const V d = v - o;
          v = o + V(c * d.x() - s * d.y(), s * d.x() + c * d.y());
        }
      }
      return workloads::rounded_to(precision, out);
    }
    case Invariance::Reorder:
      std::rotate(out.a.begin(), out.a.begin() + 1 + rng.below(2), out.a.end());
      std::swap(out.b[1], out.b[2]);
      return out;
    case Invariance::Swap:
      return RawPair{p.b, p.a};
  }
  return out;
}

// What one category in one precision needs, computed once for every runner.
struct Category {
  std::vector<RawPair> pairs[kVariants];
  std::vector<bool> valid[kVariants];
  std::vector<double> exact[kVariants];  // translated and rotated pairs have their own answers
  std::vector<int> sign;
  std::vector<double> size;
};

template <class T>
Category prepare(InputClass c, Precision precision, const StressOptions& o) {
  Category cat;
  cat.pairs[0] = workloads::make_pairs(c, o.pairs, o.seed, precision);
  workloads::Random rng(o.seed * 31 + static_cast<std::uint64_t>(c) * 2 +
                        (precision == Precision::Float ? 1 : 0));
  for (const RawPair& p : cat.pairs[0]) {
    for (int v = 1; v < kVariants; ++v) {
      cat.pairs[v].push_back(variant(static_cast<Invariance>(v - 1), p, precision, rng));
    }
  }
  const std::size_t n = cat.pairs[0].size();
  for (int v = 0; v < kVariants; ++v) {
    cat.valid[v].resize(n);
    cat.exact[v].resize(n);
    for (std::size_t k = 0; k < n; ++k) {
      const auto t = workloads::build<T>(cat.pairs[v][k]);
      cat.valid[v][k] = t.a.ok() && t.b.ok();
    }
  }
  cat.sign.resize(n);
  cat.size.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    cat.size[k] = workloads::pair_size(cat.pairs[0][k]);
    if (!cat.valid[0][k]) continue;
    const ExactAnswer e = workloads::exact_separation(cat.pairs[0][k]);
    cat.sign[k] = e.sign;
    // Reordering and swapping change no coordinate: the exact answer is the same.
    for (int v = 0; v < kVariants; ++v) cat.exact[v][k] = e.separation;
    for (Invariance moved : {Invariance::Translation, Invariance::Rotation}) {
      const int v = 1 + static_cast<int>(moved);
      if (cat.valid[v][k])
        cat.exact[v][k] = workloads::exact_separation(cat.pairs[v][k]).separation;
    }
  }
  return cat;
}

template <class T>
StressRecord measure(const adapters::NarrowPhase& r, InputClass c, const Category& cat) {
  const Precision precision = std::is_same_v<T, float> ? Precision::Float : Precision::Double;
  StressRecord rec;
  rec.method = r;
  rec.cls = c;
  rec.precision = precision;
  const std::size_t n = cat.pairs[0].size();
  rec.pairs = static_cast<int>(n);
  std::vector<StressAnswer> answers[kVariants];
  for (int v = 0; v < kVariants; ++v) {
    answers[v] = experiments::stress_answers<T>(r, cat.pairs[v], v == 0);
  }
  for (int v = 0; v < kVariants; ++v) {
    for (std::size_t k = 0; k < n; ++k) {
      rec.nonfinite += !answers[v][k].finite;
      rec.invalid += answers[v][k].verdict_mismatch;
    }
  }
  const double bound = exact_bound(precision);
  std::vector<double> errors;
  double worst = -1;
  for (std::size_t k = 0; k < n; ++k) {
    if (!cat.valid[0][k]) {
      ++rec.rejected;
      continue;
    }
    const StressAnswer& a = answers[0][k];
    if (a.status == Status::Invalid) {
      if (r == adapters::NarrowPhase::of(Method::DyopPaper)) {
        ++rec.invalid_by_design;
      } else if (adapters::call_of(r) != adapters::Call::Batch) {  // batch rows: their verdict
        ++rec.invalid;
      }
      continue;
    }
    if (!a.finite) continue;
    const double size = cat.size[k];
    const double exact = cat.exact[0][k];
    const double error = std::abs(a.separation - exact) / size;
    errors.push_back(error);
    if (error > worst) {
      worst = error;
      rec.worst_pair = csv_line(cat.pairs[0][k]);
    }
    const double band = 4 * touching_tolerance<T>() * size;
    if (std::abs(exact) > band &&
        a.status != (exact < 0 ? Status::Penetrating : Status::Separated)) {
      ++rec.misclassified;
    }
    for (int v = 1; v < kVariants; ++v) {
      const StressAnswer& b = answers[v][k];
      if (!cat.valid[v][k] || b.status == Status::Invalid || !b.finite) continue;
      const double change = b.separation - a.separation;
      const double exact_change = cat.exact[v][k] - exact;
      rec.invariance[v - 1] += std::abs(change - exact_change) > bound * size;
    }
  }
  const ErrorFigures figures = error_figures(errors);
  rec.err_max = figures.max;
  rec.err_p99 = figures.p99;
  return rec;
}

template <class T>
void run_precision(const StressOptions& o, std::vector<StressRecord>& records,
                   std::ostream& progress) {
  constexpr bool is_float = std::is_same_v<T, float>;
  const Precision precision = is_float ? Precision::Float : Precision::Double;
  for (InputClass c : workloads::stress_classes) {
    const auto start = std::chrono::steady_clock::now();
    const Category cat = prepare<T>(c, precision, o);
    int rejected = 0;
    // Every narrow phase once, from no state (a warm-startable method's cold variant).
    for (const adapters::NarrowPhase& r : adapters::narrow_phases(nullptr, true)) {
      if (r.method && r.method->warm) continue;
      if (!experiments::stress_runs(r, is_float)) continue;
      records.push_back(measure<T>(r, c, cat));
      rejected = records.back().rejected;
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    progress << "dyop stress: " << workloads::name(precision) << " " << workloads::name(c) << ": "
             << cat.pairs[0].size() << " pairs, " << rejected << " rejected, "
             << fmt("%.1f", seconds) << " s\n";
  }
}

}  // namespace

bool promises_exact(const adapters::NarrowPhase& p) {
  return p.method && info(p.method->method).accuracy == Accuracy::Exact;  // Box2D's: absolute
}

bool promises_invariance(const adapters::NarrowPhase& p) {
  return p.method && info(p.method->method).invariant();  // Box2D's tolerances are absolute
}

const char* name(Invariance i) {
  switch (i) {
    case Invariance::Translation:
      return "translation";
    case Invariance::Rotation:
      return "rotation";
    case Invariance::Reorder:
      return "reorder";
    case Invariance::Swap:
      return "swap";
  }
  return "unknown";
}

std::vector<StressRecord> run_stress(const StressOptions& options, std::ostream& progress) {
  std::vector<StressRecord> records;
  if (options.run_double) run_precision<double>(options, records, progress);
  if (options.run_float) run_precision<float>(options, records, progress);
  return records;
}

std::vector<std::string> broken_promises(const std::vector<StressRecord>& records) {
  std::vector<std::string> out;
  for (const StressRecord& r : records) {
    const std::string what = std::string(adapters::name(r.method)) + " " +
                             workloads::name(r.precision) + " " + workloads::name(r.cls) + ": ";
    const adapters::NarrowPhase& runner = r.method;
    const double bound = exact_bound(r.precision);
    if (promises_exact(runner) && r.err_max > bound) {
      out.push_back(what + "max error " + fmt("%.3g", r.err_max) + " of the pair's size exceeds " +
                    fmt("%.0e", bound));
    }
    if (promises_exact(runner) && r.misclassified > 0) {
      out.push_back(what + std::to_string(r.misclassified) + " misclassified pairs");
    }
    if (promises_invariance(runner)) {
      for (int i = 0; i < invariance_count; ++i) {
        if (r.invariance[i] > 0) {
          out.push_back(what + std::to_string(r.invariance[i]) + " " +
                        name(static_cast<Invariance>(i)) + " invariance violations");
        }
      }
    }
    if (r.nonfinite > 0 && adapters::call_of(runner) != adapters::Call::Box2D) {
      out.push_back(what + std::to_string(r.nonfinite) + " NaN or inf answers");
    }
    if (r.invalid > 0) {
      out.push_back(what + std::to_string(r.invalid) +
                    " valid pairs answered Invalid or rows lost");
    }
  }
  return out;
}

}  // namespace dyop::experiments
