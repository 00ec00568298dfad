#!/usr/bin/env bash
# Installs the build into a temporary prefix, MOVES the prefix elsewhere, and from yet another
# folder runs the moved bin/dspbr (--version, eval, params list, a tiny lut, validate --quick) and
# builds examples/ as an outside project with find_package(dspbr CONFIG REQUIRED), then runs it;
# also compiles the example through the moved dspbr.pc, and imports the installed Python module
# (vectorized eval/pdf against the moved dspbr eval to 1e-6 relative, lut.generate sizes). Proves the install is complete and
# relocatable and reads nothing from the source or build tree.
#   install_test.sh BUILD_DIR SOURCE_DIR WORK_DIR CMAKE
set -euo pipefail
build=$1 src=$2 work=$3 cmake=${4:-cmake}
rm -rf "$work"
mkdir -p "$work/elsewhere"
step() { echo "== $*"; }

step "install into $work/stage"
"$cmake" --install "$build" --prefix "$work/stage" > "$work/install.log"
mv "$work/stage" "$work/moved"
prefix="$work/moved"
dspbr="$prefix/bin/dspbr"
for f in bin/dspbr lib/libdspbr_core.a lib/libdspbr_lutgen.a lib/libdspbr_formats.a lib/libdspbr_validate.a \
         lib/libdspbr_fit.a lib/libdspbr_conformance.a lib/cmake/dspbr/dspbr_coreTargets.cmake lib/cmake/dspbr/dspbrConfig.cmake lib/cmake/dspbr/dspbrConfigVersion.cmake \
         lib/cmake/dspbr/dspbrTargets.cmake lib/pkgconfig/dspbr.pc include/dspbr/bsdf/material_bsdf.h \
         lib/cmake/dspbr/dspbr_shadersTargets.cmake share/dspbr/shaders/dspbr.h share/dspbr/shaders/dspbr.glsl \
         share/dspbr/shaders/dspbr.hlsl share/dspbr/shaders/dspbr/bsdf.glsl share/dspbr/shaders/dspbr_lookup.glsl \
         share/dspbr/shaders/dspbr_thin_film_lookup.h include/dspbr/luts/dspbr_thin_film_lookup.h \
         include/dspbr/version.h include/dspbr/luts/pbrlut.hpp include/dspbr/luts/dspbr_lookup.h \
         include/dspbr/luts/dspbr_lookup.glsl include/dspbr/luts/dspbr_lookup.hlsl \
         include/dspbr/luts/dspbr_glass_lookup.h include/dspbr/luts/dspbr_glass_lookup.glsl \
         include/dspbr/luts/dspbr_glass_lookup.hlsl include/dspbr/fits/dspbr_fits.hpp \
         share/dspbr/data/params-2025x.json share/dspbr/data/LICENSE.txt share/dspbr/data/gltf_ext/schema \
         share/dspbr/luts/dspbr_renderer_luts.json share/dspbr/report/make_report.py \
         share/dspbr/report/templates/index.html.j2 share/dspbr/report/conformance_report.py \
         share/dspbr/scenes/sphere/00-metal-roughness-0.05.gltf include/dspbr/conformance/vector_set.h; do
  [ -e "$prefix/$f" ] || { echo "missing in the install: $f"; exit 1; }
done
# Nothing installed may name the source or the build tree (the binary, the CMake files, the .pc).
if grep -rlF -e "$src" -e "$build" "$prefix" ; then echo "the install names the source or build tree (above)"; exit 1; fi
if grep -rlF "$work/stage" "$prefix"; then echo "the install names its first prefix (above)"; exit 1; fi

cd "$work/elsewhere"
step "dspbr --version"; "$dspbr" --version
step "dspbr eval"; "$dspbr" eval --view 0,0,1 --light 0.3,0,1
step "dspbr params list"; "$dspbr" params list > params.txt; head -3 params.txt
step "dspbr lut"; "$dspbr" lut --out T --tables GGX_E --size GGX_E=4x4 --samples 1024 > lut.log
[ -s T/dspbr_luts.json ] || { echo "lut wrote no T/dspbr_luts.json"; exit 1; }
step "dspbr validate --quick"; "$dspbr" validate --quick --out R > validate.log 2> validate.err || {
  cat validate.log validate.err; exit 1; }
[ -s R/index.html ] || { echo "validate wrote no R/index.html"; exit 1; }
grep -q '"file": "built-in luts/dspbr_renderer_luts.json"' R/data/report.json ||
  { echo "the report does not name the built-in tables"; exit 1; }

if [ -d "$prefix/lib/python3/dist-packages/dspbr" ]; then
  step "import dspbr from the moved prefix: eval/pdf agree with the moved dspbr eval, lut.generate sizes"
  PYTHONPATH="$prefix/lib/python3/dist-packages" DSPBR="$dspbr" PREFIX="$prefix" /usr/bin/python3 - <<'PY'
import json, os, subprocess
import numpy as np
import dspbr
assert os.path.realpath(dspbr.__file__).startswith(os.path.realpath(os.environ["PREFIX"])), dspbr.__file__
material = {"albedo": [0.8, 0.5, 0.2], "roughness": 0.3, "sheenColor": [0.3, 0.3, 0.9], "sheenRoughness": 0.4}
rng = np.random.default_rng(7)
v = rng.normal(size=(6, 3)); v[:, 2] = np.abs(v[:, 2]) + 0.1
l = rng.normal(size=(6, 3)); l[:, 2] = np.abs(l[:, 2]) + 0.1
v /= np.linalg.norm(v, axis=1, keepdims=True); l /= np.linalg.norm(l, axis=1, keepdims=True)
bsdf = dspbr.Bsdf(material)
f, pdf = bsdf.eval(v, l), bsdf.pdf(v, l)
sets = ["--set", "albedo=0.8,0.5,0.2", "--set", "roughness=0.3", "--set", "sheenColor=0.3,0.3,0.9",
        "--set", "sheenRoughness=0.4"]
for i in range(len(v)):
    cli = json.loads(subprocess.run([os.environ["DSPBR"], "eval", *sets, "--view", ",".join(map(repr, v[i])),
                                     "--light", ",".join(map(repr, l[i]))], check=True, capture_output=True,
                                    text=True).stdout)
    np.testing.assert_allclose(f[i], cli["f"], rtol=1e-6, atol=0)
    np.testing.assert_allclose(pdf[i], cli["pdf"], rtol=1e-6, atol=0)
tables = dspbr.lut.generate(tables=["GGX_E", "Base_E_avg"], size={"GGX_E": (5, 7), "Base_E_avg": (3, 4)},
                            samples=256, target_error=0, layout="published")
assert tables["GGX_E"].shape == (5, 7) and tables["Base_E_avg"].shape == (3, 4), {k: t.shape for k, t in tables.items()}
print("python: %d directions agree with dspbr eval to 1e-6; lut.generate shapes %s" %
      (len(v), {k: t.shape for k, t in tables.items()}))
PY
fi

step "examples/ against the moved prefix (CMake package)"
"$cmake" -S "$src/examples" -B ex -DCMAKE_PREFIX_PATH="$prefix" > ex-configure.log
"$cmake" --build ex -j2 > ex-build.log
./ex/bsdf_example
./ex/core_renderer > /dev/null
./ex/shader_furnace

step "COMPONENTS core alone from the moved prefix: only dspbr::core defined, no Ceres/OpenImageIO/TBB/glog linked"
"$cmake" -S "$src/examples" -B ex-core -DCMAKE_PREFIX_PATH="$prefix" -DDSPBR_COMPONENTS=core > ex-core-configure.log
"$cmake" --build ex-core -j2 > ex-core-build.log
[ -x ex-core/core_renderer ] && [ ! -e ex-core/bsdf_example ] || { echo "COMPONENTS core built the wrong programs"; exit 1; }
bash "$src/tests/core_links_alone.sh" ex-core/core_renderer > /dev/null

step "each component on its own from the moved prefix; an unknown one is refused"
for c in core lutgen formats validate fit conformance shaders; do
  mkdir -p "comp-$c"
  printf 'cmake_minimum_required(VERSION 3.20)\nproject(c LANGUAGES CXX)\nfind_package(dspbr CONFIG REQUIRED COMPONENTS %s)\nif(NOT TARGET dspbr::%s)\n  message(FATAL_ERROR "no dspbr::%s")\nendif()\n' \
    "$c" "$c" "$c" > "comp-$c/CMakeLists.txt"
  "$cmake" -S "comp-$c" -B "comp-$c/b" -DCMAKE_PREFIX_PATH="$prefix" > "comp-$c.log" || { cat "comp-$c.log"; exit 1; }
done
mkdir -p comp-bad
printf 'cmake_minimum_required(VERSION 3.20)\nproject(c LANGUAGES CXX)\nfind_package(dspbr CONFIG REQUIRED COMPONENTS nonsense)\n' > comp-bad/CMakeLists.txt
if "$cmake" -S comp-bad -B comp-bad/b -DCMAKE_PREFIX_PATH="$prefix" > comp-bad.log 2>&1; then
  echo "an unknown component was accepted"; exit 1
fi
grep -q "unknown dspbr component 'nonsense'" comp-bad.log || { cat comp-bad.log; exit 1; }

step "conformance kit from the moved prefix: generate (the installed scenes), the C harness, check (HTML)"
"$dspbr" conformance generate --directions 2 --no-albedo --out C > conformance.log
grep -q '"scenes":"validation scenes' C/vectors.json || { echo "the vectors lack the installed scenes"; exit 1; }
./ex/conformance_harness C/vectors.csv C/results.csv >> conformance.log
"$dspbr" conformance check C/vectors.json C/results.csv --out CR >> conformance.log ||
  { cat conformance.log; exit 1; }
[ -s CR/index.html ] || { echo "conformance check wrote no CR/index.html"; exit 1; }

step "examples/bsdf_example.cpp through dspbr.pc"
export PKG_CONFIG_PATH="$prefix/lib/pkgconfig"
pkg-config --modversion dspbr
[ "$(realpath "$(pkg-config --variable=prefix dspbr)")" = "$(realpath "$prefix")" ] ||
  { echo "dspbr.pc does not point at the moved prefix"; exit 1; }
# shellcheck disable=SC2046
c++ -std=c++17 -O1 "$src/examples/bsdf_example.cpp" -o pc_example $(pkg-config --cflags --libs dspbr)
./pc_example > /dev/null
step "ok"
