// `dyop view`'s recording (two runners over one scene, frame by frame) and its page.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>
#include <string>

#include "experiments/lockstep_recording.hpp"
#include "report/viewer_page.hpp"
#include "scenes/scene.hpp"

namespace {

using dyop::box2d::Backend;
using namespace dyop::experiments;

int marked(const ViewFrame& f) {
  int n = 0;
  for (const ViewContact& c : f.contacts) n += c.mark != EdgeMark::None;
  return n;
}

TEST(LockstepRecording, EveryCatalogueSceneRecordsBothRunnersStepByStep) {
  for (const dyop::scenes::SceneInfo& s : dyop::scenes::scene_catalog()) {
    const LockstepRecording r = record_lockstep(s.name, {std::nullopt, Backend::Dyop}, 3, 0);
    EXPECT_FALSE(r.bodies.empty()) << s.name;
    EXPECT_FALSE(r.fixtures.empty()) << s.name;
    for (int k = 0; k < 2; ++k) {
      ASSERT_EQ(r.frames[k].size(), 3u) << s.name;
      for (const ViewFrame& f : r.frames[k]) {
        EXPECT_EQ(f.poses.size(), r.bodies.size()) << s.name;
        EXPECT_LE(f.agreeing, f.touching) << s.name;
        for (const ViewContact& c : f.contacts) {
          EXPECT_LT(std::size_t(c.fixture_a), r.fixtures.size()) << s.name;
          EXPECT_LT(std::size_t(c.fixture_b), r.fixtures.size()) << s.name;
        }
      }
    }
  }
}

TEST(LockstepRecording, TheSameRunnerTwiceAgreesOnEveryContact) {
  const LockstepRecording r = record_lockstep("slide", {Backend::Dyop, Backend::Dyop}, 60, 0);
  for (int step = 0; step < r.steps; ++step) {
    for (int k = 0; k < 2; ++k) {
      const ViewFrame& f = r.frames[k][step];
      EXPECT_EQ(f.agreeing, f.touching) << "step " << step + 1;
      EXPECT_EQ(f.touching, r.frames[1 - k][step].touching);
    }
    for (std::size_t b = 0; b < r.bodies.size(); ++b) {
      EXPECT_EQ(r.frames[0][step].poses[b].x, r.frames[1][step].poses[b].x);
      EXPECT_EQ(r.frames[0][step].poses[b].angle, r.frames[1][step].poses[b].angle);
    }
  }
}

TEST(LockstepRecording, OnlyThePluginsInternalEdgeRuleIsMarked) {
  // Box2D's own contact is Box2D's code: never marked. On triangulated grounds the plug-in's rule
  // removes the ghost contacts Box2D's code makes at internal edges; with the rule off, the
  // plug-in's manifolds are Box2D's on the same poses.
  const LockstepRecording on = record_lockstep("slide", {std::nullopt, Backend::Dyop}, 60, 0);
  dyop::box2d::Config rule_off;
  rule_off.internal_edges = false;
  const LockstepRecording off =
      record_lockstep("slide", {std::nullopt, Backend::Dyop}, 60, 0, {rule_off, rule_off});
  int marked_on = 0, removed_on = 0;
  for (int step = 0; step < 60; ++step) {
    EXPECT_EQ(marked(on.frames[0][step]), 0);
    EXPECT_EQ(marked(off.frames[0][step]), 0);
    EXPECT_EQ(marked(off.frames[1][step]), 0) << "step " << step + 1;
    marked_on += marked(on.frames[1][step]);
    for (const ViewContact& c : on.frames[1][step].contacts) {
      removed_on += c.mark == EdgeMark::Removed;
      if (c.mark != EdgeMark::None) {
        EXPECT_GT(c.box2d.points, 0);
      }
    }
  }
  EXPECT_GT(marked_on, 0);
  EXPECT_GT(removed_on, 0);
}

TEST(LockstepRecording, UnknownSceneOrNoStepIsRefused) {
  EXPECT_THROW(record_lockstep("nope", {std::nullopt, Backend::Dyop}, 3, 0), std::invalid_argument);
  EXPECT_THROW(record_lockstep("slide", {std::nullopt, Backend::Dyop}, 0, 0),
               std::invalid_argument);
}

TEST(ViewerPage, IsOneSelfContainedFileWithTheRecording) {
  const LockstepRecording r = record_lockstep("mixed", {std::nullopt, Backend::Sat}, 5, 0);
  std::ostringstream page;
  dyop::report::write_viewer_page(r, page);
  const std::string html = page.str();
  EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_EQ(html.find("{{RECORDING}}"), std::string::npos);
  EXPECT_NE(html.find("\"scene\":\"mixed\""), std::string::npos);
  for (const char* outside : {"http://", "https://", "src=", "<link", "@import"}) {
    EXPECT_EQ(html.find(outside), std::string::npos) << outside;
  }
}

TEST(ViewerPage, SummaryCountsWhatTheFramesHold) {
  const LockstepRecording r = record_lockstep("stack", {std::nullopt, Backend::Dyop}, 4, 0);
  const dyop::report::Json s = dyop::report::viewer_summary(r);
  EXPECT_EQ(s["runners"][0], "box2d-own");
  EXPECT_EQ(s["runners"][1], "dyop");
  EXPECT_EQ(s["bodies"], r.bodies.size());
  ASSERT_EQ(s["frames"].size(), 4u);
  for (int step = 0; step < 4; ++step) {
    for (int k = 0; k < 2; ++k) {
      const ViewFrame& f = r.frames[k][step];
      EXPECT_EQ(s["frames"][step]["touching"][k], f.touching);
      EXPECT_EQ(s["frames"][step]["agreeing"][k], f.agreeing);
      EXPECT_EQ(s["frames"][step]["marked"][k], marked(f));
    }
  }
}

}  // namespace
