#include "workloads/bench_classes.hpp"

#include "dyop/sat.hpp"

namespace dyop::workloads {
namespace {

bool penetrating(const RawPair& p) {
  const auto t = build<double>(p);
  return sat(t.a.triangle, t.b.triangle, Query<double>{Level::Overlap}).status ==
         Status::Penetrating;
}

bool boxes_overlap(const RawPair& p) {
  const Vec2<double> lo_a = p.a[0].cwiseMin(p.a[1]).cwiseMin(p.a[2]);
  const Vec2<double> hi_a = p.a[0].cwiseMax(p.a[1]).cwiseMax(p.a[2]);
  const Vec2<double> lo_b = p.b[0].cwiseMin(p.b[1]).cwiseMin(p.b[2]);
  const Vec2<double> hi_b = p.b[0].cwiseMax(p.b[1]).cwiseMax(p.b[2]);
  return (lo_a.array() <= hi_b.array()).all() && (lo_b.array() <= hi_a.array()).all();
}

// General pairs, drawn in batches, kept by `want(index_in_output, pair)`.
template <class Want>
std::vector<RawPair> filtered(int count, std::uint64_t seed, Want want) {
  std::vector<RawPair> out;
  out.reserve(static_cast<std::size_t>(count));
  for (std::uint64_t batch = 0; static_cast<int>(out.size()) < count; ++batch) {
    for (const RawPair& p : make_pairs(PairClass::General, 4096, seed * 7919 + batch)) {
      if (static_cast<int>(out.size()) < count && want(static_cast<int>(out.size()), p)) {
        out.push_back(p);
      }
    }
  }
  return out;
}

}  // namespace

const char* name(BenchClass c) {
  switch (c) {
    case BenchClass::Overlapping: return "overlapping";
    case BenchClass::Mixed: return "mixed";
    case BenchClass::Separated: return "separated";
    case BenchClass::Slivers: return "slivers";
    case BenchClass::NearParallel: return "near-parallel";
    case BenchClass::Far: return "far";
  }
  return "unknown";
}

std::vector<RawPair> make_bench_pairs(BenchClass c, int count, std::uint64_t seed) {
  switch (c) {
    case BenchClass::Overlapping:
      return filtered(count, seed, [](int, const RawPair& p) { return penetrating(p); });
    case BenchClass::Mixed:
      // A third penetrate, at positions picked by a hash: no period a branch predictor could learn.
      return filtered(count, seed, [](int i, const RawPair& p) {
        const bool want_penetrating = (static_cast<std::uint32_t>(i) * 2654435761u >> 16) % 3 == 0;
        return penetrating(p) == want_penetrating && boxes_overlap(p);
      });
    case BenchClass::Separated:
      return filtered(count, seed,
                      [](int, const RawPair& p) { return !penetrating(p) && boxes_overlap(p); });
    case BenchClass::Slivers: return make_pairs(PairClass::Sliver, count, seed);
    case BenchClass::NearParallel: return make_pairs(PairClass::NearParallel, count, seed);
    case BenchClass::Far: return make_pairs(PairClass::FarFromOrigin, count, seed);
  }
  return {};
}

}  // namespace dyop::workloads
