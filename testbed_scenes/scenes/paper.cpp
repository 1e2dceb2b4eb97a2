#include "scenes/paper.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iterator>
#include <stdexcept>

#include "dyop/dyop.hpp"
#include "dyop/dyop_paper.hpp"
#include "dyop/epa.hpp"
#include "dyop/lin_canny.hpp"
#include "dyop/sat.hpp"
#include "workloads/exact_reference.hpp"

namespace dyop::scenes::paper {
namespace {

using V = Vec2<double>;

// Raw vertices; triangle_types() moves each to its centroid. Longest edges 0.5 … 3 units.
constexpr double kRawTypes[type_count][6] = {
    {-0.25, -0.10, 0.25, -0.05, -0.05, 0.18},  //  1: small, acute
    {-0.35, -0.20, 0.40, -0.15, 0.10, 0.30},   //  2: acute
    {-0.50, 0.00, 0.50, -0.05, 0.15, 0.25},    //  3: obtuse, flat
    {-0.45, -0.40, 0.55, -0.40, -0.45, 0.35},  //  4: right-angled, axis-aligned legs
    {-0.75, -0.05, 0.75, 0.05, 0.10, 0.20},    //  5: thin
    {-0.80, -0.50, 0.90, -0.30, -0.10, 0.80},  //  6: acute
    {-1.00, -0.30, 1.00, -0.20, -0.50, 0.50},  //  7: obtuse
    {-1.10, -0.70, 1.20, -0.40, 0.20, 1.00},   //  8: acute
    {-1.35, 0.00, 1.35, 0.20, 0.60, 0.45},     //  9: thin, obtuse
    {-1.40, -1.00, 1.60, -0.80, -0.30, 1.40},  // 10: large, acute
};

// Columns as `Path`: cx, cy, ax, ay, wx, wy, phase, angle0, spin. Centres on a circle of radius
// 1.6 (k·36°), amplitudes ~2, frequencies spread so that no two types move in step.
constexpr Path kPaths[type_count] = {
    {1.60, 0.00, 2.00, 1.80, 0.90, 1.30, 0.00, 0.00, 0.50},
    {1.29, 0.94, 2.10, 1.90, 1.03, 1.23, 0.60, 0.40, -0.65},
    {0.49, 1.52, 2.20, 2.00, 1.16, 1.16, 1.20, 0.80, 0.80},
    {-0.49, 1.52, 2.00, 2.10, 1.29, 1.09, 1.80, 1.20, -0.95},
    {-1.29, 0.94, 2.10, 1.80, 1.42, 1.02, 2.40, 1.60, 1.10},
    {-1.60, 0.00, 2.20, 1.90, 1.55, 0.95, 3.00, 2.00, -1.25},
    {-1.29, -0.94, 2.00, 2.00, 1.68, 0.88, 3.60, 2.40, 1.40},
    {-0.49, -1.52, 2.10, 2.10, 1.81, 0.81, 4.20, 2.80, -1.55},
    {0.49, -1.52, 2.20, 1.80, 1.94, 0.74, 4.80, 3.20, 1.70},
    {1.29, -0.94, 2.00, 1.90, 2.07, 0.67, 5.40, 3.60, -1.85},
};

// Every method behind one signature, so that all are called alike (one indirect call each).
using Fn = Result<float> (*)(const Triangle<float>&, const Triangle<float>&, LinCannyCache*);
// The paper asks for penetration depths: pairs apart need only the proof (`Apart::Gap`).
constexpr Query<float> kDepth{Level::Depth, 0, 0, Apart::Gap};

Result<float> run_dyop(const Triangle<float>& a, const Triangle<float>& b, LinCannyCache*) {
  return dyop::dyop(a, b, kDepth);
}
Result<float> run_dyop_fast(const Triangle<float>& a, const Triangle<float>& b, LinCannyCache*) {
  return dyop::dyop_fast(a, b, kDepth);
}
Result<float> run_dyop_paper(const Triangle<float>& a, const Triangle<float>& b, LinCannyCache*) {
  return dyop::dyop_paper(a, b, kDepth);
}
Result<float> run_lin_canny_warm(const Triangle<float>& a, const Triangle<float>& b,
                                 LinCannyCache* cache) {
  return dyop::lin_canny(a, b, kDepth, cache);
}
Result<float> run_lin_canny_cold(const Triangle<float>& a, const Triangle<float>& b,
                                 LinCannyCache*) {
  return dyop::lin_canny(a, b, kDepth);
}
Result<float> run_sat(const Triangle<float>& a, const Triangle<float>& b, LinCannyCache*) {
  return dyop::sat(a, b, kDepth);
}
Result<float> run_epa(const Triangle<float>& a, const Triangle<float>& b, LinCannyCache*) {
  return dyop::epa(a, b, kDepth);
}
Result<float> run_box2d(const Triangle<float>& a, const Triangle<float>& b, LinCannyCache*) {
  return box2d::collide_triangles(a, b);
}

Fn fn_of(Method m) {
  switch (m) {
    case Method::Dyop: return run_dyop;
    case Method::DyopFast: return run_dyop_fast;
    case Method::DyopPaper: return run_dyop_paper;
    case Method::LinCannyWarm: return run_lin_canny_warm;
    case Method::LinCannyCold: return run_lin_canny_cold;
    case Method::Sat: return run_sat;
    case Method::Epa: return run_epa;
    case Method::Box2D: return run_box2d;
  }
  return run_sat;
}

int pair_index(int i, int j) {  // i < j
  return i * (2 * type_count - i - 1) / 2 + (j - i - 1);
}

// One call of the narrow phase: a pair of one step.
struct Job {
  const Triangle<float>* a;
  const Triangle<float>* b;
  int pair;
};

// The result of summing depths is stored here so that the timed calls cannot be optimised away.
volatile double g_sink = 0;

// Wall time of `jobs` in microseconds; `caches` (one per pair) start from `start`.
double time_jobs(const std::vector<Job>& jobs, Fn fn, std::vector<LinCannyCache>& caches,
                 const std::vector<LinCannyCache>& start) {
  caches = start;
  double sink = 0;
  const auto t0 = std::chrono::steady_clock::now();
  for (const Job& j : jobs) sink += fn(*j.a, *j.b, &caches[j.pair]).depth;
  const auto t1 = std::chrono::steady_clock::now();
  g_sink = sink;
  return std::chrono::duration<double, std::micro>(t1 - t0).count();
}

// The exact signed separation of a pair, on the float vertices the methods were given.
workloads::ExactAnswer exact_of(const Triangle<float>& a, const Triangle<float>& b) {
  workloads::RawPair p;
  for (int i = 0; i < 3; ++i) {
    p.a[i] = a.vertex(i).cast<double>();
    p.b[i] = b.vertex(i).cast<double>();
  }
  return workloads::exact_separation(p);
}

double band_of(const Triangle<float>& a, const Triangle<float>& b) {
  return static_cast<double>(touching_tolerance<float>()) * std::max(a.size(), b.size());
}

double area_of(const TriangleType& t) {
  return 0.5 * std::abs(cross<double>(t[1] - t[0], t[2] - t[0]));
}

}  // namespace

const std::array<TriangleType, type_count>& triangle_types() {
  static const std::array<TriangleType, type_count> types = [] {
    std::array<TriangleType, type_count> out;
    for (int k = 0; k < type_count; ++k) {
      const double* r = kRawTypes[k];
      const V c((r[0] + r[2] + r[4]) / 3, (r[1] + r[3] + r[5]) / 3);
      for (int i = 0; i < 3; ++i) out[k][i] = V(r[2 * i], r[2 * i + 1]) - c;
    }
    return out;
  }();
  return types;
}

const std::array<Path, type_count>& paths() {
  static const std::array<Path, type_count> out = [] {
    std::array<Path, type_count> p;
    std::copy(std::begin(kPaths), std::end(kPaths), p.begin());
    return p;
  }();
  return out;
}

double start_time(std::uint64_t seed) { return static_cast<double>(seed % 1000) * 3.0; }

Pose pose(int k, double t) {
  const Path& p = paths()[k];
  Pose out;
  out.position = V(p.cx + p.ax * std::sin(p.wx * t + p.phase), p.cy + p.ay * std::sin(p.wy * t));
  out.velocity = V(p.ax * p.wx * std::cos(p.wx * t + p.phase), p.ay * p.wy * std::cos(p.wy * t));
  out.angle = p.angle0 + p.spin * t;
  out.spin = p.spin;
  return out;
}

Frame frame_at(double t) {
  Frame f;
  std::array<Vec2<float>, type_count> lo, hi;
  for (int k = 0; k < type_count; ++k) {
    const Pose p = pose(k, t);
    const double c = std::cos(p.angle), s = std::sin(p.angle);
    Vec2<float> v[3];
    for (int i = 0; i < 3; ++i) {
      const V& u = triangle_types()[k][i];
      v[i] = (p.position + V(c * u.x() - s * u.y(), s * u.x() + c * u.y())).cast<float>();
    }
    const TriangleOrError<float> tri = Triangle<float>::make(v[0], v[1], v[2]);
    if (!tri.ok())
      throw std::logic_error("paper: triangle type " + std::to_string(k + 1) + ": " +
                             describe(tri.error));
    f.triangles.push_back(tri.triangle);
    lo[k] = v[0].cwiseMin(v[1]).cwiseMin(v[2]);
    hi[k] = v[0].cwiseMax(v[1]).cwiseMax(v[2]);
  }
  for (int i = 0; i < type_count; ++i) {
    for (int j = i + 1; j < type_count; ++j) {
      if ((lo[i].array() <= hi[j].array()).all() && (lo[j].array() <= hi[i].array()).all()) {
        f.pairs.emplace_back(i, j);
      }
    }
  }
  return f;
}

const char* name(Method m) {
  switch (m) {
    case Method::Dyop: return "dyop";
    case Method::DyopFast: return "dyop-fast";
    case Method::DyopPaper: return "dyop-paper";
    case Method::LinCannyWarm: return "lin-canny-warm";
    case Method::LinCannyCold: return "lin-canny-cold";
    case Method::Sat: return "sat";
    case Method::Epa: return "epa";
    case Method::Box2D: return "box2d";
  }
  return "unknown";
}

Method method_of(box2d::Backend backend) {
  switch (backend) {
    case box2d::Backend::Dyop: return Method::Dyop;
    case box2d::Backend::DyopFast: return Method::DyopFast;
    case box2d::Backend::LinCanny: return Method::LinCannyWarm;
    case box2d::Backend::Sat: return Method::Sat;
    case box2d::Backend::Epa: return Method::Epa;
    case box2d::Backend::Box2D: return Method::Box2D;
  }
  return Method::Sat;
}

Experiment run_experiment(std::uint64_t seed, int steps, int repetitions) {
  Experiment e;
  e.seed = seed;
  e.steps = steps;
  e.repetitions = repetitions;
  std::vector<Frame> frames;
  for (int s = 0; s < steps; ++s) frames.push_back(frame_at(start_time(seed) + s * step_seconds));

  // The calls each timing makes, in step order: per type, all overlapping pairs, all pairs.
  std::array<std::vector<Job>, type_count> per_type;
  std::vector<Job> overlapping, everything;
  for (const Frame& f : frames) {
    for (const auto& [i, j] : f.pairs) {
      const Job job{&f.triangles[i], &f.triangles[j], pair_index(i, j)};
      overlapping.push_back(job);
      per_type[i].push_back(job);
      per_type[j].push_back(job);
    }
    for (int i = 0; i < type_count; ++i) {
      for (int j = i + 1; j < type_count; ++j) {
        everything.push_back({&f.triangles[i], &f.triangles[j], pair_index(i, j)});
      }
    }
  }
  e.pairs_tested = overlapping.size();
  for (int k = 0; k < type_count; ++k) e.pairs_per_type[k] = per_type[k].size();

  constexpr int kMethods = static_cast<int>(std::size(all_methods));
  std::array<std::array<std::vector<double>, type_count>, kMethods> type_us;
  std::array<std::vector<double>, kMethods> total_us, all_us;
  std::vector<LinCannyCache> caches(pair_count);
  const std::vector<LinCannyCache> cold(pair_count);
  for (int rep = 0; rep < repetitions; ++rep) {
    for (int n = 0; n < kMethods; ++n) {
      const int m = (n + rep) % kMethods;  // a different method first each repetition
      const Fn fn = fn_of(all_methods[m]);
      for (int k = 0; k < type_count; ++k) {
        type_us[m][k].push_back(time_jobs(per_type[k], fn, caches, cold));
      }
      total_us[m].push_back(time_jobs(overlapping, fn, caches, cold));
      all_us[m].push_back(time_jobs(everything, fn, caches, cold));
    }
  }

  // Errors: one untimed pass in step order (Lin–Canny's caches warm as in the timed passes).
  std::vector<workloads::ExactAnswer> exact;
  for (const Job& j : overlapping) {
    exact.push_back(exact_of(*j.a, *j.b));
    e.pairs_penetrating += exact.back().sign < 0;
  }
  for (int m = 0; m < kMethods; ++m) {
    MethodFigures f;
    f.method = all_methods[m];
    for (int k = 0; k < type_count; ++k) f.us_per_type[k] = median(type_us[m][k]);
    f.us_total = median(total_us[m]);
    f.us_all_pairs = median(all_us[m]);
    f.ns_per_pair = e.pairs_tested > 0 ? f.us_total * 1e3 / static_cast<double>(e.pairs_tested) : 0;
    const Fn fn = fn_of(f.method);
    caches = cold;
    ErrorTally tally;
    for (std::size_t n = 0; n < overlapping.size(); ++n) {
      const Job& j = overlapping[n];
      const Result<float> r = fn(*j.a, *j.b, &caches[j.pair]);
      tally.add(r.status, r.depth, exact[n].separation, band_of(*j.a, *j.b));
    }
    f.error_max = tally.max();
    f.error_mean = tally.mean();
    f.misclassified = tally.misclassified();
    f.invalid = tally.invalid();
    e.methods.push_back(f);
  }
  return e;
}

namespace {

class PaperScene : public Scene {
 public:
  PaperScene(box2d::Backend backend, std::uint64_t seed)
      : backend_(backend), seed_(seed), fn_(fn_of(method_of(backend))), caches_(pair_count) {}

  void step() override {
    const Frame f = frame_at(time_of(steps_));
    std::vector<Job> jobs;
    for (const auto& [i, j] : f.pairs) {
      jobs.push_back({&f.triangles[i], &f.triangles[j], pair_index(i, j)});
    }
    // Timed once, first: repeating a step's few pairs would let the branch predictor learn them.
    const std::vector<LinCannyCache> start = caches_;
    step_us_.push_back(time_jobs(jobs, fn_, caches_, start));
    std::vector<LinCannyCache> replay = start;
    for (const Job& j : jobs) {  // untimed, from the same caches: the answers the timing got
      const Result<float> r = fn_(*j.a, *j.b, &replay[j.pair]);
      const workloads::ExactAnswer x = exact_of(*j.a, *j.b);
      errors_.add(r.status, r.depth, x.separation, band_of(*j.a, *j.b));
      if (r.status != Status::Invalid && !std::isfinite(r.depth)) nan_ = true;
      if (x.sign <= 0) penetration_.add(std::max(0.0, -x.separation));
    }
    pairs_ += jobs.size();
    ++steps_;
  }

  SceneMetrics metrics() const override {
    SceneMetrics m;
    m.scene = "paper";
    m.backend = box2d::name(backend_);
    m.seed = seed_;
    m.steps = steps_;
    m.bodies = type_count;
    m.triangles = type_count;
    m.triangle_pairs = pairs_;
    m.contact_updates = pairs_;
    double total_us = 0;
    for (double u : step_us_) total_us += u;
    m.step_ms_median = median(step_us_) * 1e-3;
    m.step_ms_total = total_us * 1e-3;
    m.narrowphase_ms_total = total_us * 1e-3;
    m.narrowphase_ns_per_pair = pairs_ > 0 ? total_us * 1e3 / static_cast<double>(pairs_) : 0;
    add_accuracy(errors_, penetration_, m);
    // The final state: every type's pose at the last step, density 1 (mass = area; polar
    // moment about the centroid = m·(a² + b² + c²)/36).
    const double t = time_of(std::max(0, steps_ - 1));
    Fnv1a hash;
    for (int k = 0; k < type_count; ++k) {
      const Pose p = pose(k, t);
      for (double v :
           {p.position.x(), p.position.y(), p.angle, p.velocity.x(), p.velocity.y(), p.spin}) {
        hash.add(v);
      }
      const TriangleType& tt = triangle_types()[k];
      const double mass = area_of(tt);
      const double edges2 = (tt[1] - tt[0]).squaredNorm() + (tt[2] - tt[1]).squaredNorm() +
                            (tt[0] - tt[2]).squaredNorm();
      m.kinetic_energy_final +=
          0.5 * mass * p.velocity.squaredNorm() + 0.5 * mass * edges2 / 36 * p.spin * p.spin;
    }
    m.hash = hash.value();
    m.nan_detected = nan_ || !all_finite(m);
    return m;
  }

  Drawing drawing() const override {
    Drawing d;
    d.title = std::string("paper / ") + box2d::name(backend_) + ", seed " + std::to_string(seed_) +
              ", step " + std::to_string(steps_);
    const Frame f = frame_at(time_of(std::max(0, steps_ - 1)));
    for (int k = 0; k < type_count; ++k) {
      DrawShape s;
      s.role = DrawShape::Role::Kinematic;
      for (int i = 0; i < 3; ++i) s.points.push_back(f.triangles[k].vertex(i).cast<double>());
      s.label = std::to_string(k + 1);
      d.shapes.push_back(std::move(s));
    }
    return d;
  }

 private:
  double time_of(int step) const { return start_time(seed_) + step * step_seconds; }

  box2d::Backend backend_;
  std::uint64_t seed_;
  Fn fn_;
  std::vector<LinCannyCache> caches_;
  int steps_ = 0;
  std::uint64_t pairs_ = 0;
  std::vector<double> step_us_;
  ErrorTally errors_;
  PenetrationTally penetration_;
  bool nan_ = false;
};

}  // namespace

std::unique_ptr<Scene> make_scene(box2d::Backend backend, std::uint64_t seed) {
  return std::make_unique<PaperScene>(backend, seed);
}

}  // namespace dyop::scenes::paper
