// libFuzzer target: a byte string played as a sequence of operations on one to three Box2D 2.4.1
// worlds with the plug-in installed, reconfigured and uninstalled among them (format and player:
// world_ops.hpp). Each input is played six times.
//
// What it asserts, besides "no crash, no sanitizer report, no Box2D assert":
// - no body's position or angle goes NaN or infinite (every input is finite);
// - the sequence played twice in one process ends with the same hash (nothing leaks between
//   plays or worlds);
// - every install made `box2d` ends bit-identical to the plug-in never installed (Box2D's own
//   contact);
// - every install made `dyop` ends bit-identical to every install made `sat`.
// A failure prints the sequence as a list of operations and aborts. `--print` prints every input
// it runs (replay: fuzz_world --print FILE); DYOP_WORLD_STATS=1 prints, at exit, how many inputs,
// operations and steps ran.
#include <cstdio>
#include <cstdlib>
#include <string_view>

#include "world_ops.hpp"

namespace {

bool g_print = false;

struct Totals {
  long inputs = 0, played = 0, skipped = 0, steps = 0;
};
Totals g_totals;

void print_totals() {
  std::fprintf(stderr,
               "fuzz_world: %ld inputs, each played 6 times; per play %ld operations played, "
               "%ld skipped, %ld steps\n",
               g_totals.inputs, g_totals.played, g_totals.skipped, g_totals.steps);
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv) {
  for (int i = 1; i < *argc; ++i) {
    if (std::string_view((*argv)[i]) == "--print") g_print = true;
  }
  if (std::getenv("DYOP_WORLD_STATS")) std::atexit(print_totals);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace dyop::fuzz;
  const std::vector<WorldOp> ops = decode_world_ops(data, size);
  if (g_print) play_world_ops(ops, Installs::AsWritten, stdout);
  const WorldVerdict verdict = judge_world_ops(ops);
  ++g_totals.inputs;
  g_totals.played += verdict.as_written.played;
  g_totals.skipped += verdict.as_written.skipped;
  g_totals.steps += verdict.as_written.steps;
  if (const char* failure = verdict.failure()) {
    std::fprintf(stderr, "fuzz_world: %s, on this sequence (as written):\n", failure);
    play_world_ops(ops, Installs::AsWritten, stderr);
    std::abort();
  }
  return 0;
}
