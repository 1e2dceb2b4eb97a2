// The `tiles` scene: with the internal-edge rule, the exact backends let boxes and L bodies glide
// over every tiled ground (one body, a static body per tile, 8 × 8 chunks, T-junctions in one body
// and in a body per cell, tiles added and removed under the slider) as over one body, and the
// wheel roll as far as on one body; Box2D's own contact trips on tiles as bodies and at
// T-junctions. The `tile-map` scene's crowd glides too.
#include <gtest/gtest.h>

#include <iterator>
#include <string>

#include "scenes/scene.hpp"
#include "support/sliders.hpp"

namespace dyop::scenes {
namespace {

using namespace testing;  // the glide bounds and `slider`

// m/s: the wheel's own rolling over its vertices. A 16-gon of 0.4 m rises and falls by
// r·(1 − cos(π/16)) = 7.7 mm per side; its vertical speed peaks at 0.36 or 0.42 m/s (where its
// first vertex lands) on every ground under every contact, Box2D's own included; a trip throws it
// up faster than 1 m/s.
constexpr double kWheelRollingVerticalSpeed = 0.45;
constexpr std::uint64_t kTilesSeed = 3;
const char* const kGrounds[] = {"one-body",         "tiles",         "chunks-8x8", "t-junctions",
                                "t-junction-tiles", "changing-tiles"};

int tiles_full_steps() { return find_scene("tiles")->default_steps; }

TEST(Tiles, EveryGroundHasABoxAnLAndAWheel) {
  const SceneMetrics m = run_scene("tiles", box2d::Backend::Dyop, 3, kTilesSeed);
  ASSERT_TRUE(m.slide.has_value());
  EXPECT_EQ(m.slide->sliders.size(), 3 * std::size(kGrounds));
  for (const char* ground : kGrounds) {
    for (const char* body : {"box", "L", "wheel"}) EXPECT_NO_THROW(slider(m, body, ground));
  }
}

class ExactBackendOnTiles : public ::testing::TestWithParam<box2d::Backend> {};

TEST_P(ExactBackendOnTiles, BoxesAndLBodiesGlideOverEveryTiledGround) {
  const SceneMetrics m = run_scene("tiles", GetParam(), tiles_full_steps(), kTilesSeed);
  for (const char* ground : kGrounds) {
    for (const char* body : {"box", "L"}) {
      SCOPED_TRACE(std::string(body) + " on " + ground);
      const SliderFigures& s = slider(m, body, ground);
      EXPECT_LE(s.max_vertical_speed, kGlideVerticalSpeed);
      EXPECT_GE(s.travel, kGlideTravel);
    }
  }
  EXPECT_EQ(m.fallbacks, 0u);
  EXPECT_FALSE(m.nan_detected);
}

// A polygon wheel slows at each of its vertices: on every ground its travel stays within
// kWheelTravelSpread of its travel on one body, and it is thrown up no faster than its own rolling
// does.
TEST_P(ExactBackendOnTiles, WheelRollsOverEveryTiledGroundAsOverOneBody) {
  const SceneMetrics m = run_scene("tiles", GetParam(), tiles_full_steps(), kTilesSeed);
  const SliderFigures& one_body = slider(m, "wheel", "one-body");
  for (const char* ground : kGrounds) {
    SCOPED_TRACE(ground);
    const SliderFigures& s = slider(m, "wheel", ground);
    EXPECT_NEAR(s.travel / one_body.travel, 1.0, kWheelTravelSpread);
    EXPECT_LE(s.max_vertical_speed, kWheelRollingVerticalSpeed);
  }
}

INSTANTIATE_TEST_SUITE_P(Tiles, ExactBackendOnTiles,
                         ::testing::Values(box2d::Backend::Dyop, box2d::Backend::Sat),
                         [](const ::testing::TestParamInfo<box2d::Backend>& i) {
                           return std::string(box2d::name(i.param));
                         });

TEST(Tiles, BoxTripsOnTilesAndTJunctionsUnderBox2DsOwnContact) {
  const SceneMetrics m = run_scene("tiles", Runner(), tiles_full_steps(), kTilesSeed);
  for (const char* ground : {"tiles", "t-junctions"}) {
    SCOPED_TRACE(ground);
    EXPECT_GT(slider(m, "box", ground).max_vertical_speed, kTripVerticalSpeed);
  }
}

// The tile map's crowd: every box and L on every lane glides over its tiles as bodies, each
// contact running the rule at every step (too fast to be kept), with debris falling beside them.
TEST(TileMap, EverySliderOfTheCrowdGlides) {
  const SceneMetrics m = run_scene("tile-map", box2d::Backend::Dyop,
                                   find_scene("tile-map")->default_steps, kTilesSeed);
  ASSERT_TRUE(m.slide.has_value());
  EXPECT_EQ(m.slide->sliders.size(), 48u);
  for (const SliderFigures& s : m.slide->sliders) {
    SCOPED_TRACE(s.body + " on " + s.ground);
    EXPECT_LE(s.max_vertical_speed, kGlideVerticalSpeed);
    EXPECT_GE(s.travel, kGlideTravel);
  }
  EXPECT_EQ(m.fallbacks, 0u);
  EXPECT_FALSE(m.nan_detected);
}

}  // namespace
}  // namespace dyop::scenes
