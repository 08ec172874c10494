#!/usr/bin/env bash
# Installs missing packages, configures and builds shadowc into build/ (or $SHADOWC_BUILD_DIR).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${SHADOWC_BUILD_DIR:-$root/build}
bash "$root/scripts/install-deps.sh"
werror=OFF
[[ ${CI:-} == true ]] && werror=ON
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSHADOWC_WERROR=$werror >/dev/null
cmake --build "$build" -j "$(nproc)"
