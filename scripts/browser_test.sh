#!/usr/bin/env bash
# The viewer page in a real browser (CI, after the test command): installs Debian's chromium if
# missing, builds the `dyop` program, then tests/browser/viewer_page_check.py runs `dyop view` on
# small scenes, loads each page in headless chromium at a step and checks what it shows (counts
# against the recording, no script error, a screenshot with content). Fails if chromium cannot be
# installed. The README's commands never need chromium.
set -euo pipefail
cd "$(dirname "$0")/.."
DYOP_EXTRA_PACKAGES=chromium bash scripts/setup.sh dyop_executable
if ! command -v chromium > /dev/null; then
  echo "browser_test: chromium is not installed and could not be installed" >&2
  exit 1
fi
python3 tests/browser/viewer_page_check.py build/bin/dyop build/browser_test
