#!/usr/bin/env bash
# Installs every Debian package shadowc needs that is not already present.
# Idempotent: does nothing (and needs no root) when everything is installed.
set -euo pipefail
PKGS=(
  cmake make g++ pkg-config
  glslang-dev glslang-tools spirv-tools           # GLSL -> SPIR-V, spirv-opt, spirv-val (in process)
  libspirv-cross-c-shared-dev                     # SPIRV-Cross C++ libraries: --emit hlsl,msl (in process)
  libxxhash-dev                                   # manifest content hash (XXH3-128)
  libvulkan-dev mesa-vulkan-drivers vulkan-validationlayers vulkan-tools   # loader, lavapipe, Khronos layers
  libglm-dev libfmt-dev nlohmann-json3-dev libcli11-dev libstb-dev          # math, format, JSON, CLI, PNG
  libembree-dev libtbb-dev libassimp-dev zlib1g-dev              # reference, meshes (assimp links libz.so)
  libgtest-dev libgmock-dev libbenchmark-dev                                # tests and benchmarks
  gnuplot-nox                                     # shadowc sweep: time-vs-RMSE plots (SVG, PNG)
  chromium                                        # sweep report test: headless load and screenshot
  slurm-wlm munge parallel                        # sweeps on a cluster: job array test, GNU parallel
  assimp-testmodels                             # real meshes of the duck/spider/engine scenes (/usr/share/assimp/models)
  ninja-build                                     # tests/integration drives a consumer with Ninja and make
  clang-14 libclang-rt-14-dev                     # libFuzzer + ASan/UBSan runtimes (scripts/fuzz.sh)
  ccache                                          # compiler cache shared by clones (scripts/ccache.sh)
)
missing=()
for p in "${PKGS[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]} == 0)); then
  echo "install-deps: all ${#PKGS[@]} packages present"
  exit 0
fi
echo "install-deps: installing ${#missing[@]} missing packages: ${missing[*]}"
SUDO=""
if [[ $(id -u) -ne 0 ]]; then
  command -v sudo >/dev/null || { echo "install-deps: error: need root or sudo to install: ${missing[*]}" >&2; exit 1; }
  SUDO=sudo
fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "install-deps: done"
