#!/usr/bin/env bash
# Set up, build the test programs (with the `dyop` program they run and the examples, which run as
# tests), and run every test through ctest. The benchmarks are built by `cmake --build build` (CI
# does).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh dyop_test_programs
ctest --test-dir build --output-on-failure -j"$(nproc)"
