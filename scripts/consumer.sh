#!/usr/bin/env bash
# The CMake package as a user gets it: builds and installs the two libraries into a temporary
# prefix, then builds and runs examples/consumer against it (find_package), then again with the
# source tree through add_subdirectory, checking that this way looks for nothing but Eigen and
# Box2D. Everything happens in a temporary folder, removed at the end. Prints PASS/FAIL lines;
# exits non-zero on the first failure.
set -euo pipefail
cd "$(dirname "$0")/.."
source_dir=$PWD
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
jobs=$(nproc)

step() {  # step NAME COMMAND...: runs the command quietly, prints PASS or FAIL and its output
  local name=$1 log="$work/log"
  shift
  if "$@" >"$log" 2>&1; then
    echo "consumer: PASS $name"
  else
    cat "$log" >&2
    echo "consumer: FAIL $name" >&2
    exit 1
  fi
}

# The libraries only (no testbed, tests, benchmarks or examples): what a package build does.
step "configure the libraries" cmake -S . -B "$work/lib" -DCMAKE_BUILD_TYPE=Release \
  -DDYOP_BUILD_TESTBED=OFF -DDYOP_BUILD_TESTS=OFF -DDYOP_BUILD_BENCH=OFF -DDYOP_BUILD_EXAMPLES=OFF
step "build the libraries" cmake --build "$work/lib" -j"$jobs"
step "install into a temporary prefix" cmake --install "$work/lib" --prefix "$work/prefix"
step "the licence installed with the package" test -s "$work/prefix/share/doc/dyop/LICENSE"

# Both ways the same program: configure, build, run (its output shown).
consumer() {  # consumer WAY BUILD_DIR CMAKE_ARGS...
  local way=$1 dir=$2
  shift 2
  step "$way: configure" cmake -S examples/consumer -B "$dir" -DCMAKE_BUILD_TYPE=Release "$@"
  step "$way: build" cmake --build "$dir" -j"$jobs"
  step "$way: run" "$dir/consumer"
  sed 's/^/  /' "$work/log"
}

consumer "find_package" "$work/installed" -DCMAKE_PREFIX_PATH="$work/prefix"
step "find_package: used the installed package" \
  grep -qx "dyop_DIR:PATH=$work/prefix/.*/cmake/dyop" "$work/installed/CMakeCache.txt"

consumer "add_subdirectory" "$work/subdirectory" -DDYOP_SOURCE_DIR="$source_dir"
# A package that was looked for leaves its <name>_DIR (or the find module's variables) in the cache.
if grep -E '^(GTest_DIR|benchmark_DIR|CLI11_DIR|nlohmann_json_DIR|GMP_[A-Z_]+):' \
     "$work/subdirectory/CMakeCache.txt" >&2; then
  echo "consumer: FAIL add_subdirectory: looked for a test, benchmark or testbed dependency" >&2
  exit 1
fi
echo "consumer: PASS add_subdirectory: looked for Eigen and Box2D only"
