#pragma once
/// \file
/// The one taxonomy of input: every class of triangle pairs the tests, `dyop bench`, `dyop stress`,
/// the Google Benchmark suite and the fuzz seeds name, each made by one seeded generator
/// (`workloads/random.hpp`), so that a seed gives the same pairs with any compiler and library.
/// Each consumer takes a named subset: `test_classes`, `bench_classes`, `stress_classes`.

#include <cstdint>
#include <vector>

#include "workloads/precision.hpp"
#include "workloads/raw_pair.hpp"

namespace dyop::workloads {

enum class InputClass {
  General,       ///< random triangles of size ~1, overlapping about a third of the time
  Overlapping,   ///< general pairs that penetrate
  Mixed,         ///< general pairs, a third penetrating, the rest apart with overlapping boxes
  Separated,     ///< general pairs apart whose boxes overlap (what a broad phase lets through)
  Apart,         ///< clearly apart: B 2.5 to 10 units from A
  AxisAligned,   ///< vertical and horizontal edges, half the time on one line with the other's
  Sliver,        ///< one or both triangles with aspect ratio 1e-1 down to 1e-7
  NearParallel,  ///< an edge of B at 1e-14 to 1e-3 rad from an edge of A, just in or out
  Far,           ///< general pairs 1 to `max_offset` units from the origin
  Scale,         ///< general pairs scaled by 1e-8 to 1e8; a quarter with B up to 1e6 smaller
  Contained,     ///< B in A or A in B: about the centroid, at a shared vertex, on an edge
  Identical,     ///< A and B the same triangle, any winding
  Touching,      ///< exactly touching in double: vertex or edge of B on an axis-aligned edge of A
  TouchingUlp,   ///< B's vertex (a quarter: B's edge) within 2 ulps of A's edge, outside or in
  NearlyCollinear,  ///< A flat to 0.1 to 1000 times the validation tolerance: some are rejected
};

/// What the tests check on, each pair through `make_valid_pairs`.
inline constexpr InputClass test_classes[] = {
    InputClass::General,  InputClass::AxisAligned, InputClass::Sliver,    InputClass::NearParallel,
    InputClass::Far,      InputClass::Scale,       InputClass::Contained, InputClass::Identical,
    InputClass::Touching, InputClass::Apart};

/// What `dyop bench` and the Google Benchmark suite time: what a narrow phase meets after a broad
/// phase.
inline constexpr InputClass bench_classes[] = {InputClass::Overlapping,  InputClass::Mixed,
                                               InputClass::Separated,    InputClass::Sliver,
                                               InputClass::NearParallel, InputClass::Far};

/// What `dyop stress` measures: where floating-point trouble lives.
inline constexpr InputClass stress_classes[] = {
    InputClass::Sliver,    InputClass::NearParallel, InputClass::AxisAligned,
    InputClass::Scale,     InputClass::Far,          InputClass::TouchingUlp,
    InputClass::Identical, InputClass::Contained,    InputClass::NearlyCollinear};

/// The class's one spelling, the enumerator's name in lower case with hyphens: "general",
/// "overlapping", "mixed", "separated", "apart", "axis-aligned", "sliver", "near-parallel", "far",
/// "scale", "contained", "identical", "touching", "touching-ulp", "nearly-collinear".
const char* name(InputClass c);

/// Farthest distance of class Far from the origin. Why these values: at 1e7 a double keeps nine
/// digits of a unit pair, at 1e4 a float keeps three (its ulp there is 1e-3).
double max_offset(Precision p);

/// `count` pairs of class `c` made for `precision` and rounded to it, the same for the same seed.
/// Either triangle may be invalid in that precision (`Triangle<T>::make` says why): a float sliver,
/// a nearly collinear triangle, a triangle scaled below the smallest size.
std::vector<RawPair> make_pairs(InputClass c, int count, std::uint64_t seed, Precision precision);

/// `count` pairs of class `c` in double whose triangles are both valid (the tests' input): the
/// same draws as `make_pairs`, the invalid pairs skipped.
std::vector<RawPair> make_valid_pairs(InputClass c, int count, std::uint64_t seed);

}  // namespace dyop::workloads
