#!/usr/bin/env bash
# Installs, with apt-get, the Debian 12 packages shadowfx builds and tests with, skipping those already
# present. Needs root (or sudo). Nothing is downloaded from anywhere else.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config
  # lld links the test executables in less than half of GNU ld's time (CMake falls back to ld without it).
  lld
  # The sanitized build (scripts/configure-sanitized.sh) is clang's, for libFuzzer (libclang-rt-14-dev).
  clang libclang-rt-14-dev
  glslang-dev glslang-tools spirv-tools
  libspirv-cross-c-shared-dev spirv-cross
  libglm-dev libosmesa6-dev libegl-dev libegl1-mesa-dev libgl-dev libgl1-mesa-dri libglfw3-dev
  libgtest-dev libgmock-dev libbenchmark-dev libstb-dev
  libassimp-dev nlohmann-json3-dev
  # DXT blocks of the DDS texture files FX Composer and DirectX SDK effects name (runtime/TextureFile.h).
  libsquish-dev
  # Meshes the built-in scenes read where Debian installs them (runtime/assets/src/AssetScenes.cpp).
  glmark2-data assimp-testmodels
  # `shadowfx bench`: Embree casts the ground truth's shadow rays; gnuplot draws scripts/gamma_sweep.py's plot.
  libembree-dev gnuplot-nox
  # `shadowfx view`: Dear ImGui (static, with its GLFW/OpenGL3 backends); Xvfb runs its test without a display.
  libimgui-dev xvfb
  # `shadowfx bench --peers osg`: OpenSceneGraph's osgShadow on the same scenes (benchmarks/peers/).
  libopenscenegraph-dev
  # scripts/gamma_sweep.py (the main job's γ sweep) and scripts/bench_paired_ratios.py.
  python3
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

echo "install-deps: installing ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
