#!/usr/bin/env bash
# The main job: set up, build, and run every method on the example pairs, as a table.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
build/bin/dyop pairs --method all --format table --input examples/pairs.csv
