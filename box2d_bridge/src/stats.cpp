#include "stats.hpp"

namespace dyop::box2d {

namespace detail {

Stats& counters() {
  static Stats live;
  return live;
}

}  // namespace detail

Stats stats() { return detail::counters(); }

void reset_stats() { detail::counters() = Stats{}; }

}  // namespace dyop::box2d
