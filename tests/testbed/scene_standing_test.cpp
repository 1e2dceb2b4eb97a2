// With `dyop` the pyramids and the stacks stand as they do with Box2D's own narrow phase.
#include <gtest/gtest.h>

#include <string>

#include "experiments/compare.hpp"
#include "scenes/scene.hpp"

namespace dyop::scenes {
namespace {

using namespace experiments;  // the experiments these tests run over the scenes

constexpr int kStandingSteps = 600;  // 10 s

class Standing : public ::testing::TestWithParam<std::string> {};

TEST_P(Standing, WithDyopAsWithBox2D) {
  const SceneMetrics box2d = run_scene(GetParam(), box2d::Backend::Box2D, kStandingSteps, 0);
  const SceneMetrics dyop = run_scene(GetParam(), box2d::Backend::Dyop, kStandingSteps, 0);
  ASSERT_TRUE(box2d.top_displacement.has_value());
  ASSERT_TRUE(dyop.top_displacement.has_value());
  EXPECT_LE(*box2d.top_displacement, standing_displacement) << "Box2D's own reference";
  EXPECT_LE(*dyop.top_displacement, standing_displacement);
  EXPECT_NEAR(*dyop.top_displacement, *box2d.top_displacement, 0.05);
  EXPECT_EQ(*dyop.fallbacks, 0u);
  RecordProperty("top_displacement_dyop", std::to_string(*dyop.top_displacement));
  RecordProperty("top_displacement_box2d", std::to_string(*box2d.top_displacement));
}

INSTANTIATE_TEST_SUITE_P(Structures, Standing,
                         ::testing::Values("pyramid", "pyramid-rows", "stack"),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           std::string n = info.param;
                           for (char& c : n) c = c == '-' ? '_' : c;
                           return n;
                         });

}  // namespace
}  // namespace dyop::scenes
