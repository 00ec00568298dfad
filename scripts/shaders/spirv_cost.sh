#!/usr/bin/env bash
# The SPIR-V cost of the shader library (docs/renderer.md, "Measurements"): bench/shader_cost.comp
# compiled by glslangValidator and optimised by spirv-opt -O for each variant; prints a Markdown
# table of the static texel-fetch count and the size in bytes.
#   bash scripts/shaders/spirv_cost.sh
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
echo "| kernel | texel fetches | SPIR-V bytes |"
echo "|---|---|---|"
for variant in "eval, metal/dielectric parameters read from a buffer|" \
               "eval, every component's parameters from a buffer|-DFULL" \
               "sample, metal/dielectric|-DSAMPLE" "sample, every component|-DFULL -DSAMPLE"; do
  name="${variant%%|*}" defs="${variant#*|}"
  # shellcheck disable=SC2086  # the defines are separate words
  glslangValidator -V $defs -I"$here/shaders" -I"$here/luts" -o "$tmp/k.spv" "$here/bench/shader_cost.comp" > /dev/null
  spirv-opt -O "$tmp/k.spv" -o "$tmp/o.spv"
  printf '| %s | %d | %d |\n' "$name" "$(spirv-dis "$tmp/o.spv" | grep -c OpImageFetch)" "$(stat -c %s "$tmp/o.spv")"
done
