#!/usr/bin/env bash
# Installs whatever Debian 12 packages the project needs and are missing, then configures and
# builds the Release tree in build/: the targets named (`bash scripts/setup.sh dyop_executable`),
# or everything. Called by main.sh (the `dyop` program only), test.sh (everything) and
# browser_test.sh (the program, with DYOP_EXTRA_PACKAGES=chromium); safe to run again. The
# build's own output goes to build/build.log; standard error gets one progress line per tenth of
# the build, and the log's end if the build fails. Standard output stays free for the tables of
# the command that follows.
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(cmake g++ make ninja-build pkg-config libeigen3-dev libbox2d-dev libgtest-dev libbenchmark-dev
          libcli11-dev libgmp-dev nlohmann-json3-dev zlib1g-dev gnuplot-nox
          libgeos-dev                # for dyop::box2d_outlines (grounds from outlines)
          clang libclang-rt-14-dev   # for scripts/fuzz.sh (libFuzzer)
          doxygen                    # for scripts/api_docs.sh (the API reference)
          clang-format)              # for scripts/format_check.sh (one code format)
# More for one caller only, e.g. DYOP_EXTRA_PACKAGES=chromium (scripts/browser_test.sh): the
# main command does not wait for them.
read -r -a extra <<< "${DYOP_EXTRA_PACKAGES:-}"
packages+=("${extra[@]}")
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}" >&2
  if [ "$(id -u)" -eq 0 ]; then sudo_cmd=(); else sudo_cmd=(sudo); fi
  "${sudo_cmd[@]}" apt-get update -qq >&2
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq "${missing[@]}" >/dev/null
fi

# DYOP_PACKAGES_ONLY=1: the packages only, no build (scripts/api_docs.sh run on its own).
if [ "${DYOP_PACKAGES_ONLY:-0}" = 1 ]; then exit 0; fi

source scripts/generator.sh
mkdir -p build
dyop_fresh_tree build
log=build/build.log
targets=()
for t in "$@"; do targets+=(--target "$t"); done
echo "setup: configuring and building ${*:-everything} (Release; log: $log)" >&2
start=$SECONDS
if ! { cmake -S . -B build "${dyop_generator[@]}" -DCMAKE_BUILD_TYPE=Release &&
       cmake --build build -j"$(nproc)" "${targets[@]}"; } > "$log" 2>&1 < /dev/null; then
  echo "setup: the build failed; the end of $log:" >&2
  tail -n 40 "$log" >&2
  exit 1
fi &
build_pid=$!
# Progress: the build's percentage, each time it passes another tenth.
shown=-10
while kill -0 "$build_pid" 2>/dev/null; do
  # Make prints "[ 42%]", Ninja "[17/40]".
  pct=$(grep -oE '^\[ *[0-9]+%\]|^\[[0-9]+/[0-9]+\]' "$log" 2>/dev/null | tail -n 1 |
        awk -F'[][/%]' '{ print ($3 == "" ? $2 + 0 : int(100 * $2 / $3)) }' || true)
  if [ -n "$pct" ] && [ "$pct" -ge $((shown + 10)) ]; then
    shown=$pct
    echo "setup: build ${pct}% ($((SECONDS - start)) s)" >&2
  fi
  sleep 2
done
wait "$build_pid"
echo "setup: built in $((SECONDS - start)) s" >&2
