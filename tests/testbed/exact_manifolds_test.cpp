// The manifolds Box2D's solver gets in scenes with every pair family (`mixed`: triangles, boxes
// and circles on edges; `crowd`: boxes, hexagons, circles and triangles in a triangulated bin)
// against the exact answer for the same pose: each manifold's deepest separation is the exact
// separation within Box2D's face hysteresis (the reference face may be B's within it), and its
// normal pushes no deeper than the exact depth by more than that. Nothing kept (recycling off):
// every manifold is an answer afresh.
#include <gtest/gtest.h>

#include <memory>

#include "dyop/box2d.hpp"
#include "scenes/scene.hpp"

namespace dyop::box2d::testing {
namespace {

// What float arithmetic adds to the hysteresis in a pose of metre-sized shapes (metres).
constexpr float kFloatRounding = 1e-5f;

TEST(ExactManifolds, EveryFamilysManifoldIsTheExactAnswerWithinTheFaceHysteresis) {
  Config config = Config::all();
  config.recycle_distance = 0;
  config.internal_edges = false;  // the rule changes the answer on purpose (internal edges)
  for (const char* scene : {"mixed", "crowd"}) {
    const std::unique_ptr<scenes::Scene> s = scenes::make_scene(scene, Backend::Dyop, 3, config);
    s->check_manifolds();
    for (int i = 0; i < 150; ++i) s->step();
    const scenes::SceneMetrics m = s->metrics();
    ASSERT_TRUE(m.manifold_errors.has_value());
    EXPECT_GT(m.manifold_errors->checked, 500u) << scene;
    EXPECT_LE(m.manifold_errors->depth_max, face_hysteresis + kFloatRounding) << scene;
    EXPECT_LE(m.manifold_errors->normal_max, face_hysteresis + kFloatRounding) << scene;
    EXPECT_LE(m.manifold_errors->kept_max, 1e-12) << scene;  // a fresh answer is the answer
  }
}

}  // namespace
}  // namespace dyop::box2d::testing
