// Box2D scenes under Box2D's own contact (the plug-in not installed) and the in-world comparison
// built on them: the reference every in-world ratio is taken against.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "dyop/box2d.hpp"
#include "report/compare_in_world.hpp"
#include "experiments/compare.hpp"
#include "experiments/in_world.hpp"
#include "experiments/recycling_sweep.hpp"
#include "scenes/scene.hpp"

namespace dyop::scenes {
namespace {

using namespace experiments;  // the experiments these tests run over the scenes

TEST(OwnContact, GivesTheWorldOfBox2DsCodeThroughThePlugIn) {
  // `box2d` answers with b2CollidePolygons through the plug-in, bit for bit Box2D's own contact.
  for (const char* scene : {"pyramid", "mixed", "stack-concave"}) {
    const SceneMetrics own = run_scene(scene, std::nullopt, 120, 3);
    const SceneMetrics through = run_scene(scene, box2d::Backend::Box2D, 120, 3);
    EXPECT_EQ(own.hash, through.hash) << scene;
    EXPECT_EQ(own.contact_updates, through.contact_updates) << scene;
    EXPECT_EQ(own.runner, Runner{});
  }
}

TEST(OwnContact, LeavesThePlugInUninstalledAndReportsNoPlugInCounters) {
  ASSERT_TRUE(box2d::install(box2d::Backend::Dyop).ok());
  const SceneMetrics own = run_scene("rain", std::nullopt, 30, 0);
  EXPECT_FALSE(box2d::installed().has_value());
  EXPECT_FALSE(own.plugin_evaluations.has_value()) << "the plug-in evaluated nothing";
  EXPECT_FALSE(own.fallbacks.has_value());
  EXPECT_FALSE(own.skips.has_value());
  EXPECT_FALSE(own.skip_config.has_value());
  EXPECT_GT(own.contact_updates, 0u);
  EXPECT_GT(own.step_ms_total, 0.0);
  EXPECT_GE(own.step_ms_total, own.narrowphase_ms_total) << "the step contains the narrow phase";
}

TEST(OwnContact, HasNoPaperScene) {
  EXPECT_THROW(make_scene("paper", std::nullopt, 0), std::invalid_argument);
}

TEST(InWorld, AlternatesOwnAndBackendAndGivesFinitePositiveRatios) {
  std::string order;
  const InWorldRatio r = measure_in_world("stack", box2d::Backend::Sat, 2, [&](const Runner& x) {
    order += x ? "b" : "o";
    return run_scene("stack", x, 60, 0);
  });
  EXPECT_EQ(order, "obob");
  EXPECT_EQ(r.backend, box2d::Backend::Sat);
  EXPECT_EQ(r.repetitions, 2);
  EXPECT_EQ(r.steps, 60);
  for (double ratio : {r.narrowphase_ratio(), r.step_ratio()}) {
    EXPECT_TRUE(std::isfinite(ratio) && ratio > 0) << ratio;
  }
  EXPECT_THROW(measure_in_world("stack", box2d::Backend::Sat, 0,
                                [](const Runner&) { return SceneMetrics{}; }),
               std::invalid_argument);
}

TEST(InWorld, CompareHasOneRowPerBox2DSceneAndBackendInTableAndCsv) {
  CompareOptions options;
  options.quick = true;
  options.steps = 90;  // every stack has landed: contacts on both sides
  options.scenes = {"paper", "stack", "mixed"};
  std::ostringstream progress;
  const report::Comparison comparison = report::run_comparison(options, progress);
  const report::InWorldSection* section = comparison.section<report::InWorldSection>();
  ASSERT_NE(section, nullptr);
  const std::vector<InWorldRatio>& rows = section->rows();
  const std::vector<box2d::Backend> backends = in_world_backends(options);
  ASSERT_EQ(rows.size(), 2 * backends.size()) << "no row for paper (no Box2D world)";
  for (const InWorldRatio& r : rows) {
    EXPECT_TRUE(r.scene == "stack" || r.scene == "mixed") << r.scene;
    EXPECT_GT(r.own.narrowphase_ms, 0);
    EXPECT_GT(r.plugin.step_ms, 0);
  }
  std::ostringstream table, csv;
  report::in_world_records(rows).write_markdown(table);
  report::in_world_records(rows).write_csv(csv);
  EXPECT_NE(table.str().find("| mixed | dyop |"), std::string::npos) << table.str();
  const std::string text = csv.str();
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), static_cast<long>(rows.size()) + 1);
  EXPECT_EQ(text.rfind("scene,backend,steps,repetitions,narrowphase_ms_own", 0), 0u);
}

TEST(InWorld, NamedBackendsAloneRunInTheMainTableAndTheInWorldSectionInTheirOrder) {
  CompareOptions options;
  options.steps = 20;
  options.scenes = {"stack"};
  options.sections = {"in-world"};
  options.backends = {box2d::Backend::Sat, box2d::Backend::Dyop, box2d::Backend::Sat};
  const std::vector<box2d::Backend> expected = {box2d::Backend::Dyop, box2d::Backend::Sat};
  EXPECT_EQ(compare_backends(options), expected) << "the plug-in's order, each once";
  EXPECT_EQ(in_world_backends(options), expected);
  std::ostringstream progress;
  const report::Comparison comparison = report::run_comparison(options, progress);
  ASSERT_EQ(comparison.main.rows.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(comparison.main.rows[i].runner, expected[i]);
  }
  const report::InWorldSection* section = comparison.section<report::InWorldSection>();
  ASSERT_NE(section, nullptr);
  ASSERT_EQ(section->rows().size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(section->rows()[i].backend, expected[i]);
  }
}

// The recycling sweep of one scene: Box2D's own accuracy, one row per distance (times against
// Box2D's own, the share kept, the checked run's errors), then the floor (times only).
TEST(RecyclingSweep, GivesOwnAccuracyEveryDistanceAndTheFloor) {
  RecyclingSweepOptions o;
  o.scenes = {"stack"};
  o.distances = {0.0f, 0.01f};
  o.steps = [](const std::string&) { return 60; };
  o.repetitions = 1;
  std::ostringstream progress;
  const std::vector<RecyclingRecord> rows = run_recycling_sweep(o, progress);
  ASSERT_EQ(rows.size(), 4u);
  EXPECT_EQ(rows[0].row, SweepRow::Own);
  ASSERT_TRUE(rows[0].accuracy && rows[0].accuracy->manifold_errors);
  EXPECT_EQ(rows[0].accuracy->manifold_errors->kept_max, 0.0) << "Box2D's own keeps nothing";
  EXPECT_FALSE(rows[0].timing.has_value());
  for (int i : {1, 2}) {
    const RecyclingRecord& r = rows[static_cast<std::size_t>(i)];
    EXPECT_EQ(r.row, SweepRow::Plugin);
    ASSERT_TRUE(r.timing && r.accuracy && r.accuracy->manifold_errors);
    EXPECT_GT(r.timing->own.narrowphase_ms, 0);
    EXPECT_GT(r.timing->plugin.step_ms, 0);
    EXPECT_GT(r.accuracy->manifold_errors->touching, 0u);
  }
  EXPECT_EQ(rows[1].recycled_share, 0.0) << "off keeps nothing";
  EXPECT_GT(rows[2].recycled_share, 0.5) << "a resting stack keeps most of its manifolds";
  EXPECT_EQ(rows[3].row, SweepRow::Floor);
  ASSERT_TRUE(rows[3].timing.has_value());
  EXPECT_FALSE(rows[3].accuracy.has_value());
  EXPECT_NE(progress.str().find("recycling sweep stack"), std::string::npos);
}

}  // namespace
}  // namespace dyop::scenes
