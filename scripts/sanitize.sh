#!/usr/bin/env bash
# The whole test suite under AddressSanitizer + UndefinedBehaviorSanitizer (GCC), in build-asan/:
# configure, build the test programs only (with the `dyop` program, which the command-line tests
# run, and the examples, which run as tests; not the benchmarks), then ctest. Any sanitizer report aborts the test that
# made it, and the run fails. Box2D comes from Debian uninstrumented: ASan still checks every
# access our code makes.
#   SANITIZE_EXCLUDE  ctest -E regular expression of tests left out (default: the many-worlds
#                     resident-memory test, as ASan's quarantine holds freed memory on purpose;
#                     and the skip replays of the three largest scenes, rain, rain-tall and
#                     tumbler, 630 of the suite's 1,700 s under ASan: every other scene's skip
#                     replays run the same code under the sanitizers. SANITIZE_EXCLUDE= runs all)
set -euo pipefail
cd "$(dirname "$0")/.."
start=$SECONDS
sanitizers="-fsanitize=address,undefined -fno-sanitize-recover=all"
source scripts/generator.sh
dyop_fresh_tree build-asan
cmake -S . -B build-asan "${dyop_generator[@]}" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DCMAKE_CXX_FLAGS="$sanitizers -fno-omit-frame-pointer" \
      -DCMAKE_EXE_LINKER_FLAGS="$sanitizers" -DCMAKE_SHARED_LINKER_FLAGS="$sanitizers" \
      -DDYOP_BUILD_BENCH=OFF >/dev/null
cmake --build build-asan -j"$(nproc)" --target dyop_test_programs
echo "sanitize: built in $((SECONDS - start)) s" >&2

export ASAN_OPTIONS=halt_on_error=1:abort_on_error=1:detect_leaks=1:detect_stack_use_after_return=1
export UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1
exclude_pattern=${SANITIZE_EXCLUDE-'ResidentMemoryStaysFlat|Skips.*/(rain|rain_tall|tumbler)(_dyop|_sat)?( |$)'}
exclude=(${exclude_pattern:+-E "$exclude_pattern"})
ctest --test-dir build-asan --output-on-failure -j"$(nproc)" --timeout 900 "${exclude[@]}"
echo "sanitize: done in $((SECONDS - start)) s" >&2
