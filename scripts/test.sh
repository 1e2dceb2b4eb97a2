#!/usr/bin/env bash
# Set up, build the test programs (and the `dyop` program they run), and run every test through
# ctest. The benchmarks and examples are built by `cmake --build build` (CI does).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh dyop_test_programs
ctest --test-dir build --output-on-failure -j"$(nproc)"
