#!/usr/bin/env bash
# Installs the Debian packages the project needs (idempotent, non-interactive).
# Does nothing when everything is already installed.
set -euo pipefail
PKGS=(build-essential cmake pkg-config
      libopenimageio-dev openimageio-tools libopenexr-dev
      libceres-dev libeigen3-dev libtbb-dev
      libgtest-dev libgmock-dev libbenchmark-dev
      nlohmann-json3-dev libcli11-dev libfmt-dev
      libboost-dev glslang-tools libglm-dev
      python3-numpy python3-matplotlib python3-jinja2 python3-openimageio
      python3-dev pybind11-dev python3-pybind11 python3-pytest
      python3-venv python3-pip python3-setuptools python3-wheel mypy  # pip install . (pyproject.toml), stubs
      mesa-vulkan-drivers libvulkan-dev  # lavapipe: the shader tests on a Vulkan driver (tests/vulkan.cmake)
      spirv-tools  # spirv-opt / spirv-dis: the shader library's SPIR-V cost (scripts/shaders/spirv_cost.sh)
      clang libclang-rt-14-dev)  # libFuzzer + sanitizers (fuzz/, CTest fuzz_short)
missing=()
for p in "${PKGS[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}"
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
else
  echo "setup: all packages present"
fi
