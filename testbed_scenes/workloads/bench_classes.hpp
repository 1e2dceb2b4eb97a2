#pragma once
// The input classes of the benchmarks and of `dyop bench`: what a narrow phase meets after a
// broad phase, each a set of distinct seeded pairs (at least 8192 in the reports, so that the
// branch predictor cannot learn the set).

#include <cstdint>
#include <vector>

#include "workloads/pair_classes.hpp"

namespace dyop::workloads {

enum class BenchClass {
  Overlapping,   // general pairs that penetrate
  Mixed,         // general pairs, a third penetrating, the rest apart with overlapping AABBs
  Separated,     // general pairs apart whose AABBs overlap (what a broad phase lets through)
  Slivers,       // one or both triangles with aspect ratio 1e-1 to 1e-7
  NearParallel,  // an edge of B at 1e-14 to 1e-3 rad from an edge of A, just in or out
  Far,           // general pairs 1 to 1e6 units from the origin
};

inline constexpr BenchClass all_bench_classes[] = {
    BenchClass::Overlapping,  BenchClass::Mixed, BenchClass::Separated,
    BenchClass::Slivers,      BenchClass::NearParallel, BenchClass::Far};

/// "overlapping", "mixed", "separated", "slivers", "near-parallel", "far".
const char* name(BenchClass c);

/// `count` distinct pairs of class `c`, the same for the same seed.
std::vector<RawPair> make_bench_pairs(BenchClass c, int count, std::uint64_t seed);

}  // namespace dyop::workloads
