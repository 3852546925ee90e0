#!/usr/bin/env bash
# Installs the Debian 12 packages glintlab needs, if any are missing.
# Usage: tools/install-deps.sh          what building, testing and running need (ffmpeg: animate's MP4s;
#                                       clang and its libFuzzer runtime: the fuzz targets, docs/fuzzing.md;
#                                       GLFW and Dear ImGui: the viewer; xvfb: its test on a virtual display;
#                                       chromium: the HTML report's test in a real browser; GNU parallel: the
#                                       tiled-reference recipe's test; glslang and
#                                       SPIRV-Tools: glintlab-shader-stats and shader tests; SPIRV-Cross:
#                                       glintlab export's HLSL and MSL; pybind11, numpy and pytest: the
#                                       Python module and its tests)
#        tools/install-deps.sh demo     only what building and running the glintlab binary need (make demo):
#                                       no test, benchmark, fuzzing, video or browser packages
#        tools/install-deps.sh results  also what the runs of tools/results.py use (jq: tools/bench-constant-cost.sh)
# (as root, or with sudo available)
set -euo pipefail

# Building and running glintlab: the compiler and build tools, OpenGL through EGL on Mesa (llvmpipe
# without a GPU), the header libraries, GLFW and Dear ImGui (the viewer is part of the binary),
# Embree and TBB (the path tracer's rays) and the font the worst-region crops are labelled with.
demo_packages=(
  build-essential cmake ninja-build pkg-config
  libepoxy-dev libegl-dev libgl-dev libegl-mesa0 libgl1-mesa-dri
  libglm-dev libopenexr-dev libstb-dev libtinygltf-dev libtinyobjloader-dev
  libtomlplusplus-dev libcli11-dev nlohmann-json3-dev libeigen3-dev
  libglfw3-dev libimgui-dev
  libembree-dev libtbb-dev
  fonts-dejavu-core
)
packages=("${demo_packages[@]}"
  libgtest-dev libgmock-dev libbenchmark-dev
  glslang-tools glslang-dev spirv-tools spirv-headers spirv-cross
  pybind11-dev python3-dev python3-numpy python3-pytest
  clang libclang-rt-dev
  ffmpeg parallel
  xvfb xauth chromium
)
case "${1:-}" in
  "") ;;
  demo) packages=("${demo_packages[@]}") ;;
  results) packages+=(jq) ;;
  *) echo "tools/install-deps.sh: unknown list '$1'; allowed: demo, results, or none (everything)" >&2; exit 2 ;;
esac

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

echo "glintlab: installing missing packages: ${missing[*]}"
sudo=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "glintlab: need root (or sudo) to install: ${missing[*]}" >&2; exit 1; }
  sudo="sudo"
fi
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
