#!/usr/bin/env bash
# Fuzzing: builds the libFuzzer targets of fuzz/ with clang (ASan + UBSan on the code under test)
# in build-fuzz/, then runs each for a bounded time on its seed corpus (fuzz/corpus/csv for the
# CSV reader, fuzz/corpus/methods for the methods, fuzz/corpus/convex for the polygon and circle
# pairs, fuzz/corpus/world for sequences of world operations), new inputs going to
# build-fuzz/corpus/. Any crash, sanitizer report or failed property stops it with a non-zero
# status and leaves the reproducer in build-fuzz/artifacts/
# (replay: build-fuzz/bin/fuzz_csv <file>, build-fuzz/bin/fuzz_method --method=NAME <file>,
# build-fuzz/bin/fuzz_convex <file>, or build-fuzz/bin/fuzz_world --print <file>, which prints the
# operations).
#   FUZZ_SECONDS        seconds per target (default 20)
#   FUZZ_WORLD_SECONDS  seconds for fuzz_world (default 60)
#   FUZZ_CONVEX_SECONDS seconds for fuzz_convex (default 10)
#   FUZZ_TARGETS        targets to run (default: all): fuzz_csv, fuzz_convex, fuzz_world, and
#                       method:NAME for each method of the registry (fuzz_method --list-methods);
#                       only the fuzzers they need are built
#   FUZZ_SEED     libFuzzer's seed (default 1, so that CI explores the same inputs every run and
#                 passes or fails alike; 0 lets libFuzzer pick one, for hunting)
# Needs clang and libFuzzer's runtime (Debian 12: clang, libclang-rt-14-dev).
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${FUZZ_SECONDS:-20}"
world_seconds="${FUZZ_WORLD_SECONDS:-60}"
convex_seconds="${FUZZ_CONVEX_SECONDS:-10}"
seed="${FUZZ_SEED:-1}"

if ! command -v clang++ >/dev/null; then
  echo "fuzz: clang++ not found (Debian 12: apt-get install clang libclang-rt-14-dev)" >&2
  exit 2
fi
if ! echo 'extern "C" int LLVMFuzzerTestOneInput(const char*, unsigned long) { return 0; }' |
     clang++ -x c++ -fsanitize=fuzzer - -o /dev/null 2>/dev/null; then
  echo "fuzz: clang++ cannot link libFuzzer (Debian 12: apt-get install libclang-rt-14-dev)" >&2
  exit 2
fi

start=$SECONDS
if [ -n "${FUZZ_TARGETS:-}" ]; then
  targets=($FUZZ_TARGETS)
  binaries=()
  for target in "${targets[@]}"; do
    case "$target" in
      method:*) binaries+=(fuzz_method) ;;
      *) binaries+=("$target") ;;
    esac
  done
  binaries=($(printf '%s\n' "${binaries[@]}" | sort -u))
else
  binaries=(fuzz_csv fuzz_method fuzz_convex fuzz_world)
fi
source scripts/generator.sh
dyop_fresh_tree build-fuzz
cmake -S . -B build-fuzz "${dyop_generator[@]}" -DDYOP_FUZZ=ON -DCMAKE_CXX_COMPILER=clang++ \
      -DCMAKE_BUILD_TYPE=RelWithDebInfo -DDYOP_BUILD_TESTS=OFF -DDYOP_BUILD_BENCH=OFF >/dev/null
cmake --build build-fuzz -j"$(nproc)" --target "${binaries[@]}"
echo "fuzz: built ${binaries[*]} in $((SECONDS - start)) s" >&2
if [ -z "${FUZZ_TARGETS:-}" ]; then
  targets=(fuzz_csv fuzz_convex fuzz_world)
  for method in $(build-fuzz/bin/fuzz_method --list-methods); do targets+=("method:$method"); done
fi

export ASAN_OPTIONS=halt_on_error=1:abort_on_error=1:detect_leaks=1
export UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1
mkdir -p build-fuzz/artifacts
for target in "${targets[@]}"; do
  time_limit=$seconds
  if [ "$target" = fuzz_csv ]; then
    run=(build-fuzz/bin/fuzz_csv)
    seeds=fuzz/corpus/csv
  elif [ "$target" = fuzz_convex ]; then
    run=(build-fuzz/bin/fuzz_convex)
    seeds=fuzz/corpus/convex
    time_limit=$convex_seconds
  elif [ "$target" = fuzz_world ]; then
    # 8 bytes per operation, at most 200 operations (fuzz/world_ops.hpp).
    run=(build-fuzz/bin/fuzz_world -max_len=1600)
    seeds=fuzz/corpus/world
    time_limit=$world_seconds
  else
    run=(build-fuzz/bin/fuzz_method "--method=${target#method:}")
    seeds=fuzz/corpus/methods
    target="fuzz_${target#method:}"
  fi
  mkdir -p "build-fuzz/corpus/$target"
  echo "fuzz: $target for ${time_limit} s" >&2
  if ! "${run[@]}" -seed="$seed" -max_total_time="$time_limit" -timeout=10 -rss_limit_mb=2048 \
         -print_final_stats=1 -artifact_prefix="build-fuzz/artifacts/$target-" \
         "build-fuzz/corpus/$target" "$seeds" > "build-fuzz/$target.log" 2>&1; then
    tail -n 60 "build-fuzz/$target.log" >&2
    echo "fuzz: $target FAILED (log: build-fuzz/$target.log, reproducer in build-fuzz/artifacts/)" >&2
    exit 1
  fi
  grep -E "stat::number_of_executed_units|stat::new_units_added" "build-fuzz/$target.log" |
    tr '\n' ' ' | sed "s/^/fuzz: $target: /; s/\$/\n/" >&2
done
echo "fuzz: ${#targets[@]} targets ran without a failure (${seconds} s each, fuzz_convex ${convex_seconds} s, fuzz_world ${world_seconds} s; $((SECONDS - start)) s in all)"
