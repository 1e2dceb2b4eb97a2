// One answer from every batch kernel: each kernel the CPU has (AVX2, AVX-512) gives every row the
// same bits as the portable kernel (status, separation, normal), at the Overlap and Depth levels,
// on every input class (the tests', the benchmarks' and `dyop stress`'s, with its seed, each pair
// also swapped and rewound), on the method fuzzers' seed corpus, and on rows the vector lanes
// hand to the portable code or reject. Compared as bit patterns, not within a tolerance.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

#include "dyop/batch.hpp"
#include "fuzz_input.hpp"
#include "workloads/batch_arrays.hpp"
#include "workloads/input_classes.hpp"

namespace dyop {
namespace {

using workloads::InputClass;
using workloads::RawPair;
using V2 = Vec2<double>;

constexpr BatchKernel kForced[] = {BatchKernel::Portable, BatchKernel::Avx2, BatchKernel::Avx512};

constexpr InputClass kEveryClass[] = {
    InputClass::General,   InputClass::Overlapping,  InputClass::Mixed,
    InputClass::Separated, InputClass::Apart,        InputClass::AxisAligned,
    InputClass::Sliver,    InputClass::NearParallel, InputClass::Far,
    InputClass::Scale,     InputClass::Contained,    InputClass::Identical,
    InputClass::Touching,  InputClass::TouchingUlp,  InputClass::NearlyCollinear};

constexpr std::uint64_t kStressSeed = 2027;  // `dyop stress`'s default (StressOptions::seed)

template <class T>
workloads::Precision precision_of() {
  return std::is_same_v<T, float> ? workloads::Precision::Float : workloads::Precision::Double;
}

// The pairs of a batch, each also swapped and with A rewound (`push_variants`).
struct Rows {
  std::vector<RawPair> pairs;

  void push(const RawPair& p) { pairs.push_back(p); }
  void push_variants(const RawPair& p) {
    RawPair rewound = p;
    std::swap(rewound.a[1], rewound.a[2]);
    for (const RawPair& q : {p, rewound}) {
      push(q);
      push({q.b, q.a});
    }
  }
  // As T holds them, one column per coordinate.
  template <class T>
  workloads::BatchArrays<T> arrays() const {
    return workloads::BatchArrays<T>(pairs.size(), [&](std::size_t k, int side, int i) {
      return Vec2<T>((side == 0 ? pairs[k].a[i] : pairs[k].b[i]).template cast<T>());
    });
  }
};

// What one kernel wrote for every row.
template <class T>
struct Answers {
  BatchError error = BatchError::None;
  std::vector<Status> status;
  std::vector<T> separation, normal_x, normal_y;
};

template <class T>
Answers<T> run(const workloads::BatchArrays<T>& rows, Level level, BatchKernel kernel) {
  Answers<T> a;
  const std::size_t n = rows.status.size();
  a.status.assign(n, Status::Invalid);
  a.separation.assign(n, T(0));
  a.normal_x.assign(n, T(0));
  a.normal_y.assign(n, T(0));
  a.error = penetrate_batch(
      rows.pairs(), level,
      BatchOutput<T>{a.status.data(), a.separation.data(), a.normal_x.data(), a.normal_y.data()},
      kernel);
  return a;
}

template <class T>
bool same_bits(T x, T y) {
  return std::memcmp(&x, &y, sizeof x) == 0;
}

// Every available vector kernel against the portable one, bit for bit, at both levels.
template <class T>
void expect_same_bits(const Rows& pairs, const std::string& what) {
  const workloads::BatchArrays<T> rows = pairs.arrays<T>();
  for (Level level : {Level::Overlap, Level::Depth}) {
    const Answers<T> want = run(rows, level, BatchKernel::Portable);
    EXPECT_EQ(want.error, BatchError::None);
    for (BatchKernel kernel : {BatchKernel::Avx2, BatchKernel::Avx512}) {
      if (!batch_kernel_available(kernel)) continue;
      const Answers<T> got = run(rows, level, kernel);
      ASSERT_EQ(got.error, BatchError::None);
      int differing = 0;
      for (std::size_t k = 0; k < pairs.pairs.size(); ++k) {
        const bool same = got.status[k] == want.status[k] &&
                          same_bits(got.separation[k], want.separation[k]) &&
                          same_bits(got.normal_x[k], want.normal_x[k]) &&
                          same_bits(got.normal_y[k], want.normal_y[k]);
        if (same) continue;
        if (++differing <= 5) {
          ADD_FAILURE() << what << ", " << name(kernel) << " at " << name(level) << ", row " << k
                        << ": status " << int(got.status[k]) << " / " << int(want.status[k])
                        << ", separation " << got.separation[k] << " / " << want.separation[k]
                        << ", normal (" << got.normal_x[k] << ", " << got.normal_y[k] << ") / ("
                        << want.normal_x[k] << ", " << want.normal_y[k] << ")";
        }
      }
      EXPECT_EQ(differing, 0) << what << ", " << name(kernel) << " at " << name(level);
    }
  }
}

template <class T>
class BatchKernelsAgree : public ::testing::Test {};

struct PrecisionNames {
  template <class T>
  static std::string GetName(int) {
    return std::is_same_v<T, float> ? "float" : "double";
  }
};

using Precisions = ::testing::Types<float, double>;
TYPED_TEST_SUITE(BatchKernelsAgree, Precisions, PrecisionNames);

// Every input class, made for T and rounded to it (invalid rows included), with the tests' seed
// and `dyop stress`'s: 15 classes × 2 seeds × 1,500 pairs × 4 variants.
TYPED_TEST(BatchKernelsAgree, EveryKernelGivesThePortableBitsOnEveryInputClass) {
  using T = TypeParam;
  for (InputClass c : kEveryClass) {
    for (std::uint64_t seed : {std::uint64_t{5}, kStressSeed}) {
      Rows rows;
      for (const RawPair& p : workloads::make_pairs(c, 1500, seed, precision_of<T>())) {
        rows.push_variants(p);
      }
      expect_same_bits<T>(rows, std::string(workloads::name(c)) + " seed " + std::to_string(seed));
    }
  }
}

// The method fuzzers' seed corpus (fuzz/corpus/methods): every input of T's precision, at each
// lane of a block of 16 and in the tail.
TYPED_TEST(BatchKernelsAgree, EveryKernelGivesThePortableBitsOnTheFuzzCorpus) {
  using T = TypeParam;
  Rows rows;
  int inputs = 0;
  for (const auto& entry : std::filesystem::directory_iterator(DYOP_FUZZ_CORPUS)) {
    std::ifstream file(entry.path(), std::ios::binary);
    const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(file)),
                                          std::istreambuf_iterator<char>());
    const fuzz::FuzzInput in = fuzz::decode(bytes.data(), bytes.size());
    if (in.is_float != std::is_same_v<T, float>) continue;
    ++inputs;
    for (int copy = 0; copy < 17; ++copy) rows.push_variants(in.pair());
  }
  EXPECT_GT(inputs, 10);
  expect_same_bits<T>(rows, "fuzz corpus");
}

// Rows whose squared edge lengths the vector lanes' estimate cannot take (redone portably), rows
// Triangle<T>::make rejects (non-finite, too large, repeated vertex, flat), and the worked cases
// of batch_test, mixed with ordinary rows at every lane position.
TYPED_TEST(BatchKernelsAgree, EveryKernelGivesThePortableBitsOnRedoneAndInvalidRows) {
  using T = TypeParam;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const double huge = 4.0 * double(max_coordinate<T>());
  const RawPair good{{V2(0, 0), V2(2, 0), V2(0, 2)}, {V2(1, 1), V2(3, 1), V2(1, 3)}};
  std::vector<RawPair> special = {
      {{V2(nan, 0), V2(2, 0), V2(0, 2)}, good.b},
      {good.a, {V2(1, 1), V2(inf, 1), V2(1, 3)}},
      {{V2(huge, 0), V2(2, 0), V2(0, 2)}, good.b},
      {good.a, {V2(1, 1), V2(1, 1), V2(1, 3)}},
      {{V2(0, 0), V2(1, 1), V2(2, 2)}, good.b},
      {{V2(0, 0), V2(4, 0), V2(2, 4)}, {V2(2, 0.5), V2(1, -2), V2(3, -2)}},
      {{V2(0, 0), V2(-1, 0), V2(0, -1)}, {V2(1, 1), V2(2, 1), V2(1, 2)}},
      {{V2(-5, 0), V2(0, -5), V2(5, 0)}, {V2(-1, 0), V2(1, 0), V2(0, 1)}},
  };
  for (const RawPair& p : workloads::make_valid_pairs(InputClass::General, 40, 4)) {
    const double beyond = std::is_same_v<T, float> ? 1e30 : 1e150;  // T holds the coordinates
    for (double unit : {1e-25, 1e-11, 1e17, 1e25, beyond}) {
      RawPair scaled = p;
      for (V2& v : scaled.a) v *= unit;
      for (V2& v : scaled.b) v *= unit;
      special.push_back(scaled);
    }
  }
  const auto ordinary = workloads::make_valid_pairs(InputClass::Mixed, 300, 6);
  Rows rows;
  for (std::size_t k = 0; k < ordinary.size(); ++k) {
    rows.push_variants(ordinary[k]);
    rows.push_variants(special[k % special.size()]);
  }
  expect_same_bits<T>(rows, "redone and invalid rows");
}

// Runs of whole blocks without a pair apart (overlapping pairs) between runs of blocks with pairs
// apart: the vector kernels settle a block's pairs apart with its geometry kept or computed again,
// as the block before it turned out, and either form must give the portable bits.
TYPED_TEST(BatchKernelsAgree, EveryKernelGivesThePortableBitsWhenBlocksAlternateBetweenKinds) {
  using T = TypeParam;
  constexpr std::size_t kWidest = 16;  // the widest block; narrower ones divide it
  Rows candidates;
  for (const RawPair& p : workloads::make_valid_pairs(InputClass::Overlapping, 600, 8)) {
    candidates.push(p);
  }
  const Answers<T> depth = run(candidates.arrays<T>(), Level::Depth, BatchKernel::Portable);
  std::vector<RawPair> overlapping;  // penetrating: no distance needed, at either level
  for (std::size_t k = 0; k < candidates.pairs.size(); ++k) {
    if (depth.status[k] == Status::Penetrating) overlapping.push_back(candidates.pairs[k]);
  }
  ASSERT_GT(overlapping.size(), 500u);
  const auto apart = workloads::make_valid_pairs(InputClass::Mixed, 600, 9);
  Rows rows;
  std::size_t next_overlapping = 0, next_apart = 0;
  for (std::size_t overlapping_blocks : {1, 2, 3}) {
    for (std::size_t apart_blocks : {1, 2, 3}) {
      for (std::size_t k = 0; k < overlapping_blocks * kWidest; ++k) {
        rows.push(overlapping[next_overlapping++ % overlapping.size()]);
      }
      for (std::size_t k = 0; k < apart_blocks * kWidest; ++k) {
        rows.push(apart[next_apart++ % apart.size()]);
      }
    }
  }
  expect_same_bits<T>(rows, "blocks alternating between kinds");
}

// A kernel the CPU lacks is refused with a clear error and nothing written; an available one runs.
TEST(BatchKernelChoice, ForcingAKernelTheCpuLacksIsRefusedAndWritesNothing) {
  const RawPair p{{V2(0, 0), V2(1, 0), V2(0, 1)}, {V2(2, 0), V2(3, 0), V2(2, 1)}};
  Rows rows;
  rows.push(p);
  const workloads::BatchArrays<double> one = rows.arrays<double>();
  for (BatchKernel kernel : kForced) {
    Status status = Status::Invalid;
    const BatchError e = penetrate_batch(one.pairs(), Level::Overlap, {&status}, kernel);
    if (batch_kernel_available(kernel)) {
      EXPECT_EQ(e, BatchError::None) << name(kernel);
      EXPECT_EQ(status, Status::Separated) << name(kernel);
    } else {
      EXPECT_EQ(e, BatchError::KernelUnavailable) << name(kernel);
      EXPECT_EQ(status, Status::Invalid) << name(kernel);
      EXPECT_NE(std::string(describe(e)).find("unavailable"), std::string::npos);
    }
    EXPECT_EQ(batch_kernel_used(kernel), kernel);
  }
  EXPECT_TRUE(batch_kernel_available(BatchKernel::Portable));
}

// Auto runs the widest kernel available here, and names it.
TEST(BatchKernelChoice, AutoRunsTheWidestAvailableKernel) {
  const BatchKernel used = batch_kernel_used(BatchKernel::Auto);
  EXPECT_TRUE(batch_kernel_available(used));
  EXPECT_NE(used, BatchKernel::Auto);
  const BatchKernel widest = batch_kernel_available(BatchKernel::Avx512) ? BatchKernel::Avx512
                             : batch_kernel_available(BatchKernel::Avx2) ? BatchKernel::Avx2
                                                                         : BatchKernel::Portable;
  EXPECT_EQ(used, widest);
  for (BatchKernel k :
       {BatchKernel::Auto, BatchKernel::Portable, BatchKernel::Avx2, BatchKernel::Avx512}) {
    EXPECT_GT(std::string(name(k)).size(), 0u);
  }
  EXPECT_EQ(std::string(name(BatchKernel::Avx512)), "avx512");
}

}  // namespace
}  // namespace dyop
