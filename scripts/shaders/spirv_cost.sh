#!/usr/bin/env bash
# The SPIR-V cost of the shader library (docs/renderer.md, "Measurements"): bench/shader_cost.comp
# compiled by glslangValidator and optimised by spirv-opt -O for each variant; prints a Markdown
# table of the static texel-fetch count and the size in bytes. With --scenes DSPBR (the built dspbr
# command), also a row per distinct specialisation of the validation scenes (`dspbr shader
# --scene`), each the eval kernel with every component's parameters read from the buffer.
#   bash scripts/shaders/spirv_cost.sh [--scenes build/dspbr]
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
dspbr=""
if [ "${1:-}" = "--scenes" ]; then dspbr=${2:?--scenes needs the dspbr command}; fi
cost() {  # cost NAME DEFINES...: one table row
  local name=$1; shift
  glslangValidator -V "$@" -I"$here/shaders" -I"$here/luts" -o "$tmp/k.spv" "$here/bench/shader_cost.comp" > /dev/null
  spirv-opt -O "$tmp/k.spv" -o "$tmp/o.spv"
  printf '| %s | %d | %d |\n' "$name" "$(spirv-dis "$tmp/o.spv" | grep -c OpImageFetch)" "$(stat -c %s "$tmp/o.spv")"
}
echo "| kernel | texel fetches | SPIR-V bytes |"
echo "|---|---|---|"
for variant in "eval, metal/dielectric parameters read from a buffer|" \
               "eval, every component's parameters from a buffer|-DFULL" \
               "sample, metal/dielectric|-DSAMPLE" "sample, every component|-DFULL -DSAMPLE"; do
  # shellcheck disable=SC2086  # the defines are separate words
  cost "${variant%%|*}" ${variant#*|}
done
[ -n "$dspbr" ] || exit 0
declare -A seen
for scene in "$here"/data/dspbr/scenes/sphere/*.gltf; do
  "$dspbr" shader --scene "$scene" --out "$tmp/s" > /dev/null
  comps=$(sed -n 's|^// Compiled in: \(.*\)\.$|\1|p' "$tmp/s/dspbr_specialization.h")
  [ -z "${seen[$comps]:-}" ] || continue
  seen[$comps]=1
  cost "eval, every parameter, \`dspbr shader\` for $(basename "$scene" .gltf): $comps" -DFULL -DDSPBR_USE_SPECIALIZATION -I"$tmp/s"
done
