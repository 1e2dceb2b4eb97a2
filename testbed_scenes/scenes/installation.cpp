#include "scenes/installation.hpp"

#include <stdexcept>
#include <string>

namespace dyop::scenes {

Installation::Installation(const Runner& runner, const box2d::Config& skips) {
  const box2d::InstallResult r = runner ? box2d::install(*runner, skips) : box2d::uninstall();
  if (!r.ok()) throw std::runtime_error(std::string("cannot install the backend: ") + r.message);
  box2d::reset_stats();
}

Installation::~Installation() { box2d::uninstall(); }

}  // namespace dyop::scenes
