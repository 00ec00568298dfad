#!/usr/bin/env bash
# `dspbr shader --scene` for every validation scene (data/dspbr/scenes/sphere): the header it
# writes compiles in C++ under strict warnings, and the GLSL conformance kernel built with it
# passes that scene's conformance vectors on the Vulkan device (scenes with the same header share
# one build). Prints a line per distinct specialisation; exit 1 on a failure, 77 without a device.
#   specializations.sh DSPBR VK_RUNNER VECTORS.json SOURCE_DIR WORK_DIR
set -euo pipefail
dspbr=$1 runner=$2 vectors=$3 src=$4 work=$5
rm -rf "$work" && mkdir -p "$work"
declare -A scenes_of
for scene in "$src"/data/dspbr/scenes/sphere/*.gltf; do
  stem=$(basename "$scene" .gltf)
  "$dspbr" shader --scene "$scene" --out "$work/scene-$stem" > /dev/null
  # Scenes whose headers differ only in the first comment line (the scene's name) share a build.
  key=$(tail -n +2 "$work/scene-$stem/dspbr_specialization.h" | sha256sum | cut -c1-16)
  scenes_of[$key]="${scenes_of[$key]:+${scenes_of[$key]},}scenes/$stem/"
  [ -e "$work/spec-$key" ] || cp -r "$work/scene-$stem" "$work/spec-$key"
done
status=0
for key in $(printf '%s\n' "${!scenes_of[@]}" | sort); do
  dir="$work/spec-$key"
  components=$(sed -n 's|^// Compiled in: \(.*\)\.$|\1|p' "$dir/dspbr_specialization.h")
  g++ -std=c++17 -Wall -Wextra -Wconversion -Wshadow -Werror -fsyntax-only -include "$dir/dspbr_specialization.h" \
      -I"$src/shaders" -I"$src/luts" "$src/tests/shader_library/shader_warnings.cpp"
  glslangValidator -V -DDSPBR_USE_SPECIALIZATION -DDSPBR_TEST_NO_ALBEDO -I"$dir" -I"$src/shaders" -I"$src/luts" \
      -I"$src/tests/shader_library" -o "$dir/kernel.spv" "$src/tests/shader_library/conformance.comp" > /dev/null
  set +e
  out=$("$runner" "$dir/kernel.spv" "$vectors" "$src/luts" "glsl[$components]" --ids "${scenes_of[$key]}" --no-albedo)
  rc=$?
  set -e
  [ $rc -eq 77 ] && { echo "no Vulkan device: skipped"; exit 77; }
  echo "$out" | tail -1
  [ $rc -eq 0 ] || { echo "$out" | grep FAIL | head -5; status=1; }
done
exit $status
