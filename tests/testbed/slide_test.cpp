// The `slide` scene: its figures are there and finite under every runner (and absent from the
// other scenes); with the internal-edge rule on, the exact backends let its boxes and L bodies
// glide over triangulated grounds as over a one-piece ground, where Box2D's own contact trips
// (ghost collisions); the resting box stays put; the wheel rolls as far as on a one-piece ground.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "report/metrics_io.hpp"
#include "support/sliders.hpp"
#include "scenes/scene.hpp"
#include "experiments/slide_run.hpp"

namespace dyop::scenes {
namespace {

using namespace experiments;  // the experiments these tests run over the scenes

using namespace testing;  // the glide bounds and `slider`

// m: a box resting across a junction moves by rounding only.
constexpr double kRestingJitter = 1e-3;
constexpr std::uint64_t kSlideSeed = 3;

int slide_full_steps() { return find_scene("slide")->default_steps; }

box2d::Config rule_on() {
  box2d::Config c = box2d::Config::all();
  c.internal_edges = true;
  return c;
}

std::string runner_name(const ::testing::TestParamInfo<Runner>& info) {
  std::string n = name(info.param);
  for (char& c : n) c = c == '-' ? '_' : c;
  return n;
}

class EveryRunner : public ::testing::TestWithParam<Runner> {};

TEST_P(EveryRunner, SlideFiguresArePresentAndFinite) {
  const SceneMetrics m = run_scene("slide", GetParam(), 120, kSlideSeed, rule_on());
  ASSERT_TRUE(m.slide.has_value());
  EXPECT_EQ(m.slide->sliders.size(), 8u);
  EXPECT_TRUE(all_finite(m));
  EXPECT_FALSE(m.nan_detected);
  ASSERT_TRUE(m.top_displacement.has_value()) << "the resting box is watched";
  double largest = 0;
  for (const SliderFigures& s : m.slide->sliders) {
    SCOPED_TRACE(s.body + " on " + s.ground);
    EXPECT_GE(s.max_vertical_speed, 0);
    EXPECT_GE(s.max_angular_speed, 0);
    EXPECT_TRUE(std::isfinite(s.travel));  // < 0 when a trip throws it back
    EXPECT_EQ(s.rolling, s.body == "wheel");
    if (!s.rolling) largest = std::max(largest, s.max_vertical_speed);
  }
  EXPECT_EQ(m.slide->max_vertical_speed, largest);

  std::ostringstream out;
  report::write_json(m, out);
  const nlohmann::json j = nlohmann::json::parse(out.str());
  ASSERT_TRUE(j["slide"].is_object());
  EXPECT_EQ(j["slide"]["sliders"].size(), 8u);
  EXPECT_TRUE(j["slide"]["min_travel"].is_number());
  const std::string row = report::csv_row(m);
  EXPECT_EQ(std::count(row.begin(), row.end(), ','),
            static_cast<long>(report::csv_columns().size()) - 1)
      << "the per-slider list has no CSV column";
}

INSTANTIATE_TEST_SUITE_P(Slide, EveryRunner,
                         ::testing::Values(Runner(), Runner(box2d::Backend::Dyop),
                                           Runner(box2d::Backend::Sat)),
                         runner_name);

TEST(Slide, OtherScenesHaveNoSlideFigures) {
  EXPECT_FALSE(run_scene("stack", box2d::Backend::Dyop, 3, 0).slide.has_value());
  std::ostringstream out;
  report::write_json(run_scene("mixed", box2d::Backend::Dyop, 3, 0), out);
  EXPECT_TRUE(nlohmann::json::parse(out.str())["slide"].is_null());
}

class ExactBackend : public ::testing::TestWithParam<box2d::Backend> {};

TEST_P(ExactBackend, SlidersGlideOverTriangulatedGroundsWithTheInternalEdgeRule) {
  const SceneMetrics m = run_scene("slide", GetParam(), slide_full_steps(), kSlideSeed, rule_on());
  ASSERT_TRUE(m.slide.has_value());
  for (const SliderFigures& s : m.slide->sliders) {
    if (s.rolling) continue;
    SCOPED_TRACE(s.body + " on " + s.ground);
    EXPECT_LE(s.max_vertical_speed, kGlideVerticalSpeed);
    EXPECT_GE(s.travel, kGlideTravel);
  }
  EXPECT_EQ(m.fallbacks, 0u);
}

TEST_P(ExactBackend, RestingBoxStaysAcrossItsJunction) {
  const SceneMetrics m = run_scene("slide", GetParam(), slide_full_steps(), kSlideSeed, rule_on());
  ASSERT_TRUE(m.top_displacement.has_value());
  EXPECT_LE(*m.top_displacement, kRestingJitter);
}

// A polygon wheel slows at each of its vertices, and where the vertices land on the cells' varies
// with the launch point: its travel on cells stays within kWheelTravelSpread of the one-piece
// ground's, and it is thrown up no faster than there.
TEST_P(ExactBackend, WheelRollsOverTriangulatedCellsAboutAsOverOnePiece) {
  const SceneMetrics m = run_scene("slide", GetParam(), slide_full_steps(), kSlideSeed, rule_on());
  const SliderFigures& one_piece = slider(m, "wheel", "one-piece");
  const SliderFigures& cells = slider(m, "wheel", "diagonal-0.25m");
  EXPECT_NEAR(cells.travel / one_piece.travel, 1.0, kWheelTravelSpread)
      << "one-piece " << one_piece.travel << ", cells " << cells.travel;
  EXPECT_LE(cells.max_vertical_speed, one_piece.max_vertical_speed + kGlideVerticalSpeed);
}

INSTANTIATE_TEST_SUITE_P(Slide, ExactBackend,
                         ::testing::Values(box2d::Backend::Dyop, box2d::Backend::Sat),
                         [](const ::testing::TestParamInfo<box2d::Backend>& i) {
                           return std::string(box2d::name(i.param));
                         });

TEST(Slide, BoxTripsOnQuarterMetreCellsUnderBox2DsOwnContact) {
  const SceneMetrics m = run_scene("slide", Runner(), slide_full_steps(), kSlideSeed);
  const SliderFigures& one_piece = slider(m, "box", "one-piece");
  EXPECT_LE(one_piece.max_vertical_speed, kGlideVerticalSpeed) << "a one-piece ground: a glide";
  EXPECT_GE(one_piece.travel, kGlideTravel);
  for (const char* ground : {"diagonal-0.25m", "fan-0.25m"}) {
    SCOPED_TRACE(ground);
    const SliderFigures& box = slider(m, "box", ground);
    EXPECT_GT(box.max_vertical_speed, kTripVerticalSpeed);
    EXPECT_LT(box.travel, 0.5);
  }
  ASSERT_TRUE(m.top_displacement.has_value());
  EXPECT_LE(*m.top_displacement, kRestingJitter);
}

TEST(Slide, CompareRunnersStartWithBox2DsOwnContact) {
  const std::vector<Runner> quick = slide_runners(true);
  ASSERT_EQ(quick.size(), 3u);
  EXPECT_FALSE(quick[0].has_value());
  EXPECT_EQ(slide_runners(false).size(), 1u + box2d::backend_count);
  const SlideRun r = run_slide(box2d::Backend::Dyop, 10, kSlideSeed, rule_on());
  ASSERT_TRUE(r.metrics.slide.has_value());
  ASSERT_EQ(r.paths.size(), r.metrics.slide->sliders.size());
  for (const SliderPath& p : r.paths) {
    EXPECT_EQ(p.x.size(), 10u);
    EXPECT_EQ(p.height.size(), 10u);
  }
  EXPECT_GT(r.paths.front().x.back(), 0.5) << "a box at 6 m/s, 10 steps";
}

}  // namespace
}  // namespace dyop::scenes
