#!/usr/bin/env bash
# A/B of the shader library's speed: the BM_Shader benchmarks of the working tree against those of
# an earlier commit, on one machine, in one run (ratios to the bare GGX eval differ between
# processors, so two versions are compared side by side, not against figures of another day).
#   bash scripts/bench_shader_ab.sh REV [REPETITIONS]
# REV's shaders/, luts/ and tests/shader_library/ are compiled into bench/bench_shader.cpp with
# build/'s flags and linked as build/dspbr_bench is (Makefile generator); scripts/bench_ratios.py
# then runs REV's benchmark and the working tree's in turn and prints both tables.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
rev="${1:?usage: bench_shader_ab.sh REV [REPETITIONS]}"
reps="${2:-3}"
build="${BUILD_DIR:-$here/build}"
git -C "$here" rev-parse --verify --quiet "$rev^{commit}" >/dev/null || { echo "bench_shader_ab.sh: no commit '$rev' in $here" >&2; exit 2; }
cmake --build "$build" --target dspbr_bench >/dev/null
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
git -C "$here" archive "$rev" shaders luts tests/shader_library | tar -x -C "$work"
# shellcheck source=scripts/lib/build_like.sh
. "$here/scripts/lib/build_like.sh"
compile_like "$build" dspbr_bench "$here/bench/bench_shader.cpp" "$work/bench_shader.o" \
  "s#-I$here/shaders#-I$work/shaders#; s#-I$here/luts#-I$work/luts#; s#-I$here/tests/shader_library#-I$work/tests/shader_library#"
link_like "$build" dspbr_bench "$work/dspbr_bench_rev" "s#CMakeFiles/dspbr_bench.dir/bench/bench_shader.cpp.o#$work/bench_shader.o#"
for bench in "$work/dspbr_bench_rev" "$build/dspbr_bench"; do
  [ "$bench" = "$build/dspbr_bench" ] && echo "## working tree" || echo "## $rev"
  /usr/bin/python3 "$here/scripts/bench_ratios.py" --shader --repetitions "$reps" --bench "$bench"
done
