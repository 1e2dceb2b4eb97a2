#!/usr/bin/env bash
# One code format: every C++ source and header under git must be as clang-format (.clang-format)
# writes it. Fails listing the files that are not; `clang-format -i FILE` formats one.
set -euo pipefail
cd "$(dirname "$0")/.."
command -v clang-format >/dev/null ||
  { echo "format_check: clang-format not found (Debian 12: apt-get install clang-format)" >&2; exit 2; }
mapfile -t files < <(git ls-files '*.cpp' '*.hpp' '*.h')
clang-format --dry-run --Werror "${files[@]}"
echo "format_check: ${#files[@]} files formatted ($(clang-format --version | head -1))"
