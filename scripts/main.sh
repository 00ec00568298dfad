#!/usr/bin/env bash
# The README's main command: install, build, regenerate every table into luts/.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$here/scripts/build.sh"
dspbr="${BUILD_DIR:-$here/build}/dspbr"
"$dspbr" lut --out "$here/luts"
