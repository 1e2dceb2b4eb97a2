// `dyop scene --json`: one valid JSON object with every key, non-finite numbers as null (and then
// `nan_detected` true); the CSV rows of `dyop compare` line up with their header.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "report/metrics_io.hpp"
#include "support/metrics_json.hpp"
#include "scenes/scene.hpp"

namespace dyop::scenes {
namespace {

using namespace report;  // the metrics as the report writes them

using testing::json_of;

TEST(MetricsJson, HasEveryKeyTheIssueAsksForWithItsType) {
  const nlohmann::json j = json_of(run_scene("stack", box2d::Backend::Dyop, 70, 5));
  ASSERT_TRUE(j.is_object());
  for (const char* key :
       {"scene", "runner", "steps", "bodies", "triangle_pairs", "step_ms_median",
        "narrowphase_ns_per_pair", "max_penetration", "mean_penetration", "pd_error_max",
        "pd_error_mean", "kinetic_energy_final", "nan_detected", "hash"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  for (const std::string& key : metrics_keys()) EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_EQ(j.size(), metrics_keys().size());
  EXPECT_EQ(j["scene"], "stack");
  EXPECT_EQ(j["runner"], "dyop");
  EXPECT_EQ(j["steps"], 70);
  EXPECT_TRUE(j["bodies"].is_number_integer());
  EXPECT_TRUE(j["triangle_pairs"].is_number_unsigned());
  EXPECT_TRUE(j["step_ms_median"].is_number());
  EXPECT_TRUE(j["nan_detected"].is_boolean());
  EXPECT_FALSE(j["nan_detected"].get<bool>());
  EXPECT_TRUE(j["top_displacement"].is_number()) << "a stack watched after its first second";
  ASSERT_TRUE(j["hash"].is_string());
  EXPECT_EQ(j["hash"].get<std::string>().size(), 16u);
}

TEST(MetricsJson, PaperHasNullsWhereTheFigureDoesNotApply) {
  const nlohmann::json j = json_of(run_scene("paper", box2d::Backend::LinCanny, 5, 0));
  EXPECT_TRUE(j["fallbacks"].is_null());
  EXPECT_TRUE(j["plugin_evaluations"].is_null());
  EXPECT_TRUE(j["top_displacement"].is_null());
  EXPECT_EQ(j["bodies"], 10);
}

TEST(MetricsJson, NonFiniteNumbersAreNullAndFlagged) {
  SceneMetrics m;
  m.scene = "x";
  m.runner = box2d::Backend::Dyop;
  m.max_penetration = std::numeric_limits<double>::quiet_NaN();
  m.kinetic_energy_final = std::numeric_limits<double>::infinity();
  const nlohmann::json j = json_of(m);
  EXPECT_TRUE(j["max_penetration"].is_null());
  EXPECT_TRUE(j["kinetic_energy_final"].is_null());
  EXPECT_TRUE(j["nan_detected"].get<bool>());
}

TEST(MetricsCsv, RowsHaveAsManyFieldsAsTheHeader) {
  auto fields = [](const std::string& line) {
    return static_cast<int>(std::count(line.begin(), line.end(), ',')) + 1;
  };
  const SceneMetrics m = run_scene("paper", box2d::Backend::Dyop, 3, 0);
  const int columns = static_cast<int>(csv_columns().size());
  EXPECT_EQ(fields(csv_header()), columns);
  EXPECT_EQ(fields(csv_row(m)), columns);
  EXPECT_EQ(csv_row(m).rfind("paper,dyop,0,3,", 0), 0u) << csv_row(m);
  EXPECT_EQ(fields(csv_row(run_scene("stack", box2d::Backend::Dyop, 3, 0))), columns)
      << "a Box2D scene, with its skip counts";
}

}  // namespace
}  // namespace dyop::scenes
