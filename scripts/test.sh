#!/usr/bin/env bash
# The README's test command: install, build, run the whole suite through CTest. CI (.ci/run) then
# runs the undefined-behaviour pass (scripts/sanitize.sh: every GoogleTest case again under
# AddressSanitizer and UndefinedBehaviorSanitizer, with an ODR check) and the fuzz targets
# (scripts/fuzz.sh) as well.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$here/scripts/build.sh"
(cd "${BUILD_DIR:-$here/build}" && ctest --output-on-failure -j "$(nproc)")
