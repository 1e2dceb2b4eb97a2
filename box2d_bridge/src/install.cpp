#include "backend.hpp"
#include "installation.hpp"
#include "triangle_contact.hpp"

namespace dyop::box2d {

InstallResult install(Backend backend, const Config& config) {
  detail::Installation& now = detail::installation();
  if (now.backend == backend && now.config == config) {
    return {InstallStatus::Done, "already installed"};
  }
  if (!now.saved) {
    now.box2d_own = detail::polygon_contact_fcns();
    now.saved = true;
  }
  // Contacts already made, ours and Box2D's own, stay valid under any registration: see
  // TriangleContact::destroy. Ours read `now` at every evaluation, so they switch at the next step.
  detail::register_polygon_contact({&detail::TriangleContact::create,
                                    &detail::TriangleContact::destroy});
  now.backend = backend;
  now.config = config;
  reset_stats();
  return {InstallStatus::Done, "installed"};
}

InstallResult install(Method method, const Config& config) {
  const std::optional<Backend> backend = detail::backend_of(method);
  if (!backend) {
    return {InstallStatus::UnsupportedMethod,
            "refused: dyop-paper reproduces the paper's equations and is not offered to Box2D"};
  }
  return install(*backend, config);
}

InstallResult uninstall() {
  detail::Installation& now = detail::installation();
  if (!now.backend) return {InstallStatus::Done, "not installed: Box2D's own contact is registered"};
  detail::register_polygon_contact(now.box2d_own);
  now.backend.reset();
  return {InstallStatus::Done, "uninstalled: Box2D's own contact is registered again"};
}

std::optional<Backend> installed() { return detail::installation().backend; }

Config installed_config() { return detail::installation().config; }

}  // namespace dyop::box2d
