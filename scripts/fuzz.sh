#!/usr/bin/env bash
# Builds and runs the libFuzzer targets of fuzz/ (docs/limits.md, "Fuzzing"): clang++,
# AddressSanitizer + UndefinedBehaviorSanitizer, a seed corpus from the project's own JSON and
# glTF files, the dictionary fuzz/json.dict.
#   bash scripts/fuzz.sh [SECONDS]        build, then run each target SECONDS (default 100: 10 min in all)
#   bash scripts/fuzz.sh --build-only     configure and build only (the dspbr_fuzz target of a -DDSPBR_FUZZ=ON build)
#   bash scripts/fuzz.sh --no-build SECONDS   run only (CTest fuzz_short of a -DDSPBR_FUZZ=ON build)
# Work folder: ${FUZZ_DIR:-${BUILD_DIR:-build}/fuzz} (build, corpora, artifacts, logs).
# FUZZ_TARGETS="gltf uri" runs only those targets (default: all eight).
# Exit status: 0 when no target crashed, hung (10 s per input), leaked past 2 GB or got a
# sanitizer report; else 1, with the reproducer in <work folder>/artifacts/.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
work="${FUZZ_DIR:-${BUILD_DIR:-$here/build}/fuzz}"
build=1 run=1 seconds=100
case "${1:-}" in
  --build-only) run=0 ;;
  --no-build) build=0; seconds="${2:-3}" ;;
  "") ;;
  *) seconds="$1" ;;
esac
read -r -a targets <<<"${FUZZ_TARGETS:-params instance gltf luts uri output conformance lookups}"

if ((build)); then
  cxx="${FUZZ_CXX:-$(command -v clang++ || true)}"
  [ -n "$cxx" ] || { echo "fuzz: clang++ not found (Debian: clang, libclang-rt-14-dev)" >&2; exit 1; }
  cmake -S "$here/fuzz" -B "$work/build" -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
  # Parallel jobs: FUZZ_JOBS, else the -jN of the make that runs this script (the dspbr_fuzz target
  # of a -DDSPBR_FUZZ=ON build; a make without -j: 1), else CMAKE_BUILD_PARALLEL_LEVEL, else all cores.
  jobs="${FUZZ_JOBS:-}"
  if [ -z "$jobs" ] && [ -n "${MAKEFLAGS+set}" ]; then
    jobs=1
    if [[ " $MAKEFLAGS " =~ [[:space:]]-?j([0-9]+) ]]; then jobs="${BASH_REMATCH[1]}"; fi
  fi
  jobs="${jobs:-${CMAKE_BUILD_PARALLEL_LEVEL:-$(nproc)}}"
  cmake --build "$work/build" -j "$jobs"
fi
((run)) || exit 0

# Seed corpora (rebuilt each run from the sources; what the fuzzer adds goes to corpus/<target>).
seeds="$work/seeds"
rm -rf "$seeds"
mkdir -p "$seeds"/{params,instance,gltf,luts,uri,output,conformance,lookups}
cp "$here/data/dspbr/params-2025x.json" "$seeds/params/"
for f in "$here"/tests/data/params/*.json; do
  if grep -q '"materials"' "$f"; then cp "$f" "$seeds/params/"; else cp "$f" "$seeds/instance/"; fi
done
find "$here/data/dspbr/scenes" "$here/tests/data" -name '*.json' -size -8k \
  -exec grep -l '"material"' {} + 2>/dev/null | while read -r f; do cp "$f" "$seeds/instance/$(echo "${f#$here/}" | tr / _)"; done
find "$here/data/dspbr/scenes" "$here/tests/data/gltf" \( -name '*.gltf' -o -name '*.glb' \) -size -64k |
  while read -r f; do cp "$f" "$seeds/gltf/$(echo "${f#$here/}" | tr / _)"; done
# The committed tables with every table cut to 2 samples per axis (same structure, small inputs).
/usr/bin/python3 - "$here/luts" "$seeds/luts" <<'PY'
import json, sys
src, dst = sys.argv[1], sys.argv[2]
for name in ("dspbr_luts.json", "dspbr_renderer_luts.json"):
    doc = json.load(open(f"{src}/{name}"))
    for t in doc["tables"].values():
        n = 1
        for a in t["axes"]:
            a["size"] = 2
            n *= 2
        t["values"] = t["values"][:n]
        t["errors"] = t["errors"][:n]
    json.dump(doc, open(f"{dst}/{name}", "w"), indent=1)
PY

# URIs that stay inside, leave, or go through the links fuzz_uri plants; output sets for fuzz_output
# (first byte: odd commits), some of them through the links it plants.
i=0
for u in sub/a.bin in/a.bin in_abs/a.bin ../secret.bin out/secret.bin out_abs/secret.bin sub/up2/secret.bin \
         '..%2Fsecret.bin' '%2E%2E/x' sub/../sub/a.bin loop /etc/passwd 'a%00b'; do
  printf '%s' "$u" >"$seeds/uri/$((i++))"
done
printf '1a.json\nrenderer/b.exr\nc.png\n' >"$seeds/output/0"
printf '1x.json\ny/z.json\n' >"$seeds/output/1"
printf '0a.json\nfile/q.json\n' >"$seeds/output/2"
printf '1file\n' >"$seeds/output/3"

# Conformance readers (first byte even: a vector document, odd: a results file): the committed
# small vector set, and results for it in JSON and CSV.
{ printf '0'; cat "$here/tests/data/conformance/vectors-small.json"; } >"$seeds/conformance/vectors"
printf '1{"results": [{"id": "plain_metal/gold-r10/00", "f_cos": [1, 2, 3], "pdf": 1, "delta": [{"l": [0, 0, 1], "value": [1, 1, 1]}]}]}' \
  >"$seeds/conformance/results-json"
printf '1id,f_cos_r,f_cos_g,f_cos_b,pdf\nplain_metal/gold-r10/00,1,2,3,4\nmetallic/metal-mirror/00,0,0,0,0\n' \
  >"$seeds/conformance/results-csv"

# Lookup arguments (7 floats): NaN, infinities, huge, subnormal, and ordinary values.
/usr/bin/python3 - "$seeds/lookups" <<'PY'
import struct, sys
rows = [[float("nan")] * 7, [float("inf"), -float("inf"), 1e30, -1e30, 0.0, 1.0, 0.0],
        [0.5, 0.5, 1.5, 0.3, 0.7, 1.0, 1.0], [1e-45, 2.0, 1e4, 0.0, -0.0, 0.0, 1.0]]
for i, r in enumerate(rows):
    open(f"{sys.argv[1]}/{i}", "wb").write(struct.pack("<7f", *r))
PY

mkdir -p "$work/artifacts" "$work/logs"
# The short run (--no-build, CTest) starts from the seeds alone each time, so that it stays a few
# seconds; longer runs keep growing corpus/<target>.
corpus="$work/corpus"
((build)) || { corpus="$work/corpus-short"; rm -rf "$corpus"; }
status=0
for t in "${targets[@]}"; do
  mkdir -p "$corpus/$t"
  log="$work/logs/fuzz_$t.log"
  if "$work/build/fuzz_$t" "$corpus/$t" "$seeds/$t" -dict="$here/fuzz/json.dict" -max_total_time="$seconds" \
       -timeout=10 -rss_limit_mb=2048 -max_len=65536 -print_final_stats=1 \
       -artifact_prefix="$work/artifacts/$t-" >"$log" 2>&1; then
    echo "fuzz_$t: $(grep -E '^stat::number_of_executed_units' "$log" | awk '{print $2}') runs in ${seconds} s, no crash, hang or sanitizer report"
  else
    status=1
    echo "fuzz_$t: FAILED, see $log and $work/artifacts/" >&2
    grep -E 'ERROR|SUMMARY|runtime error|deadly signal|timeout' "$log" | head -5 >&2
  fi
done
exit $status
