#include "installation.hpp"
#include "triangle_contact.hpp"

namespace dyop::box2d {

InstallResult install(Backend backend, const Config& config) {
  if (!is_backend(backend)) {
    return {InstallStatus::UnsupportedMethod,
            "refused: not a backend of the plug-in (dyop::box2d::all_backends)"};
  }
  detail::Installation& now = detail::installation();
  if (now.setting.backend == backend && now.setting.config == config) {
    return {InstallStatus::Done, "already installed"};
  }
  if (!now.saved) {
    now.box2d_own = detail::polygon_contact_fcns();
    now.saved = true;
  }
  // Contacts already made, ours and Box2D's own, stay valid under any registration: see
  // TriangleContact::destroy. Ours read the setting at every evaluation, so they switch at the
  // next step, and take their internal-edge masks again under the new epoch.
  detail::register_polygon_contact({&detail::TriangleContact::create,
                                    &detail::TriangleContact::destroy});
  const std::uint8_t epoch = now.setting.epoch == 255 ? 1 : now.setting.epoch + 1;
  now.setting = detail::Setting(backend, config, static_cast<std::uint8_t>(epoch));
  reset_stats();
  return {InstallStatus::Done, "installed"};
}

InstallResult uninstall() {
  detail::Installation& now = detail::installation();
  if (!now.setting.backend) {
    return {InstallStatus::Done, "not installed: Box2D's own contact is registered"};
  }
  detail::register_polygon_contact(now.box2d_own);
  // The config and the epoch stay: `installed_config()` is the last install's.
  now.setting.backend.reset();
  now.setting.method.reset();
  now.setting.internal_edges = false;
  return {InstallStatus::Done, "uninstalled: Box2D's own contact is registered again"};
}

std::optional<Backend> installed() { return detail::installation().setting.backend; }

Config installed_config() { return detail::installation().setting.config; }

}  // namespace dyop::box2d
