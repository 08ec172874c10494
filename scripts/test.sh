#!/usr/bin/env bash
# The README's second command (and .ci/run): set up, build, run every test.
# Validation layers are on for every GPU test (tests/CMakeLists.txt sets SHADOWC_VALIDATION=1).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${SHADOWC_BUILD_DIR:-$root/build}
bash "$root/scripts/build.sh"
cd "$build"
ctest --output-on-failure -j "$(nproc)" "$@"
