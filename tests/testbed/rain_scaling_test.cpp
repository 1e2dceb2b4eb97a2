// The rain scene at any size and `dyop bench`'s scaling runs over it: the catalogue's rain is the
// 500-triangle case, every backend is run at every size, and the figures are written in full.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>

#include "report/bench_sections.hpp"
#include "scenes/scene.hpp"

namespace dyop::scenes {
namespace {

using namespace experiments;  // the experiments these tests run over the scenes

constexpr int kScalingSteps = 20;

SceneMetrics run_rain(int falling, box2d::Backend backend) {
  const std::unique_ptr<Scene> scene = make_rain(falling, backend, 3);
  for (int i = 0; i < kScalingSteps; ++i) scene->step();
  return scene->metrics();
}

TEST(RainScene, AtTheCataloguesSizeIsTheCataloguesScene) {
  const SceneMetrics sized = run_rain(rain_triangles, box2d::Backend::Dyop);
  const SceneMetrics catalogue = run_scene("rain", box2d::Backend::Dyop, kScalingSteps, 3);
  EXPECT_EQ(sized.hash, catalogue.hash);
  EXPECT_EQ(sized.triangles, catalogue.triangles);
}

TEST(RainScene, HoldsTheFallingTrianglesAskedForPlusItsBin) {
  const SceneMetrics small = run_rain(100, box2d::Backend::Sat);
  const SceneMetrics large = run_rain(1000, box2d::Backend::Sat);
  EXPECT_EQ(small.bodies, 100 + 1);  // the bin is one static body
  EXPECT_EQ(large.bodies, 1000 + 1);
  // The bin widens with the grid: more of its triangles for more falling ones.
  EXPECT_GT(large.triangles - 1000, small.triangles - 100);
  EXPECT_FALSE(large.nan_detected);
  EXPECT_THROW(make_rain(0, box2d::Backend::Sat, 3), std::invalid_argument);
}

TEST(RainScaling, RunsEveryBackendAtEverySizeWithRatiosToBox2dAndToBox2DsOwnContact) {
  ScalingOptions options;
  options.sizes = {30, 60};
  options.steps = 90;  // 1.5 s: the first rows have landed
  std::ostringstream progress;
  const std::vector<ScalingRecord> records = run_rain_scaling(options, progress);
  // Every backend, and Box2D's own contact (the plug-in not installed), at each size.
  ASSERT_EQ(records.size(), 2 * (std::size(box2d::all_backends) + 1));
  for (const ScalingRecord& r : records) {
    SCOPED_TRACE(std::string(name(r.runner)) + " " + std::to_string(r.falling));
    EXPECT_EQ(r.steps, options.steps);
    EXPECT_GT(r.step_ms_median, 0);
    EXPECT_GT(r.narrowphase_ms_per_step, 0);
    EXPECT_GT(r.pairs_per_step, 0);
    EXPECT_EQ(r.fallbacks, 0u);
    EXPECT_FALSE(r.nan_detected);
    if (r.runner == box2d::Backend::Box2D) {
      EXPECT_EQ(r.ratio_vs_box2d, 1.0);
    } else {
      EXPECT_GT(r.ratio_vs_box2d, 0);
    }
    if (!r.runner) {
      EXPECT_EQ(r.ratio_vs_own, 1.0);
      EXPECT_EQ(r.step_ratio_vs_own, 1.0);
    } else {
      EXPECT_TRUE(std::isfinite(r.ratio_vs_own) && r.ratio_vs_own > 0) << r.ratio_vs_own;
      EXPECT_TRUE(std::isfinite(r.step_ratio_vs_own) && r.step_ratio_vs_own > 0);
    }
  }
  EXPECT_EQ(std::count_if(records.begin(), records.end(),
                          [](const ScalingRecord& r) { return !r.runner; }),
            2)
      << "one record of Box2D's own contact per size";
  EXPECT_NE(progress.str().find("rain 60 triangles, epa"), std::string::npos);

  const std::string dir = ::testing::TempDir() + "rain_scaling_test";
  report::ReportDirectory out(dir);
  const std::string section = report::write_scaling_outputs(records, out);
  for (const report::Problem& problem : out.problems()) {
    const std::string& p = problem.message;
    EXPECT_EQ(p.rfind("cannot", 0), std::string::npos) << p;  // gnuplot may be missing, no more
  }
  std::ifstream csv(dir + "/scaling.csv");
  const auto lines =
      std::count(std::istreambuf_iterator<char>(csv), std::istreambuf_iterator<char>(), '\n');
  EXPECT_EQ(lines, static_cast<long>(records.size()) + 1);
  EXPECT_NE(section.find("| lin-canny | 60 |"), std::string::npos);
}

TEST(RainScaling, RefusesSizesAndStepsItCannotMeasure) {
  std::ostringstream progress;
  ScalingOptions no_steps;
  no_steps.steps = 1;
  EXPECT_THROW(run_rain_scaling(no_steps, progress), std::invalid_argument);
  ScalingOptions empty_rain;
  empty_rain.sizes = {100, 0};
  EXPECT_THROW(run_rain_scaling(empty_rain, progress), std::invalid_argument);
  EXPECT_TRUE(progress.str().empty()) << "nothing should run before the arguments are checked";
}

}  // namespace
}  // namespace dyop::scenes
