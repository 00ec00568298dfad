#!/usr/bin/env bash
# The SPIR-V cost of the shader library (docs/renderer.md, "Measurements"): bench/shader_cost.comp
# compiled by glslangValidator and optimised by spirv-opt -O for each variant; prints a Markdown
# table of the static texel-fetch count and the size in bytes. With --scenes DSPBR (the built dspbr
# command), also a row per distinct specialisation of the validation scenes (`dspbr shader
# --scene`), each the eval kernel with every component's parameters read from the buffer, and the
# C++ cost of prepare + eval of the scene's material (scripts/shaders/scene_bench.cpp, Google
# Benchmark, median of three repetitions): generic, then with the scene's header, each also as a
# ratio to a bare GGX eval in the same run; then the same two with every table read one load
# (bench/null_tables/dspbr_fits.hpp: the floor under any lookup).
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
# shellcheck source=scripts/lib/build_like.sh
. "$here/scripts/lib/build_like.sh"
scene_bench_build "$here" "$tmp/generic"
null=(-I"$here/bench/null_tables" -DDSPBR_USE_FITS)  # every table read one load
scene_bench_build "$here" "$tmp/generic_null" "${null[@]}"
echo
echo "| scene (first material) | components | texel fetches | SPIR-V bytes | C++ prepare + eval, generic | with the header | one load per table read, generic | with the header |"
echo "|---|---|---|---|---|---|---|---|"
declare -A seen
for scene in "$here"/data/dspbr/scenes/sphere/*.gltf; do
  "$dspbr" shader --scene "$scene" --out "$tmp/s" > /dev/null
  comps=$(sed -n 's|^// Compiled in: \(.*\)\.$|\1|p' "$tmp/s/dspbr_specialization.h")
  [ -z "${seen[$comps]:-}" ] || continue
  seen[$comps]=1
  row=$(cost x -DFULL -DDSPBR_USE_SPECIALIZATION -I"$tmp/s")
  fetches=$(echo "$row" | cut -d'|' -f3 | tr -d ' ')
  bytes=$(echo "$row" | cut -d'|' -f4 | tr -d ' ')
  scene_bench_build "$here" "$tmp/special" -include "$tmp/s/dspbr_specialization.h"
  scene_bench_build "$here" "$tmp/special_null" -include "$tmp/s/dspbr_specialization.h" "${null[@]}"
  printf '| %s | %s | %s | %s | %s | %s | %s | %s |\n' "$(basename "$scene" .gltf)" "$comps" "$fetches" "$bytes" \
    "$(scene_bench_run "$tmp/generic" "$scene")" "$(scene_bench_run "$tmp/special" "$scene")" \
    "$(scene_bench_run "$tmp/generic_null" "$scene")" "$(scene_bench_run "$tmp/special_null" "$scene")"
done
