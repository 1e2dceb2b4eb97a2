#include "backend.hpp"
#include "body_edges.hpp"
#include "installation.hpp"
#include "triangle_contact.hpp"

namespace dyop::box2d {

InstallResult install(Backend backend, const Config& config) {
  if (!is_backend(backend)) {
    return {InstallStatus::UnsupportedMethod,
            "refused: not a backend of the plug-in (dyop::box2d::all_backends)"};
  }
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
  now.find_internal_edges = config.internal_edges && info(backend).allowed_directions;
  reset_stats();
  return {InstallStatus::Done, "installed"};
}

InstallResult uninstall() {
  detail::Installation& now = detail::installation();
  if (!now.backend) return {InstallStatus::Done, "not installed: Box2D's own contact is registered"};
  detail::register_polygon_contact(now.box2d_own);
  now.backend.reset();
  now.find_internal_edges = false;
  detail::forget_bodies();
  return {InstallStatus::Done, "uninstalled: Box2D's own contact is registered again"};
}

std::optional<Backend> installed() { return detail::installation().backend; }

Config installed_config() { return detail::installation().config; }

}  // namespace dyop::box2d
