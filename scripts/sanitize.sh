#!/usr/bin/env bash
# Builds every target with AddressSanitizer + UndefinedBehaviorSanitizer (SHADOWC_SANITIZE=ON,
# own build dir) and runs the ctest suite in it. A sanitizer report fails its test: UBSan stops
# at the first report (-fno-sanitize-recover), ASan/LSan exit non-zero. Suppressions are only for
# third-party code, each with its reason: tests/sanitizers/{lsan,ubsan}.supp.
# usage: scripts/sanitize.sh [CTEST ARGS...]   (e.g. -L dsl)
#   SHADOWC_SANITIZE_BUILD_DIR build dir (default build-asan/)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${SHADOWC_SANITIZE_BUILD_DIR:-$root/build-asan}
werror=OFF
[[ ${CI:-} == true ]] && werror=ON
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSHADOWC_SANITIZE=ON -DSHADOWC_WERROR=$werror \
  "${launcher[@]}" >/dev/null
cmake --build "$build" -j "$(nproc)"

supp=$root/tests/sanitizers
export ASAN_OPTIONS=detect_leaks=1:check_initialization_order=1:strict_init_order=1
export LSAN_OPTIONS=suppressions=$supp/lsan.supp:print_suppressions=0
export UBSAN_OPTIONS=suppressions=$supp/ubsan.supp:print_stacktrace=1:halt_on_error=1
cd "$build"
ctest --output-on-failure -j "$(nproc)" "$@"
