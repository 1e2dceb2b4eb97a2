#pragma once
// The hard input categories of `dyop stress`: seeded triangle pairs where floating-point trouble
// lives, in the precision under test. Unlike `make_pairs`, a pair may be invalid in that
// precision (a float-degenerate sliver, a triangle flatter than the validation tolerance): how
// the validation and the methods cope with it is what is measured.

#include <cstdint>
#include <vector>

#include "workloads/pair_classes.hpp"

namespace dyop::workloads {

enum class StressClass {
  Sliver,           // one or both triangles with aspect ratio 1e-1 down to 1e-7
  NearParallel,     // an edge of B at 1e-14 to 1e-3 rad from an edge of A, just in or out
  AxisAligned,      // vertical and horizontal edges, half the time on one line with the other's
  Scale,            // general pairs scaled by 1e-8 to 1e8; a quarter with B up to 1e6 smaller
  Offset,           // general pairs up to `max_offset` from the origin
  TouchingUlp,      // B's vertex (a quarter: B's edge) within an ulp of A's edge, outside or in
  Identical,        // A and B the same triangle, any winding
  Contained,        // B inside A or A inside B: about the centroid, at a shared vertex, on an edge
  NearlyCollinear,  // A flat to 0.1 to 1000 times the validation tolerance: some are rejected
};

inline constexpr StressClass all_stress_classes[] = {
    StressClass::Sliver,      StressClass::NearParallel, StressClass::AxisAligned,
    StressClass::Scale,       StressClass::Offset,       StressClass::TouchingUlp,
    StressClass::Identical,   StressClass::Contained,    StressClass::NearlyCollinear};

/// "sliver", "near-parallel", "axis-aligned", "scale", "offset", "touching-ulp", "identical",
/// "contained", "nearly-collinear".
const char* name(StressClass c);

/// The scalar a stress run measures.
enum class Precision { Double, Float };

/// "double", "float".
const char* name(Precision p);

/// Farthest distance of class Offset from the origin. Why these values: at 1e7 a double keeps
/// nine digits of a unit pair, at 1e4 a float keeps three (its ulp there is 1e-3).
double max_offset(Precision p);

/// `p` with every coordinate rounded to float (held exactly in double), so that the exact
/// reference sees exactly what a float program sees.
RawPair rounded_to_float(const RawPair& p);

/// `p` rounded to precision `precision` (unchanged for double).
RawPair rounded_to(Precision precision, const RawPair& p);

/// `count` pairs of class `c` for `precision`, already rounded to it, the same for the same seed.
/// Either triangle may be invalid in that precision (`Triangle<T>::make` says why).
std::vector<RawPair> make_stress_pairs(StressClass c, Precision precision, int count,
                                       std::uint64_t seed);

}  // namespace dyop::workloads
