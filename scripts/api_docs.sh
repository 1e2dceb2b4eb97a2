#!/usr/bin/env bash
# The API reference: Doxygen over the public headers (dyop/include, box2d_bridge/include), with
# every warning an error (an undocumented public member, a broken reference). Installs Debian's
# doxygen when it is missing; writes build/doxygen/html/index.html; fails, printing the warnings,
# when there is any.
set -euo pipefail
cd "$(dirname "$0")/.."
if ! command -v doxygen > /dev/null; then
  DYOP_PACKAGES_ONLY=1 bash scripts/setup.sh
fi
DYOP_VERSION=$(sed -n 's/^project(dyop_pd VERSION \([0-9.]*\).*/\1/p' CMakeLists.txt)
export DYOP_VERSION
rm -rf build/doxygen
mkdir -p build/doxygen
if ! doxygen Doxyfile > build/doxygen/doxygen.log 2>&1 || [ -s build/doxygen/warnings.log ]; then
  echo "api_docs: doxygen failed or warned:" >&2
  cat build/doxygen/warnings.log build/doxygen/doxygen.log >&2
  exit 1
fi
echo "api_docs: build/doxygen/html/index.html (doxygen $(doxygen --version), no warnings)" >&2
