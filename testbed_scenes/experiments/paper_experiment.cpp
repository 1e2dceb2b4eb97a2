// The paper's Figure-7 experiment: every method timed over the same steps, errors against exact.
#include "experiments/paper_experiment.hpp"

#include <algorithm>
#include <iterator>
#include <stdexcept>

#include "adapters/pair_function.hpp"
#include "scenes/paper_harness.hpp"

namespace dyop::experiments::paper {

using namespace scenes::paper;  // the scene's triangles, paths, frames and timing harness
using scenes::ErrorTally;
using scenes::median;

std::vector<adapters::NarrowPhase> experiment_methods() {
  std::vector<adapters::NarrowPhase> out;
  for (const adapters::NarrowPhase& p : adapters::narrow_phases(nullptr, true)) {
    if (adapters::runs_pairs<float>(p)) out.push_back(p);
  }
  return out;
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

  const std::vector<adapters::NarrowPhase> methods = experiment_methods();
  const int n_methods = static_cast<int>(methods.size());
  std::vector<std::array<std::vector<double>, type_count>> type_us(methods.size());
  std::vector<std::vector<double>> total_us(methods.size()), all_us(methods.size());
  std::vector<PairState> caches(pair_count);
  const std::vector<PairState> cold(pair_count);
  for (int rep = 0; rep < repetitions; ++rep) {
    for (int n = 0; n < n_methods; ++n) {
      const int m = (n + rep) % n_methods;  // a different method first each repetition
      const PairCall call = pair_call(methods[m]);
      for (int k = 0; k < type_count; ++k) {
        type_us[m][k].push_back(time_jobs(per_type[k], call, caches, cold));
      }
      total_us[m].push_back(time_jobs(overlapping, call, caches, cold));
      all_us[m].push_back(time_jobs(everything, call, caches, cold));
    }
  }

  // Errors: one untimed pass in step order (Lin–Canny's caches warm as in the timed passes).
  std::vector<workloads::ExactAnswer> exact;
  for (const Job& j : overlapping) {
    exact.push_back(exact_of(*j.a, *j.b));
    e.pairs_penetrating += exact.back().sign < 0;
  }
  for (int m = 0; m < n_methods; ++m) {
    MethodFigures f;
    f.method = methods[m];
    for (int k = 0; k < type_count; ++k) f.us_per_type[k] = median(type_us[m][k]);
    f.us_total = median(total_us[m]);
    f.us_all_pairs = median(all_us[m]);
    f.ns_per_pair = e.pairs_tested > 0 ? f.us_total * 1e3 / static_cast<double>(e.pairs_tested) : 0;
    const PairCall call = pair_call(f.method);
    caches = cold;
    ErrorTally tally;
    for (std::size_t n = 0; n < overlapping.size(); ++n) {
      const Job& j = overlapping[n];
      const Result<float> r = call(*j.a, *j.b, &caches[j.pair]);
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

}  // namespace dyop::experiments::paper
