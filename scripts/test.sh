#!/usr/bin/env bash
# The README's test command: install, build, run the whole suite through CTest, then the
# sanitizer and ODR pass (scripts/sanitize.sh).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$here/scripts/build.sh"
(cd "${BUILD_DIR:-$here/build}" && ctest --output-on-failure -j "$(nproc)")
bash "$here/scripts/sanitize.sh"
