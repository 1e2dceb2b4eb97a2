#include "dyop/result.hpp"

namespace dyop {

const char* name(Level level) {
  switch (level) {
    case Level::Overlap:
      return "overlap";
    case Level::Depth:
      return "depth";
    case Level::Contact:
      return "contact";
    case Level::Manifold:
      return "manifold";
  }
  return "unknown";
}

const char* describe(InvalidReason r) {
  switch (r) {
    case InvalidReason::None:
      return "no reason: the result is not Invalid";
    case InvalidReason::NotPairMethod:
      return "not a per-pair method: see dyop::pair_methods";
    case InvalidReason::PaperVerticalEdge:
      return "vertical edge: slope-intercept form (paper eq. 3) has no slope";
    case InvalidReason::PaperVertexAtOrigin:
      return "edge vertex P at the origin: paper eq. 8 divides by |P| = 0";
    case InvalidReason::PaperSlopeOverflow:
      return "slope overflows: edge too steep for slope-intercept form";
  }
  return "unknown invalid reason";
}

}  // namespace dyop
