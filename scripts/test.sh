#!/usr/bin/env bash
# The README's test command: install, build, run the whole suite through CTest. The sanitizer and
# ODR pass (scripts/sanitize.sh: every GoogleTest case again under ASan/UBSan) and the fuzz targets
# (scripts/fuzz.sh) run in CI after it (.ci/run).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$here/scripts/build.sh"
(cd "${BUILD_DIR:-$here/build}" && ctest --output-on-failure -j "$(nproc)")
