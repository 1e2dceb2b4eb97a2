#pragma once
// Shared by the bridge tests: real b2Worlds built from triangle fixtures (the scenes library's),
// and the per-backend installation every physics test runs under.

#include <box2d/box2d.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "dyop/box2d.hpp"
#include "scenes/world.hpp"

namespace dyop::box2d::testing {

// The worlds and shapes of the scenes library (testbed_scenes/scenes/world.hpp).
using scenes::add_body;
using scenes::add_split_box;
using scenes::add_triangle;
using scenes::add_triangle_ground;
using scenes::World;
constexpr int kStepsPerSecond = scenes::steps_per_second;

// Deepest overlap of the skins over the body's touching contacts (metres, 0 when none overlap):
// minus the least world-manifold separation, which Box2D measures between the skins. Box2D's
// position solver lets skins overlap by about b2_linearSlop at rest, by design.
inline float skin_penetration(b2Body* body) {
  float deepest = 0;
  for (b2ContactEdge* e = body->GetContactList(); e != nullptr; e = e->next) {
    const b2Contact* c = e->contact;
    if (!c->IsTouching()) continue;
    b2WorldManifold wm;
    c->GetWorldManifold(&wm);
    for (int i = 0; i < c->GetManifold()->pointCount; ++i)
      deepest = std::max(deepest, -wm.separations[i]);
  }
  return deepest;
}

// Every backend, plus nothing: Box2D's own b2PolygonContact (the plug-in not installed).
using Contact = std::optional<Backend>;

inline std::string contact_name(const Contact& c) {
  if (!c) return "box2d_own";
  std::string n = name(*c);
  std::replace(n.begin(), n.end(), '-', '_');
  return "via_plugin_" + n;
}

inline const Contact kAllContacts[] = {std::nullopt,      Backend::Dyop, Backend::DyopFast,
                                       Backend::LinCanny, Backend::Sat,  Backend::Epa,
                                       Backend::Box2D};

// A test run with one contact: installs the backend before the world exists, checks afterwards
// that every triangle pair was answered by it (no fallback to Box2D), and uninstalls.
class PerContact : public ::testing::TestWithParam<Contact> {
 protected:
  void SetUp() override {
    if (GetParam()) {
      const InstallResult r = install(*GetParam());
      ASSERT_TRUE(r.ok()) << r.message;
    }
  }
  void TearDown() override {
    if (GetParam()) {
      const Stats s = stats();
      EXPECT_EQ(s.fallbacks, 0u) << "pairs answered by Box2D instead of " << name(*GetParam());
      const InstallResult r = uninstall();
      EXPECT_TRUE(r.ok()) << r.message;
    }
  }
  std::string contact() const { return contact_name(GetParam()); }
};

inline std::string contact_param_name(const ::testing::TestParamInfo<Contact>& info) {
  return contact_name(info.param);
}

}  // namespace dyop::box2d::testing
