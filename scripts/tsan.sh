#!/usr/bin/env bash
# The many-worlds tests (tests/box2d_bridge/many_worlds_test.cpp: worlds on 1 to 8 threads, a
# pool of workers, reset loops, the counters of every thread) under ThreadSanitizer (GCC), in
# build-tsan/: only the bridge's test program and what it links (the plug-in, the solver, the
# worlds) are built, and only the ManyWorlds tests run. Any report of a data race in the
# project's code fails the run. Box2D comes from Debian uninstrumented: its own statistics
# counters (b2_gjkCalls, b2_toiCalls, ...) are shared by every world and are its business, and
# TSan does not see them; every access our code makes is checked.
set -euo pipefail
cd "$(dirname "$0")/.."
start=$SECONDS
sanitizers="-fsanitize=thread"
source scripts/generator.sh
dyop_fresh_tree build-tsan
# Without the libraries' precompiled headers, which every other build uses: a file of dyop or of
# the plug-in that misses an include of its own fails here.
cmake -S . -B build-tsan "${dyop_generator[@]}" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DCMAKE_CXX_FLAGS="$sanitizers" -DCMAKE_EXE_LINKER_FLAGS="$sanitizers" \
      -DCMAKE_SHARED_LINKER_FLAGS="$sanitizers" -DDYOP_BUILD_BENCH=OFF \
      -DCMAKE_DISABLE_PRECOMPILE_HEADERS=ON >/dev/null
cmake --build build-tsan -j"$(nproc)" --target box2d_bridge_tests
echo "tsan: built in $((SECONDS - start)) s" >&2

# The memory test measures the process's resident size, which TSan's shadow memory dwarfs.
export TSAN_OPTIONS=halt_on_error=1:second_deadlock_stack=1
build-tsan/bin/box2d_bridge_tests --gtest_filter='ManyWorlds.*-*ResidentMemory*'
echo "tsan: done in $((SECONDS - start)) s" >&2
