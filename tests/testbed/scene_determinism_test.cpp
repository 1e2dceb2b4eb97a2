// A scene is a function of its seed: the same seed gives the same final state (hash) twice, and a
// different seed a different one.
#include <gtest/gtest.h>

#include <string>

#include "scenes/scene.hpp"

namespace dyop::scenes {
namespace {

constexpr int kDeterminismSteps = 40;

class EverySceneSeed : public ::testing::TestWithParam<std::string> {};

TEST_P(EverySceneSeed, SameSeedSameHashOtherSeedOtherHash) {
  const std::string& name = GetParam();
  for (box2d::Backend b : {box2d::Backend::Dyop, box2d::Backend::LinCanny}) {
    const SceneMetrics first = run_scene(name, b, kDeterminismSteps, 11);
    const SceneMetrics again = run_scene(name, b, kDeterminismSteps, 11);
    const SceneMetrics other = run_scene(name, b, kDeterminismSteps, 12);
    EXPECT_EQ(first.hash, again.hash) << box2d::name(b);
    EXPECT_EQ(first.triangle_pairs, again.triangle_pairs) << box2d::name(b);
    EXPECT_EQ(first.pd_error_max, again.pd_error_max) << box2d::name(b);
    EXPECT_NE(first.hash, other.hash) << box2d::name(b);
  }
}

INSTANTIATE_TEST_SUITE_P(Catalogue, EverySceneSeed, ::testing::ValuesIn([] {
                           std::vector<std::string> names;
                           for (const SceneInfo& s : scene_catalog()) names.push_back(s.name);
                           return names;
                         }()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           std::string n = info.param;
                           for (char& c : n) c = c == '-' ? '_' : c;
                           return n;
                         });

}  // namespace
}  // namespace dyop::scenes
