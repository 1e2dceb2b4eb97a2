// The `paper` scene: the experiment's frames one step at a time, under one backend.
#include <algorithm>
#include <cmath>
#include <memory>

#include "scenes/paper_harness.hpp"

namespace dyop::scenes::paper {
namespace {

double area_of(const TriangleType& t) {
  return 0.5 * std::abs(cross<double>(t[1] - t[0], t[2] - t[0]));
}

class PaperScene : public Scene {
 public:
  PaperScene(box2d::Backend backend, std::uint64_t seed)
      : backend_(backend),
        seed_(seed),
        call_(pair_call(narrow_phase_of(backend))),
        caches_(pair_count) {}

  void step() override {
    const Frame f = frame_at(time_of(steps_));
    std::vector<Job> jobs;
    for (const auto& [i, j] : f.pairs) {
      jobs.push_back({&f.triangles[i], &f.triangles[j], pair_index(i, j)});
    }
    // Timed once, first: repeating a step's few pairs would let the branch predictor learn them.
    const std::vector<PairState> start = caches_;
    step_us_.push_back(time_jobs(jobs, call_, caches_, start));
    std::vector<PairState> replay = start;
    for (const Job& j : jobs) {  // untimed, from the same caches: the answers the timing got
      const Result<float> r = call_(*j.a, *j.b, &replay[j.pair]);
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
    m.runner = backend_;
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
  PairCall call_;
  std::vector<PairState> caches_;
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
