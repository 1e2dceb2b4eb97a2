#include "experiments/thread_scaling.hpp"

#include <algorithm>
#include <chrono>
#include <memory>
#include <ostream>
#include <stdexcept>
#include <thread>

#include "dyop/box2d.hpp"
#include "scenes/builders.hpp"
#include "experiments/progress.hpp"
#include "scenes/scene.hpp"
#include "scenes/scene_world.hpp"

namespace dyop::experiments {
namespace {

using detail::fixed;

// One run: `n` copies of the scene under whatever is installed, each stepped on its own thread.
// Seconds from the threads' start to the last one's end.
double timed_run(const ThreadScalingOptions& options, int n) {
  std::vector<std::unique_ptr<scenes::SceneWorld>> worlds;
  for (int i = 0; i < n; ++i) {
    worlds.push_back(std::make_unique<scenes::SceneWorld>(options.scene, options.seed));
  }
  const auto start = std::chrono::steady_clock::now();
  std::vector<std::thread> threads;
  for (std::unique_ptr<scenes::SceneWorld>& w : worlds) {
    threads.emplace_back([&w, &options] {
      for (int s = 0; s < options.steps; ++s) w->step();
    });
  }
  for (std::thread& t : threads) t.join();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

std::vector<ThreadScalingRecord> run_thread_scaling(const ThreadScalingOptions& options,
                                                    std::ostream& progress) {
  if (options.steps < 1 || options.runs < 1) {
    throw std::invalid_argument("thread scaling needs at least 1 step and 1 run");
  }
  for (int n : options.threads) {
    if (n < 1) throw std::invalid_argument("thread scaling needs at least 1 thread per run");
  }
  if (scenes::detail::find_builder(options.scene) == nullptr) {
    throw std::invalid_argument("thread scaling: no Box2D scene called '" + options.scene + "'");
  }
  const scenes::Runner runners[] = {std::nullopt, box2d::Backend::Dyop};
  std::vector<ThreadScalingRecord> records;
  for (int n : options.threads) {
    double best[2] = {0, 0};
    for (int run = 0; run < options.runs; ++run) {
      for (int k = 0; k < 2; ++k) {  // Box2D's own, then dyop: alternating
        if (runners[k]) {
          box2d::install(*runners[k]);
        } else {
          box2d::uninstall();
        }
        const double s = timed_run(options, n);
        best[k] = run == 0 ? s : std::min(best[k], s);
      }
    }
    box2d::uninstall();
    for (int k = 0; k < 2; ++k) {
      ThreadScalingRecord r;
      r.runner = runners[k];
      r.threads = n;
      r.steps = options.steps;
      r.seconds = best[k];
      r.steps_per_second = n * options.steps / best[k];
      r.ratio_vs_own = best[0] / best[k];
      records.push_back(r);
    }
    progress << "dyop bench: " << n << " " << options.scene << " world" << (n > 1 ? "s" : "")
             << " on as many threads: " << fixed(records.back().steps_per_second, 0)
             << " steps/s with dyop, " << fixed(records[records.size() - 2].steps_per_second, 0)
             << " with Box2D's own (" << fixed(records.back().ratio_vs_own, 2) << "x)\n";
  }
  return records;
}

}  // namespace dyop::experiments
