#include "dyop/box2d_measurement.hpp"
#include "installation.hpp"
#include "contact.hpp"

namespace dyop::box2d {

namespace {

constexpr InstallResult kNotABackend = {
    InstallStatus::UnsupportedMethod,
    "refused: not a backend of the plug-in (dyop::box2d::all_backends)"};

// Registers, for `taken_pairs[i]`, the plug-in's create function (`ours`) or Box2D's own, with
// the plug-in's destroy function (see `Contact::destroy`).
void register_taken_pair(int i, bool ours) {
  const auto k = static_cast<std::size_t>(i);
  const detail::Installation& now = detail::installation();
  detail::register_contact(
      {ours ? &detail::Contact::create : now.box2d_own[k].create, &detail::Contact::destroy},
      detail::taken_pairs[k]);
}

// Installs `backend` with `config`; `never_recompute`: the measurement floor.
InstallResult install_setting(Backend backend, const Config& config, bool never_recompute) {
  if (static_cast<int>(backend) >= backend_count) return kNotABackend;
  detail::Installation& now = detail::installation();
  if (now.setting.backend == backend && now.setting.config == config &&
      now.setting.never_recompute == never_recompute) {
    return {InstallStatus::Done, "already installed"};
  }
  if (!now.saved) {
    for (int i = 0; i < detail::taken_pair_count; ++i) {
      now.box2d_own[static_cast<std::size_t>(i)] =
          detail::contact_fcns(detail::taken_pairs[static_cast<std::size_t>(i)]);
    }
    now.saved = true;
  }
  // Contacts already made, ours and Box2D's own, stay valid under any registration: see
  // Contact::destroy. Ours read the setting at every evaluation, so they switch at the
  // next step, and take their internal-edge masks again (and drop any kept manifold) under the
  // new epoch. Our destroy function stays registered for every pair either way.
  for (int i = 0; i < detail::taken_pair_count; ++i) {
    register_taken_pair(
        i, detail::takes_pair(config, detail::taken_pairs[static_cast<std::size_t>(i)]));
  }
  const std::uint8_t epoch = now.setting.epoch == 255 ? 1 : now.setting.epoch + 1;
  now.setting = detail::Setting(backend, config, static_cast<std::uint8_t>(epoch));
  now.setting.never_recompute = never_recompute;
  reset_stats();
  return {InstallStatus::Done,
          never_recompute ? "installed (never recomputing: measurement only)" : "installed"};
}

}  // namespace

std::optional<Backend> parse_backend(std::string_view s) {
  if (s == name(Backend::Box2D)) return Backend::Box2D;
  const std::optional<Method> m =
      parse_method(s, [](const MethodInfo& row) { return row.simulation(); });
  return m ? backend_of(*m) : std::nullopt;
}

InstallResult install(Method method, const Config& config) {
  const std::optional<Backend> backend = backend_of(method);
  return backend ? install(*backend, config) : kNotABackend;
}

InstallResult install(Backend backend, const Config& config) {
  return install_setting(backend, config, false);
}

InstallResult measurement::install_never_recompute(Backend backend, const Config& config) {
  return install_setting(backend, config, true);
}

InstallResult uninstall() {
  detail::Installation& now = detail::installation();
  if (!now.setting.backend) {
    return {InstallStatus::Done, "not installed: Box2D's own contact is registered"};
  }
  // Box2D's own create functions; our destroy function stays, as it frees every contact of these
  // pairs as what it is (ours are not in the class Box2D's own destroy functions free).
  for (int i = 0; i < detail::taken_pair_count; ++i) register_taken_pair(i, false);
  // The config and the epoch stay: `installed_config()` is the last install's.
  now.setting.backend.reset();
  now.setting.method.reset();
  now.setting.internal_edges = false;
  now.setting.never_recompute = false;
  return {InstallStatus::Done, "uninstalled: Box2D's own contact is registered again"};
}

std::optional<Backend> installed() { return detail::installation().setting.backend; }

Config installed_config() { return detail::installation().setting.config; }

}  // namespace dyop::box2d
