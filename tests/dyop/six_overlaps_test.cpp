// The six overlaps every exact method starts from (`detail::all_overlaps`): its float kernel in SSE
// registers gives the generic kernel's bits, the sign of a zero included, on every input class
// (touching pairs make the zeros), with the caller's winding either way.
#include <gtest/gtest.h>

#include <array>
#include <cstring>

#include "detail/axis_overlap.hpp"
#include "workloads/input_classes.hpp"
#include "workloads/raw_pair.hpp"

namespace dyop::workloads {
namespace {

TEST(SixOverlaps, TheVectorKernelGivesTheGenericKernelsBits) {
  int compared = 0;
  int zeros = 0;
  for (InputClass c : test_classes) {
    for (const RawPair& p : make_valid_pairs(c, 2000, 73)) {
      const auto f = build<float>(p);
      if (!f.a.ok() || !f.b.ok()) continue;
      for (const bool swapped : {false, true}) {
        const detail::PairFrame<float> frame =
            swapped ? detail::PairFrame<float>(f.b.triangle, f.a.triangle)
                    : detail::PairFrame<float>(f.a.triangle, f.b.triangle);
        const std::array<float, 6> generic = detail::all_overlaps<float>(frame);
        const std::array<float, 6> vector = detail::all_overlaps(frame);
        for (int k = 0; k < 6; ++k) {
          ASSERT_EQ(std::memcmp(&vector[k], &generic[k], sizeof(float)), 0)
              << name(c) << " axis " << k << ": " << vector[k] << " against " << generic[k];
          zeros += generic[k] == 0;
        }
        ++compared;
      }
    }
  }
  EXPECT_GT(compared, 30000);
  EXPECT_GT(zeros, 100);  // the touching classes reach the zeros
}

}  // namespace
}  // namespace dyop::workloads
