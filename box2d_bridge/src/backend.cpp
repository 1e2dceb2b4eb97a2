#include "backend.hpp"

namespace dyop::box2d {

const char* name(Skip s) {
  switch (s) {
    case Skip::Bounds: return "bounds";
    case Skip::WarmAxis: return "warm-axis";
  }
  return "unknown";
}

}  // namespace dyop::box2d
