#!/usr/bin/env bash
# Configures and builds the project (Release) into ${BUILD_DIR:-build}. Installs packages first.
# Arguments: the targets to build (default: all), e.g. `bash scripts/build.sh dspbr`.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$here/scripts/setup.sh"
build="${BUILD_DIR:-$here/build}"
cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
targets=()
for t in "$@"; do targets+=(--target "$t"); done
cmake --build "$build" -j "$(nproc)" "${targets[@]}"
