#include "backend.hpp"

namespace dyop::box2d {

const char* name(Backend b) {
  switch (b) {
    case Backend::Dyop: return "dyop";
    case Backend::DyopFast: return "dyop-fast";
    case Backend::LinCanny: return "lin-canny";
    case Backend::Sat: return "sat";
    case Backend::Epa: return "epa";
    case Backend::Box2D: return "box2d";
  }
  return "unknown";
}

const char* name(Skip s) {
  switch (s) {
    case Skip::Bounds: return "bounds";
    case Skip::WarmAxis: return "warm-axis";
  }
  return "unknown";
}

namespace detail {

std::optional<Backend> backend_of(Method m) {
  switch (m) {
    case Method::Dyop: return Backend::Dyop;
    case Method::DyopFast: return Backend::DyopFast;
    case Method::LinCanny: return Backend::LinCanny;
    case Method::Sat: return Backend::Sat;
    case Method::Epa: return Backend::Epa;
    case Method::DyopPaper: break;
  }
  return std::nullopt;
}

}  // namespace detail
}  // namespace dyop::box2d
