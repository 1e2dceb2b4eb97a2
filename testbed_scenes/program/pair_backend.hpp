#pragma once
/// \file
/// The narrow-phase backends the command line can run on a pair of triangles: every
/// `dyop::Method`, and Box2D's own `b2CollidePolygons` when built with Box2D.

#include <string>
#include <vector>

#include "dyop/result.hpp"
#include "dyop/triangle.hpp"

namespace dyop::cli {

/// One backend at `Level::Depth`.
struct PairBackend {
  std::string name;  ///< command-line spelling: "dyop", ..., "box2d"
  /// Double-precision run; nullptr when the backend runs in float only (box2d).
  Result<double> (*run_double)(const Triangle<double>&, const Triangle<double>&) = nullptr;
  /// Float run.
  Result<float> (*run_float)(const Triangle<float>&, const Triangle<float>&) = nullptr;
};

/// Every backend of this build, methods first in `dyop::pair_methods` order.
std::vector<PairBackend> pair_backends();

/// The result of a float run widened to double (for one output path).
Result<double> widen(const Result<float>& r);

}  // namespace dyop::cli
