# shellcheck shell=bash
# Shell functions (sourced) that build a variant of a CMake target of build/ by hand: one of its
# sources compiled with the target's own defines and flags and its include path edited, then the
# target's link line with objects swapped. Makefile generator (flags.make, link.txt).
# scripts/bench_shader_ab.sh, scripts/shaders/spirv_cost.sh, scripts/trials/lookup_trial.sh.

# compile_like BUILD TARGET SOURCE OBJECT [SED]: SOURCE compiled as TARGET's sources are, the sed
# script SED applied to its include flags (e.g. "s#-I/src/luts#-I/tmp/luts#").
compile_like() {
  local build=$1 target=$2 source=$3 object=$4 edit=${5:-}
  local flags="$build/CMakeFiles/$target.dir/flags.make"
  local defines cxxflags includes
  defines="$(sed -n 's/^CXX_DEFINES = //p' "$flags")"
  cxxflags="$(sed -n 's/^CXX_FLAGS = //p' "$flags")"
  includes="$(sed -n 's/^CXX_INCLUDES = //p' "$flags" | sed "$edit")"
  # shellcheck disable=SC2086  # CMake's word lists
  (cd "$build" && c++ $defines $includes $cxxflags -c "$source" -o "$object")
}

# link_like BUILD TARGET OUT [SED]: TARGET linked as OUT, the sed script SED applied to its link
# line (e.g. to put another object in place of one of the target's).
link_like() {
  local build=$1 target=$2 out=$3 edit=${4:-}
  local line
  line="$(sed "$edit" "$build/CMakeFiles/$target.dir/link.txt" | sed "s#-o $target #-o $out #")"
  (cd "$build" && bash -c "$line")
}

# scene_bench_build SOURCE_DIR OUT [FLAGS...]: scripts/shaders/scene_bench.cpp (prepare + eval of a
# validation scene's material against a bare GGX eval), with FLAGS first (an -include of a scene's
# header, another include folder).
scene_bench_build() {
  local here=$1 out=$2
  shift 2
  g++ -std=c++17 -O2 "$@" -I"$here/shaders" -I"$here/luts" -I"$here/src" -o "$out" \
    "$here/scripts/shaders/scene_bench.cpp" "$here/src/dspbr/shader/gltf_factors.cpp" -lbenchmark -lpthread
}

# scene_bench_run BINARY SCENE: "NS (RATIO)" of prepare + eval, the median of three repetitions
# (RATIO: to the bare GGX eval of the same run).
scene_bench_run() {
  "$1" "$2" --benchmark_repetitions=3 --benchmark_report_aggregates_only=true --benchmark_format=json 2> /dev/null |
    /usr/bin/python3 -c 'import json, sys
med = {b["run_name"]: b["cpu_time"] for b in json.load(sys.stdin)["benchmarks"] if b.get("aggregate_name") == "median"}
print("%.0f ns (%.1f\u00d7)" % (med["prepare_eval"], med["prepare_eval"] / med["bare_ggx"]))'
}
