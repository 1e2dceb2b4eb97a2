#include "stats.hpp"

namespace dyop::box2d {

Stats stats() { return detail::counters(); }

void reset_stats() { detail::counters() = Stats{}; }

}  // namespace dyop::box2d
