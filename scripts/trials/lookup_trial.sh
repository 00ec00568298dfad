#!/usr/bin/env bash
# Design trial (docs/design/renderer.md, "sixth run"): how far the prepare + eval speed targets
# move when the lookups are made cheaper than the library's, and what that costs in conformance.
# Variants of the C++ compile's generated lookups (scripts/trials/bilinear_lookups.py):
#   bicubic                 luts/ as committed (the library)
#   bicubic, no exp         1 - E_m,avg's exponential a multiply (timing only: values wrong)
#   bilinear                two taps per axis instead of four, the committed tables
#   bilinear GGX            the GGX reads bilinear, the sheen's bicubic, the committed tables
#   bicubic 2x              the library's reads over tables of twice the resolution in each axis
#                           (dspbr lut --layout renderer --renderer-scale 2)
#   bilinear 2x             bilinear over those
#   bilinear 2x, no exp     both (timing only)
# For each: BM_Shader prepare + eval of plastic, metal, car paint and every component (generic build,
# ratio to the bare GGX eval of the same run, median of three); prepare + eval of the first material
# of two validation scenes compiled with their `dspbr shader` header (scripts/shaders/scene_bench.cpp);
# and, where the values are right, the default vector set through shader_cpp_conformance built
# over the variant, judged by `dspbr conformance check` (how many fail by f cos and how many by the pdf
# alone). Prints one Markdown table (about 7 minutes).
#   bash scripts/trials/lookup_trial.sh        (needs build/ configured with the tests and built)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build="${BUILD_DIR:-$here/build}"
dspbr="$build/dspbr"
if [ ! -x "$dspbr" ] || [ ! -f "$build/CMakeFiles/shader_cpp_conformance.dir/link.txt" ]; then
  echo "lookup_trial.sh: $build has no built dspbr and shader tests (bash scripts/build.sh)" >&2
  exit 2
fi
# shellcheck source=scripts/lib/build_like.sh
. "$here/scripts/lib/build_like.sh"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cmake --build "$build" --target dspbr_bench shader_cpp_conformance > /dev/null
vectors="$work/vectors"
"$dspbr" conformance generate --out "$vectors" > /dev/null
"$dspbr" lut --out "$work/x2" --layout renderer --renderer-scale 2 > /dev/null
scenes=(00-metal-roughness-0.05 03-metal-dielectric-metallic-0.00)
for s in "${scenes[@]}"; do "$dspbr" shader --scene "$here/data/dspbr/scenes/sphere/$s.gltf" --out "$work/$s" > /dev/null; done

# variant NAME TABLES JUDGED [bilinear_lookups.py options]: one table row.
variant() {
  local name=$1 tables=$2 judged=$3
  shift 3
  local luts="$work/luts" row
  rm -rf "$luts" && mkdir "$luts"
  cp "$tables"/*.h "$luts"/
  /usr/bin/python3 "$here/scripts/trials/bilinear_lookups.py" "$tables/dspbr_lookup.h" "$luts/dspbr_lookup.h" "$@"
  local inc="s#-I$here/luts#-I$luts#"
  compile_like "$build" dspbr_bench "$here/bench/bench_shader.cpp" "$work/bench_shader.o" "$inc"
  link_like "$build" dspbr_bench "$work/bench" "s#CMakeFiles/dspbr_bench.dir/bench/bench_shader.cpp.o#$work/bench_shader.o#"
  row="| $name | $("$work/bench" --benchmark_filter='BM_Shader/(bare_ggx|prepare_eval/(plastic|metal|carpaint|full))$' \
      --benchmark_repetitions=3 --benchmark_report_aggregates_only=true --benchmark_format=json 2> /dev/null |
    /usr/bin/python3 -c 'import json, sys
med = {b["run_name"]: b["cpu_time"] for b in json.load(sys.stdin)["benchmarks"] if b.get("aggregate_name") == "median"}
bare = med["BM_Shader/bare_ggx"]
print(" | ".join("%.1f\u00d7" % (med["BM_Shader/prepare_eval/" + m] / bare) for m in ["plastic", "metal", "carpaint", "full"]))')"
  for s in "${scenes[@]}"; do
    scene_bench_build "$here" "$work/scene" -include "$work/$s/dspbr_specialization.h" -I"$luts"
    row="$row | $(scene_bench_run "$work/scene" "$here/data/dspbr/scenes/sphere/$s.gltf" | sed 's/.*(\(.*\))/\1/')"
  done
  if [ "$judged" = yes ]; then
    compile_like "$build" dspbr_shader_test "$here/tests/shader_library/shader_material.cpp" "$work/material.o" "$inc"
    compile_like "$build" shader_cpp_conformance "$here/tests/shader_library/shader_cpp_conformance.cpp" "$work/run.o" "$inc"
    link_like "$build" shader_cpp_conformance "$work/conformance" \
      "s#CMakeFiles/shader_cpp_conformance.dir/tests/shader_library/shader_cpp_conformance.cpp.o#$work/run.o $work/material.o#"
    "$work/conformance" "$vectors/vectors.json" "$work/results.json" > /dev/null || true  # exit 1: a vector fails
    "$dspbr" conformance check "$vectors/vectors.json" "$work/results.json" --no-html --out "$work/check" > /dev/null 2>&1 || true
    # The pass count, how many fail by f cos, and f cos's worst ratio to its tolerance.
    row="$row | $(/usr/bin/python3 -c 'import json, sys
r = json.load(open(sys.argv[1]))["vectors"]
fails = [v for v in r if v["verdict"] == "FAIL"]
by_f = sum(1 for v in fails if (v.get("f_cos_ratio") or 0) > 1)
worst = max((v.get("f_cos_ratio") or 0) for v in r)
print("%d of %d pass; %d fail by f cos (worst f cos %.2g of its tolerance), %d by the pdf alone" % (len(r) - len(fails), len(r), by_f, worst, len(fails) - by_f))' "$work/check/report.json") |"
  else
    row="$row | (values wrong) |"
  fi
  echo "$row"
}

echo "| lookups | plastic | metal | car paint | every component | ${scenes[0]}, header | ${scenes[1]}, header | conformance |"
echo "|---|---:|---:|---:|---:|---:|---:|---|"
variant "bicubic (the library)" "$here/luts" yes --keep-bicubic
variant "bicubic, no exp" "$here/luts" no --keep-bicubic --no-exp
variant "bilinear" "$here/luts" yes
variant "bilinear GGX" "$here/luts" yes --ggx-only
variant "bicubic 2x" "$work/x2" yes --keep-bicubic
variant "bilinear 2x" "$work/x2" yes
variant "bilinear 2x, no exp" "$work/x2" no --no-exp
