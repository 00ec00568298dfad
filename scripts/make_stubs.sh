#!/usr/bin/env bash
# Regenerates the type stubs of the extension dspbr._dspbr (python/dspbr/_dspbr/*.pyi) from the
# built module with mypy's stubgen, which reads the signature on the first line of each docstring
# (python/module.cpp). Run after the build; tests/python/test_stubs.py checks they are current.
#   bash scripts/make_stubs.sh [BUILD_DIR]
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${1:-$here/build}"
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
PYTHONPATH="$build/python" /usr/bin/stubgen -q -p dspbr._dspbr -o "$out"
mkdir -p "$here/python/dspbr/_dspbr"
for f in "$out"/dspbr/_dspbr/*.pyi; do
  cp "$f" "$here/python/dspbr/_dspbr/$(basename "$f")"
done
echo "stubs written: python/dspbr/_dspbr/{$(cd "$out/dspbr/_dspbr" && ls | paste -sd, -)}"
