// `dyop bench`'s worlds on threads: one record per runner and thread count, with finite, positive
// times and ratios, written in full to the CSV; the plug-in left uninstalled; bad options refused.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "dyop/box2d.hpp"
#include "report/bench_sections.hpp"
#include "scenes/scene.hpp"
#include "experiments/thread_scaling.hpp"

namespace dyop::scenes {
namespace {

using namespace experiments;  // the experiments these tests run over the scenes

ThreadScalingOptions tiny() {
  ThreadScalingOptions o;
  o.threads = {1, 2};
  o.scene = "pyramid";
  o.steps = 5;
  o.runs = 2;
  return o;
}

TEST(ThreadScaling, GivesOneFinitePositiveRecordPerRunnerAndThreadCount) {
  std::ostringstream progress;
  const std::vector<ThreadScalingRecord> records = run_thread_scaling(tiny(), progress);
  ASSERT_EQ(records.size(), 4u);
  for (int k = 0; k < 4; ++k) {
    const ThreadScalingRecord& r = records[static_cast<std::size_t>(k)];
    EXPECT_EQ(r.threads, k < 2 ? 1 : 2);
    EXPECT_EQ(r.runner, k % 2 == 0 ? Runner{} : Runner{box2d::Backend::Dyop});
    EXPECT_EQ(r.steps, 5);
    EXPECT_TRUE(std::isfinite(r.seconds) && r.seconds > 0);
    EXPECT_NEAR(r.steps_per_second, r.threads * r.steps / r.seconds, 1e-9 * r.steps_per_second);
    EXPECT_TRUE(std::isfinite(r.ratio_vs_own) && r.ratio_vs_own > 0);
  }
  EXPECT_EQ(records[0].ratio_vs_own, 1.0);  // Box2D's own against itself
  EXPECT_FALSE(box2d::installed().has_value());
  EXPECT_NE(progress.str().find("2 pyramid worlds"), std::string::npos) << progress.str();

  std::ostringstream csv;
  report::thread_scaling_records(records).write_csv(csv);
  std::istringstream lines(csv.str());
  std::string line;
  int count = 0;
  while (std::getline(lines, line)) ++count;
  EXPECT_EQ(count, 1 + 4);
  std::ostringstream table;
  report::write_thread_scaling_table(records, "pyramid", table);
  EXPECT_NE(table.str().find("hardware threads"), std::string::npos) << table.str();
}

TEST(ThreadScaling, RefusesAnUnknownSceneAndEmptyRuns) {
  std::ostringstream progress;
  ThreadScalingOptions o = tiny();
  o.scene = "paper";  // no Box2D world
  EXPECT_THROW(run_thread_scaling(o, progress), std::invalid_argument);
  o = tiny();
  o.steps = 0;
  EXPECT_THROW(run_thread_scaling(o, progress), std::invalid_argument);
  o = tiny();
  o.threads = {0};
  EXPECT_THROW(run_thread_scaling(o, progress), std::invalid_argument);
}

}  // namespace
}  // namespace dyop::scenes
