#pragma once
// Seeded random triangle pairs by class of input, shared by the tests (and the same classes the
// benchmarks and the stress command report on). Every pair is two valid triangles in double.

#include <array>
#include <cstdint>
#include <vector>

#include "dyop/triangle.hpp"

namespace dyop::workloads {

enum class PairClass {
  General,        // random triangles of size ~1, overlapping about a third of the time
  AxisAligned,    // edges parallel to the axes (vertical edges included)
  Sliver,         // aspect ratios from 1e-1 down to 1e-7
  NearParallel,   // an edge of A nearly parallel to an edge of B (angles 1e-14 to 1e-3)
  FarFromOrigin,  // general pairs moved up to 1e6 units from the origin
  TinyAndHuge,    // sizes from 1e-6 to 1e6, both triangles of one pair alike in size
  Containment,    // one triangle inside the other
  Identical,      // A and B the same triangle (any winding)
  Touching,       // B moved so it touches A exactly along an axis-aligned edge or at a vertex
  Apart,          // clearly separated pairs
};

inline constexpr PairClass all_pair_classes[] = {
    PairClass::General,      PairClass::AxisAligned, PairClass::Sliver,
    PairClass::NearParallel, PairClass::FarFromOrigin, PairClass::TinyAndHuge,
    PairClass::Containment,  PairClass::Identical,   PairClass::Touching,
    PairClass::Apart};

const char* name(PairClass c);

/// Two triangles as the caller gives them: world coordinates, any winding.
struct RawPair {
  std::array<Vec2<double>, 3> a;
  std::array<Vec2<double>, 3> b;
};

/// `count` pairs of class `c`, the same for the same seed, each valid for Triangle<double>::make.
std::vector<RawPair> make_pairs(PairClass c, int count, std::uint64_t seed);

/// Builds both triangles (asserting validity is the caller's job: `ok()` on each).
template <class T>
struct BuiltPair {
  TriangleOrError<T> a;
  TriangleOrError<T> b;
};
template <class T>
BuiltPair<T> build(const RawPair& p) {
  auto cast = [](const Vec2<double>& v) { return Vec2<T>(T(v.x()), T(v.y())); };
  return {Triangle<T>::make(cast(p.a[0]), cast(p.a[1]), cast(p.a[2])),
          Triangle<T>::make(cast(p.b[0]), cast(p.b[1]), cast(p.b[2]))};
}

/// The union of both triangles' bounding boxes.
struct PairBox {
  Vec2<double> lo;
  Vec2<double> hi;
};
PairBox pair_box(const RawPair& p);

/// The pair's size: the diagonal of `pair_box` (unit of relative errors).
double pair_size(const RawPair& p);

}  // namespace dyop::workloads
