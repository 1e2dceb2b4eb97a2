#pragma once
/// \file
/// The check behind "no NaN, no inf on valid input" (`dyop stress`, the fuzz targets): every field
/// of a `Result` that its status and the query's level make valid is finite.

#include <cmath>

#include "dyop/result.hpp"

namespace dyop::workloads {

/// True when every field `level` makes valid in `r` is finite. An Invalid answer and the Overlap
/// level promise no number, so they pass.
template <class T>
bool finite_at(const Result<T>& r, Level level) {
  if (r.status == Status::Invalid || level == Level::Overlap) return true;
  bool ok = std::isfinite(r.separation) && std::isfinite(r.depth) && r.normal.allFinite();
  if (level >= Level::Contact) ok = ok && r.witness_a.allFinite() && r.witness_b.allFinite();
  if (level == Level::Manifold) {
    const Manifold<T>& m = r.manifold;
    ok = ok && m.point_count >= 0 && m.point_count <= 2 && m.normal.allFinite();
    for (int i = 0; i < m.point_count; ++i) {
      ok = ok && m.points[i].point.allFinite() && std::isfinite(m.points[i].separation);
    }
  }
  return ok;
}

}  // namespace dyop::workloads
