#include "backend.hpp"
#include "contact_registry.hpp"
#include "triangle_contact.hpp"

namespace dyop::box2d {
namespace {

std::optional<Backend> active;
Config active_config;
// What was registered for polygon pairs before the first install: Box2D's own b2PolygonContact
// (its functions are not exported, so they can only be saved from the registry).
detail::PolygonContactFcns saved;

constexpr InstallResult contacts_exist{
    InstallStatus::ContactsExist,
    "refused: polygon contacts made by the DyOP-PD plug-in still exist; Box2D frees a contact with "
    "the size registered when it is destroyed, so the registration cannot change under a live "
    "contact (destroy the bodies that touch first; see dyop::box2d::live_contacts())"};

bool same(const Config& x, const Config& y) {
  return x.bounds_early_out == y.bounds_early_out && x.shape_cache == y.shape_cache &&
         x.warm_axis == y.warm_axis && x.lin_canny_cache == y.lin_canny_cache &&
         x.reuse_unmoved == y.reuse_unmoved;
}

}  // namespace

InstallResult install(Backend backend, const Config& config) {
  if (active == backend && same(active_config, config)) {
    return {InstallStatus::Done, "already installed"};
  }
  if (detail::TriangleContact::live() > 0) return contacts_exist;
  if (!active) saved = detail::polygon_contact_fcns();
  detail::TriangleContact::use(backend, config);
  active_config = config;
  detail::register_polygon_contact({&detail::TriangleContact::create,
                                    &detail::TriangleContact::destroy});
  active = backend;
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
  if (!active) return {InstallStatus::Done, "not installed: Box2D's own contact is registered"};
  if (detail::TriangleContact::live() > 0) return contacts_exist;
  detail::register_polygon_contact(saved);
  active.reset();
  return {InstallStatus::Done, "uninstalled: Box2D's own contact is registered again"};
}

std::optional<Backend> installed() { return active; }

Config installed_config() { return active_config; }

int live_contacts() { return detail::TriangleContact::live(); }

}  // namespace dyop::box2d
