// fuzz_world's oracles on its seed corpus (fuzz/corpus/world/): the hand-made seeds and every input
// a fuzzing run found failing (`regress_*`, kept once fixed), played as the fuzzer plays them
// (fuzz/world_ops.hpp). One test per property; a failure names the input (print the operations
// with `fuzz_world --print FILE`, or DYOP_PRINT_SEQUENCES=1 here).
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "world_ops.hpp"

namespace dyop::fuzz {
namespace {

struct Seed {
  std::string name;
  std::vector<WorldOp> ops;
};

std::vector<Seed> corpus() {
  std::vector<Seed> seeds;
  for (const auto& entry : std::filesystem::directory_iterator(DYOP_WORLD_CORPUS)) {
    std::ifstream in(entry.path(), std::ios::binary);
    const std::vector<char> bytes{std::istreambuf_iterator<char>(in), {}};
    seeds.push_back(
        {entry.path().filename().string(),
         decode_world_ops(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size())});
    if (std::getenv("DYOP_PRINT_SEQUENCES")) {
      std::printf("%s:\n", seeds.back().name.c_str());
      play_world_ops(seeds.back().ops, Installs::AsWritten, stdout);
    }
  }
  return seeds;
}

TEST(WorldSequences, CorpusPlaysOperationsAndSteps) {
  const std::vector<Seed> seeds = corpus();
  ASSERT_GE(seeds.size(), 5u);
  for (const Seed& s : seeds) {
    const PlayResult r = play_world_ops(s.ops, Installs::AsWritten);
    EXPECT_GT(r.played, 0) << s.name;
    EXPECT_GT(r.steps, 0) << s.name;
  }
}

TEST(WorldSequences, PositionsStayFinite) {
  for (const Seed& s : corpus()) EXPECT_TRUE(judge_world_ops(s.ops).finite) << s.name;
}

TEST(WorldSequences, SameSequenceTwiceEndsTheSame) {
  for (const Seed& s : corpus()) EXPECT_TRUE(judge_world_ops(s.ops).repeatable) << s.name;
}

TEST(WorldSequences, Box2DBackendEqualsBox2DOwnContact) {
  for (const Seed& s : corpus()) EXPECT_TRUE(judge_world_ops(s.ops).box2d_is_own) << s.name;
}

TEST(WorldSequences, DyopEqualsSat) {
  for (const Seed& s : corpus()) EXPECT_TRUE(judge_world_ops(s.ops).dyop_is_sat) << s.name;
}

}  // namespace
}  // namespace dyop::fuzz
