// `Config`'s presets do what their names say: `all()` is the default, `no_skips()` turns off the
// skips alone, `off()` the skips, the internal-edge rule and recycling, and `none()` is
// `no_skips()` by its old, deprecated name. Checked field by field and in a world, by the counters.
#include <gtest/gtest.h>

#include "dyop/box2d.hpp"
#include "support/worlds.hpp"

namespace dyop::box2d::testing {
namespace {

// Split boxes resting on a triangulated ground for 2 s under `config`: the plug-in's counters.
Stats resting_pile(const Config& config) {
  EXPECT_TRUE(install(Backend::Dyop, config).ok());
  {
    World world;
    add_triangle_ground(world, 6.0f);
    for (int i = 0; i < 4; ++i) add_split_box(world, b2Vec2(-3.0f + 2.0f * i, 0.52f), 0.5f);
    for (int i = 0; i < 2 * kStepsPerSecond; ++i) world.step();
  }
  const Stats s = stats();
  uninstall();
  return s;
}

TEST(ConfigPresets, AllIsTheDefault) { EXPECT_TRUE(Config::all() == Config()); }

TEST(ConfigPresets, NoSkipsTurnsOffTheSkipsAlone) {
  const Config c = Config::no_skips();
  EXPECT_FALSE(c.bounds_early_out);
  EXPECT_FALSE(c.warm_axis);
  EXPECT_FALSE(c.lin_canny_cache);
  Config rest = Config::all();
  rest.bounds_early_out = rest.warm_axis = rest.lin_canny_cache = false;
  EXPECT_TRUE(c == rest);  // the rule, recycling and the routing as by default
  const Stats s = resting_pile(c);
  EXPECT_EQ(s.skips(Skip::Bounds) + s.skips(Skip::WarmAxis), 0u);
  EXPECT_GT(s.internal_edge_pairs, 0u);
  EXPECT_GT(s.recycled, 0u);
}

TEST(ConfigPresets, OffTurnsOffTheSkipsTheRuleAndRecycling) {
  const Config c = Config::off();
  EXPECT_FALSE(c.bounds_early_out || c.warm_axis || c.lin_canny_cache);
  EXPECT_FALSE(c.internal_edges);
  EXPECT_EQ(c.recycle_distance, 0.0f);
  EXPECT_FALSE(c.triangles_only);  // the routing stays: every family answered exactly
  EXPECT_TRUE(c.edges_and_chains);
  const Stats s = resting_pile(c);
  EXPECT_EQ(s.skips(Skip::Bounds) + s.skips(Skip::WarmAxis), 0u);
  EXPECT_EQ(s.internal_edge_pairs, 0u);
  EXPECT_EQ(s.recycled, 0u);
  EXPECT_GT(s.manifolds, 0u);
  const Stats defaults = resting_pile(Config::all());  // the same world keeps and skips by default
  EXPECT_GT(defaults.skips(Skip::Bounds) + defaults.skips(Skip::WarmAxis), 0u);
  EXPECT_GT(defaults.recycled, 0u);
}

TEST(ConfigPresets, NoneIsNoSkipsByItsOldName) {
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"
  EXPECT_TRUE(Config::none() == Config::no_skips());
#pragma GCC diagnostic pop
}

}  // namespace
}  // namespace dyop::box2d::testing
