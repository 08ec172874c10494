#!/usr/bin/env bash
# Installs missing packages, configures and builds shadowc into build/ (or $SHADOWC_BUILD_DIR),
# through ccache when it is there (scripts/ccache.sh).
#   bash scripts/build.sh            everything: libraries, shadowc, samples, benches, tests
#   bash scripts/build.sh TARGET...  only those targets and what they need (demo.sh: shadowc)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${SHADOWC_BUILD_DIR:-$root/build}
bash "$root/scripts/install-deps.sh"
werror=OFF
[[ ${CI:-} == true ]] && werror=ON
source "$root/scripts/ccache.sh"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSHADOWC_WERROR=$werror "${ccache_args[@]}" >/dev/null
targets=()
for t in "$@"; do targets+=(--target "$t"); done
cmake --build "$build" -j "$(nproc)" "${targets[@]}"
ccache_report build.sh
