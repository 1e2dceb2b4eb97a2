#!/usr/bin/env bash
# The main job: set up, build, and run every scene under the plug-in and Box2D's own code (`dyop
# compare --quick`): the summary, then the tables on standard output, progress on standard error,
# the report (Markdown, CSV, SVG charts, viewer pages) in reports/compare/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh dyop_executable  # the program only; the tests are built by test.sh
build/bin/dyop compare --quick --out reports/compare
