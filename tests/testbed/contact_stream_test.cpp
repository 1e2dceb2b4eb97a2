// Contact streams: the recorder sees exactly the evaluations a world makes, step by step; replaying
// Box2D's backend reproduces `b2CollidePolygons` to the bit; the exact backends `sat` and `dyop`
// replay to identical manifolds; a measured stream counts every recorded call; bad input is
// refused with a message.
#include <gtest/gtest.h>

#include <cstring>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "experiments/contact_stream.hpp"
#include "scenes/scene.hpp"

namespace dyop::scenes {
namespace {

using namespace experiments;  // the experiments these tests run over the scenes

using box2d::Backend;

constexpr std::uint64_t kSeed = 1;
// 1.5 s of simulated time: dropped bodies have met the ground and the structures rest, so the
// streams hold both first contacts and resting pairs, and the tests stay short.
constexpr int kStreamSteps = 90;

// Per step: the recorded calls on triangle pairs and on other polygon pairs.
struct StepCounts {
  std::uint64_t triangles = 0;
  std::uint64_t polygons = 0;
};

std::map<int, StepCounts> recorded_per_step(const ContactStream& s) {
  std::map<int, StepCounts> out;
  for (const StreamCall& c : s.calls) {
    StepCounts& n = out[c.step];
    (s.contacts[static_cast<std::size_t>(c.contact)].triangles ? n.triangles : n.polygons) += 1;
  }
  return out;
}

// Per step from step 2: the plug-in's evaluations (Box2D's answer through it: the same world, bit
// for bit, with every evaluation counted) on triangle pairs and on other polygon pairs.
std::map<int, StepCounts> plugin_per_step(const std::string& scene) {
  std::map<int, StepCounts> out;
  const std::unique_ptr<Scene> world = make_scene(scene, Backend::Box2D, kSeed);
  for (int step = 1; step <= kStreamSteps; ++step) {
    const box2d::Stats before = box2d::stats();
    world->step();
    const box2d::Stats after = box2d::stats();
    if (step == 1) continue;  // its contacts are created inside Step: not recorded
    out[step] = {after.triangles(Backend::Box2D) - before.triangles(Backend::Box2D),
                 after.polygon_pairs - before.polygon_pairs};
  }
  return out;
}

void expect_recorder_matches_plugin(const std::string& scene) {
  const ContactStream stream = record_stream(scene, kStreamSteps, kSeed);
  ASSERT_FALSE(stream.calls.empty());
  std::map<int, StepCounts> recorded = recorded_per_step(stream);
  for (const auto& [step, evaluated] : plugin_per_step(scene)) {
    EXPECT_EQ(evaluated.triangles, recorded[step].triangles) << scene << " step " << step;
    EXPECT_EQ(evaluated.polygons, recorded[step].polygons) << scene << " step " << step;
  }
}

// In these scenes no step's motion carries a body into static ground in the first 1.5 s (no
// continuous-collision event), so every evaluation is one of `Collide`'s.
TEST(ContactStream, RecordedUpdatesEqualPluginEvaluationsEveryStepPyramid) {
  expect_recorder_matches_plugin("pyramid");
}

TEST(ContactStream, RecordedUpdatesEqualPluginEvaluationsEveryStepStack) {
  expect_recorder_matches_plugin("stack");
}

TEST(ContactStream, RecordedUpdatesEqualPluginEvaluationsEveryStepMixed) {
  expect_recorder_matches_plugin("mixed");
}

// Falling triangles reach the static bin within a step's motion: Box2D's time of impact
// re-evaluates those contacts (`SolveTOI`) on top of `Collide`'s updates, and those are not
// recorded: never fewer evaluations than recorded, and some more once triangles land.
TEST(ContactStream, RecordedUpdatesAreCollidesShareOfPluginEvaluationsRain) {
  const ContactStream stream = record_stream("rain", kStreamSteps, kSeed);
  std::map<int, StepCounts> recorded = recorded_per_step(stream);
  bool time_of_impact = false;
  for (const auto& [step, evaluated] : plugin_per_step("rain")) {
    EXPECT_GE(evaluated.triangles, recorded[step].triangles) << "step " << step;
    time_of_impact = time_of_impact || evaluated.triangles != recorded[step].triangles;
  }
  EXPECT_TRUE(time_of_impact) << "no time-of-impact evaluation in rain: make this test exact";
}

TEST(ContactStream, WorldEvaluationsAreTheRecordedCallsPlusTimeOfImpactOnes) {
  EXPECT_EQ(world_evaluations("pyramid", kStreamSteps, kSeed),
            record_stream("pyramid", kStreamSteps, kSeed).calls.size());
  EXPECT_GT(world_evaluations("rain", kStreamSteps, kSeed),
            record_stream("rain", kStreamSteps, kSeed).calls.size());
}

TEST(ContactStream, ReplayingBox2DBackendAgreesWithB2CollidePolygonsExactly) {
  for (const char* scene : {"rain", "mixed"}) {
    const ContactStream stream = record_stream(scene, kStreamSteps, kSeed);
    const StreamAgreement a = compare_with_box2d(stream, Backend::Box2D);
    EXPECT_EQ(a.calls, stream.calls.size()) << scene;
    EXPECT_EQ(a.same_point_count, a.calls) << scene;
    EXPECT_GT(a.both_points, 0u) << scene;
    EXPECT_EQ(a.same_face, a.both_points) << scene;
    EXPECT_EQ(a.normal_angle_max, 0.0) << scene;
    EXPECT_EQ(a.separation_diff_max, 0.0) << scene;
  }
}

bool same_manifold(const b2Manifold& x, const b2Manifold& y) {
  if (x.pointCount != y.pointCount) return false;
  if (x.pointCount == 0) return true;  // an empty manifold's other fields mean nothing
  if (x.type != y.type || std::memcmp(&x.localNormal, &y.localNormal, sizeof x.localNormal) != 0 ||
      std::memcmp(&x.localPoint, &y.localPoint, sizeof x.localPoint) != 0) {
    return false;
  }
  for (int i = 0; i < x.pointCount; ++i) {
    const b2ManifoldPoint& p = x.points[i];
    const b2ManifoldPoint& q = y.points[i];
    if (std::memcmp(&p.localPoint, &q.localPoint, sizeof p.localPoint) != 0 ||
        p.id.key != q.id.key) {
      return false;
    }
  }
  return true;
}

TEST(ContactStream, SatAndDyopReplaysGiveIdenticalManifolds) {
  for (const char* scene : {"rain", "pyramid", "slivers"}) {
    const ContactStream stream = record_stream(scene, kStreamSteps, kSeed);
    const std::vector<b2Manifold> sat = replay_manifolds(stream, Backend::Sat);
    const std::vector<b2Manifold> dyop = replay_manifolds(stream, Backend::Dyop);
    ASSERT_EQ(sat.size(), stream.calls.size());
    ASSERT_EQ(dyop.size(), stream.calls.size());
    std::size_t differing = 0;
    for (std::size_t i = 0; i < sat.size(); ++i) differing += !same_manifold(sat[i], dyop[i]);
    EXPECT_EQ(differing, 0u) << scene << ": of " << sat.size() << " calls";
  }
}

TEST(ContactStream, MeasuredStreamCountsEveryRecordedCall) {
  const ContactStream stream = record_stream("stack", kStreamSteps, kSeed);
  StreamOptions options;
  options.passes = 1;
  options.min_pass_ms = 0;  // one replay per runner: only the counts are checked
  const StreamResult r = measure_stream(stream, options);
  EXPECT_EQ(r.calls, stream.calls.size());
  EXPECT_EQ(r.contacts, stream.contacts.size());
  EXPECT_EQ(r.triangle_calls, stream.triangle_calls());
  EXPECT_LE(r.calls_with_points, r.calls);
  ASSERT_EQ(r.runners.size(), static_cast<std::size_t>(box2d::backend_count) + 1);
  EXPECT_EQ(r.runners.back().runner, Runner{});
  EXPECT_EQ(r.runners.back().ratio_vs_box2d_own, 1.0);
  for (const StreamRunnerResult& x : r.runners) {
    EXPECT_EQ(x.agreement.calls, stream.calls.size()) << name(x.runner);
    EXPECT_GT(x.ns_per_call, 0.0) << name(x.runner);
  }
}

TEST(ContactStream, EveryStreamCallComesFromAStepAfterTheFirst) {
  const ContactStream stream = record_stream("tumbler", kStreamSteps, kSeed);
  for (const StreamCall& c : stream.calls) {
    ASSERT_GE(c.step, 2);
    ASSERT_LE(c.step, kStreamSteps);
    ASSERT_LT(static_cast<std::size_t>(c.contact), stream.contacts.size());
  }
}

template <class F>
std::string invalid_argument_message(F&& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(no std::invalid_argument thrown)";
}

TEST(ContactStream, BadInputIsRefusedWithAMessage) {
  EXPECT_NE(invalid_argument_message([] {
              record_stream("no-such-scene", kStreamSteps, kSeed);
            }).find("unknown scene 'no-such-scene'"),
            std::string::npos);
  EXPECT_NE(invalid_argument_message([] {
              record_stream("paper", kStreamSteps, kSeed);
            }).find("no Box2D world"),
            std::string::npos);
  EXPECT_NE(invalid_argument_message([] { record_stream("rain", 1, kSeed); }).find("2 steps"),
            std::string::npos);
  EXPECT_NE(invalid_argument_message([] {
              world_evaluations("no-such-scene", kStreamSteps, kSeed);
            }).find("unknown scene"),
            std::string::npos);

  ContactStream empty;
  empty.scene = "rain";
  EXPECT_NE(
      invalid_argument_message([&] { compare_with_box2d(empty, Backend::Dyop); }).find("empty"),
      std::string::npos);
  EXPECT_NE(invalid_argument_message([&] { replay_manifolds(empty, Backend::Dyop); }).find("empty"),
            std::string::npos);
  EXPECT_NE(invalid_argument_message([&] { measure_stream(empty, StreamOptions{}); }).find("empty"),
            std::string::npos);

  const ContactStream stream = record_stream("pyramid", 10, kSeed);
  StreamOptions no_passes;
  no_passes.passes = 0;
  EXPECT_NE(invalid_argument_message([&] { measure_stream(stream, no_passes); }).find("pass"),
            std::string::npos);
}

}  // namespace
}  // namespace dyop::scenes
