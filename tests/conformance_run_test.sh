#!/usr/bin/env bash
# `dspbr conformance run --glsl/--hlsl` on the Vulkan device (CTest conformance_run_glsl,
# conformance_run_hlsl): the kit's reference shader (examples/conformance/shader_reference.glsl)
# passes every vector; the glTF one (examples/conformance/shader_gltf.glsl) every vector with a glTF
# material; a broken one (tests/data/conformance/shader_broken.glsl: clearcoat 5 % too
# bright, sheen not supported, no pdf) exits 1 with clearcoat FAIL, sheen NOT SUPPLIED, the other
# components PASS and the pdf not judged; a shader that does not compile exits 2 naming its file and
# line and leaves nothing, and so does a --glslang that writes no SPIR-V module. Exit 77 (skipped)
# without a Vulkan device.
#   conformance_run_test.sh DSPBR VECTORS SOURCE_DIR WORK_DIR glsl|hlsl
set -uo pipefail
dspbr=$1 vectors=$2 src=$3 work=$4 lang=$5
rm -rf "$work" && mkdir -p "$work"
fail() { echo "FAIL: $*"; exit 1; }

"$dspbr" conformance run "$vectors" --"$lang" "$src/examples/conformance/shader_reference.glsl" \
  --no-html --out "$work/reference" > "$work/reference.log" 2>&1
rc=$?
cat "$work/reference.log"
[ $rc -eq 77 ] && exit 77
[ $rc -eq 0 ] || fail "the reference shader: exit $rc"
grep -q "on .*: [0-9]* vectors" "$work/reference.log" || fail "the device is not named"
[ -f "$work/reference/results.json" ] || fail "no results.json"

# The glTF factors reach the shader: a renderer mapping x.gltf (examples/conformance/shader_gltf.glsl)
# passes every vector that carries a glTF material, and judges exactly those (glTF's defaults in
# place of the factors would fail them).
"$dspbr" conformance run "$vectors" --"$lang" "$src/examples/conformance/shader_gltf.glsl" \
  --no-html --out "$work/gltf" > "$work/gltf.log" 2>&1
rc=$?
cat "$work/gltf.log"
[ $rc -eq 0 ] || fail "the glTF shader: exit $rc"
/usr/bin/python3 - "$vectors" "$work/gltf/report.json" <<'PY' || fail "the glTF shader's report"
import json, sys
vectors = json.load(open(sys.argv[1]))["vectors"]
r = json.load(open(sys.argv[2]))
with_gltf = sum(1 for v in vectors if "gltf_material" in v)
judged = r["summary"]["vectors"] - r["summary"]["not_supplied"]
assert with_gltf > len(vectors) // 2 and judged == with_gltf, (with_gltf, judged, r["summary"])
PY

"$dspbr" conformance run "$vectors" --"$lang" "$src/tests/data/conformance/shader_broken.glsl" \
  --no-html --out "$work/broken" > "$work/broken.log" 2>&1
rc=$?
cat "$work/broken.log"
[ $rc -eq 1 ] || fail "the broken shader: exit $rc, expected 1"
/usr/bin/python3 - "$work/broken/report.json" <<'PY' || fail "the broken shader's report"
import json, sys
r = json.load(open(sys.argv[1]))
groups = {g["name"]: g for g in r["groups"]}
assert groups["clearcoat"]["verdict"] == "FAIL", groups["clearcoat"]
assert groups["sheen"]["verdict"] == "NOT SUPPLIED" and groups["sheen"]["not_supplied"] == groups["sheen"]["vectors"]
for name in ("plain_metal", "plain_plastic", "metallic", "opaque_dielectric", "flakes", "translucency"):
    assert groups[name]["verdict"] == "PASS", groups[name]
assert r["quantities"]["pdf"]["judged"] == 0 and r["quantities"]["pdf"]["not_judged"] > 0, r["quantities"]["pdf"]
assert r["summary"]["not_supplied"] > 0
PY

# The user's own #include lines (read by the kit, inside the file's folder): the reference shader
# included from another file passes; a syntax error in the included file is named by its file and line.
mkdir -p "$work/inc"
cp "$src/examples/conformance/shader_reference.glsl" "$work/inc/body.glsl"
printf '// my renderer\n#include "body.glsl"\n' > "$work/inc/main.glsl"
"$dspbr" conformance run "$vectors" --"$lang" "$work/inc/main.glsl" --no-html --groups clearcoat --out "$work/inc/r" \
  > "$work/inc.log" 2>&1 || { cat "$work/inc.log"; fail "a shader that includes the reference: exit $?"; }
printf '// my renderer\nvoid conformance_eval(DspbrConformanceInput x, inout DspbrConformanceResult y) {\n  y.f_cos = x.v +;\n}\n' \
  > "$work/inc/bad_body.glsl"
printf '// my renderer\n#include "bad_body.glsl"\n' > "$work/inc/bad.glsl"
"$dspbr" conformance run "$vectors" --"$lang" "$work/inc/bad.glsl" --no-html --out "$work/inc/never" > "$work/inc_bad.log" 2>&1
rc=$?
cat "$work/inc_bad.log"
[ $rc -eq 2 ] || fail "an included file that does not compile: exit $rc, expected 2"
grep -q "bad_body.glsl:3" "$work/inc_bad.log" || fail "the message does not name the included file's line"

printf 'void conformance_eval(DspbrConformanceInput x, inout DspbrConformanceResult y) {\n  y.f_cos = x.v +;\n}\n' \
  > "$work/typo.glsl"
"$dspbr" conformance run "$vectors" --"$lang" "$work/typo.glsl" --no-html --out "$work/never" > "$work/typo.log" 2>&1
rc=$?
cat "$work/typo.log"
[ $rc -eq 2 ] || fail "a shader that does not compile: exit $rc, expected 2"
[ "$(wc -l < "$work/typo.log")" -eq 1 ] || fail "not one line"
grep -q "typo.glsl: does not compile .*typo.glsl:2" "$work/typo.log" || fail "the message names no file and line"
[ ! -e "$work/never" ] || fail "a folder was left"
# A --glslang that exits 0 without a SPIR-V module (nothing, or bytes that are not SPIR-V) is bad
# input (exit 2 naming the option), not a failing implementation.
printf '#!/bin/sh\nwhile [ $# -gt 0 ]; do [ "$1" = -o ] && printf "not a SPIR-V module" > "$2"; shift; done\nexit 0\n' \
  > "$work/fake_glslang.sh"
chmod +x "$work/fake_glslang.sh"
for fake in /bin/true "$work/fake_glslang.sh"; do
  "$dspbr" conformance run "$vectors" --"$lang" "$src/examples/conformance/shader_reference.glsl" --glslang "$fake" \
    --no-html --out "$work/never" > "$work/fake.log" 2>&1
  rc=$?
  cat "$work/fake.log"
  [ $rc -eq 2 ] || fail "--glslang $fake: exit $rc, expected 2"
  grep -q "^dspbr: error: --glslang: .*wrote no SPIR-V" "$work/fake.log" || fail "--glslang $fake: the message"
  [ ! -e "$work/never" ] || fail "--glslang $fake: a folder was left"
done
echo "conformance run --$lang: reference PASS, broken FAIL as planted, compile error and a fake compiler exit 2"
