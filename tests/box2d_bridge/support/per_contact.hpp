#pragma once
// The per-contact installation every physics test of the bridge runs under: each backend of the
// plug-in, and Box2D's own contact.

#include <gtest/gtest.h>

#include <algorithm>
#include <optional>
#include <string>

#include "dyop/box2d.hpp"

namespace dyop::box2d::testing {

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

// Every contact but dyop-fast: its pivot, approximate by design, now and then takes a face that
// is not the minimum-depth axis, and some physics properties do not hold under it. Those are
// claimed for these contacts only; what dyop-fast holds instead is claimed under test names of
// its own (`...UnderDyopFast`), instantiated with `kDyopFastOnly`.
inline const Contact kContactsButDyopFast[] = {std::nullopt, Backend::Dyop, Backend::LinCanny,
                                               Backend::Sat, Backend::Epa,  Backend::Box2D};
inline const Contact kDyopFastOnly[] = {Backend::DyopFast};

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
