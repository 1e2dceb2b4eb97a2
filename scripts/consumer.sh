#!/usr/bin/env bash
# The CMake package as a user gets it: builds and installs the two libraries into a temporary
# prefix, checks that the installed package names Box2D as its package does (box2d::box2d, found
# with find_dependency), then builds and runs examples/consumer against it (find_package), then
# again with the source tree through add_subdirectory, checking that this way looks for nothing
# but Eigen and Box2D, then a third time beside a project's own `box2d` target
# (examples/consumer_box2d_target: Box2D's source tree through add_subdirectory defines one),
# checking that no Box2D package was looked for. Everything happens in a temporary folder,
# removed at the end. Prints PASS/FAIL lines; exits non-zero on the first failure.
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
package=$(dirname "$(find "$work/prefix" -name dyopConfig.cmake)")
step "the package finds Box2D with find_dependency(box2d)" \
  grep -q '^ *find_dependency(box2d 2\.4)' "$package/dyopConfig.cmake"
step "the package links Box2D as box2d::box2d" \
  grep -q 'INTERFACE_LINK_LIBRARIES ".*box2d::box2d' "$package/dyopTargets.cmake"

# Both ways the same program: configure, build, run (its output shown).
consumer() {  # consumer WAY SOURCE_DIR BUILD_DIR CMAKE_ARGS...
  local way=$1 source=$2 dir=$3
  shift 3
  step "$way: configure" cmake -S "$source" -B "$dir" -DCMAKE_BUILD_TYPE=Release "$@"
  step "$way: build" cmake --build "$dir" -j"$jobs"
  step "$way: run" "$dir/consumer"
  sed 's/^/  /' "$work/log"
}

consumer "find_package" examples/consumer "$work/installed" -DCMAKE_PREFIX_PATH="$work/prefix"
step "find_package: used the installed package" \
  grep -qx "dyop_DIR:PATH=$work/prefix/.*/cmake/dyop" "$work/installed/CMakeCache.txt"

consumer "add_subdirectory" examples/consumer "$work/subdirectory" -DDYOP_SOURCE_DIR="$source_dir"
# A package that was looked for leaves its <name>_DIR (or the find module's variables) in the cache.
if grep -E '^(GTest_DIR|benchmark_DIR|CLI11_DIR|nlohmann_json_DIR|GMP_[A-Z_]+):' \
     "$work/subdirectory/CMakeCache.txt" >&2; then
  echo "consumer: FAIL add_subdirectory: looked for a test, benchmark or testbed dependency" >&2
  exit 1
fi
echo "consumer: PASS add_subdirectory: looked for Eigen and Box2D only"

consumer "box2d target" examples/consumer_box2d_target "$work/box2d_target" \
  -DDYOP_SOURCE_DIR="$source_dir"
# find_package(box2d) leaves box2d_DIR in the cache, found or not.
if grep -E '^box2d_DIR:' "$work/box2d_target/CMakeCache.txt" >&2; then
  echo "consumer: FAIL box2d target: looked for a Box2D package beside the project's box2d target" >&2
  exit 1
fi
echo "consumer: PASS box2d target: used the project's box2d target, looked for no Box2D package"
