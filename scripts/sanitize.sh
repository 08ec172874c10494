#!/usr/bin/env bash
# Builds every target with AddressSanitizer + UndefinedBehaviorSanitizer (SHADOWC_SANITIZE=ON,
# own build dir) and runs the ctest suite in it. A sanitizer report fails its test: UBSan stops
# at the first report (-fno-sanitize-recover), ASan/LSan exit non-zero. Suppressions are only for
# third-party code, each with its reason: tests/sanitizers/{lsan,ubsan}.supp.
# usage: scripts/sanitize.sh [CTEST ARGS...]   (e.g. -L dsl)
#   SHADOWC_SANITIZE_BUILD_DIR build dir (default build-asan/)
#   SHADOWC_SANITIZE_LABELS    ctest label regex (default: every test that parses or compiles
#                              untrusted input — the front end, checker, planner, driver, manifest,
#                              CLI error paths and the fuzz corpora; "all" = the whole suite)
# Why not the whole suite by default: the GPU, stability and emit labels under ASan take longer
# than CI's budget on 2 cores (measured: the normal suite alone is ~9 min there), and they were
# not yet run clean under ASan (docs/integration.md "Sanitizers" says what is covered).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${SHADOWC_SANITIZE_BUILD_DIR:-$root/build-asan}
werror=OFF
[[ ${CI:-} == true ]] && werror=ON
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSHADOWC_SANITIZE=ON -DSHADOWC_WERROR=$werror \
  "${launcher[@]}" >/dev/null
labels=${SHADOWC_SANITIZE_LABELS:-dsl|spec|plan|manifest|driver|architecture|cli|fuzz}
if [[ $labels == all ]]; then
  cmake --build "$build" -j "$(nproc)"
else
  # Only what those labels run: their test executables, the corpus replays and the shadowc binary.
  cmake --build "$build" -j "$(nproc)" --target shadowc tests_dsl tests_spec tests_plan tests_manifest tests_driver \
    tests_architecture tests_cli replay_filter replay_scene replay_manifest
fi

supp=$root/tests/sanitizers
export ASAN_OPTIONS=detect_leaks=1:check_initialization_order=1:strict_init_order=1
export LSAN_OPTIONS=suppressions=$supp/lsan.supp:print_suppressions=0
export UBSAN_OPTIONS=suppressions=$supp/ubsan.supp:print_stacktrace=1:halt_on_error=1
cd "$build"
if [[ $labels == all ]]; then
  ctest --output-on-failure -j "$(nproc)" "$@"
else
  ctest --output-on-failure -j "$(nproc)" -L "$labels" "$@"
fi
