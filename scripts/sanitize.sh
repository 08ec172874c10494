#!/usr/bin/env bash
# Builds every target with AddressSanitizer + UndefinedBehaviorSanitizer (SHADOWC_SANITIZE=ON,
# own build dir) and runs the ctest suite in it. A sanitizer report fails its test: UBSan stops
# at the first report (-fno-sanitize-recover), ASan/LSan exit non-zero. Suppressions are only for
# third-party code, each with its reason: tests/sanitizers/{lsan,ubsan}.supp.
# usage: scripts/sanitize.sh [CTEST ARGS...]   (e.g. -L dsl)
#   SHADOWC_SANITIZE_BUILD_DIR build dir (default build-asan/)
#   SHADOWC_SANITIZE_LABELS    ctest label regex (default "all": the whole suite, GPU tests on
#                              lavapipe with validation layers included; any other regex, e.g.
#                              "dsl|spec|cli", builds only the input-parsing test folders and runs
#                              the tests with those labels)
# The whole suite ran clean this way on 2026-12-02 (1083 tests, 464 s on 2 cores).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${SHADOWC_SANITIZE_BUILD_DIR:-$root/build-asan}
bash "$root/scripts/install-deps.sh"
# Warnings are errors here as in CI (SHADOWC_WERROR=OFF to relax): the same flags in the session's
# run and CI's, so CI's fresh clone hits the compiler cache (scripts/ccache.sh) the session filled.
werror=${SHADOWC_WERROR:-ON}
source "$root/scripts/ccache.sh"
# -O1 -g1 (line tables), not RelWithDebInfo's -O2 -g: the instrumented build is the stage's largest
# cost, and these flags bring it near the normal build's (measured, compiling filter_spec.cpp:
# 17 s of CPU instrumented at -O1 -g1, 31 s at -O2 -g, 14 s uninstrumented at -O2 -g) while reports
# keep function names and lines. ASan's documentation suggests -O1 for reasonable performance.
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" \
  -DSHADOWC_SANITIZE=ON -DSHADOWC_WERROR=$werror "${ccache_args[@]}" >/dev/null
labels=${SHADOWC_SANITIZE_LABELS:-all}
if [[ $labels == all ]]; then
  cmake --build "$build" -j "$(nproc)"
else
  # Only what those labels run: their test executables, the corpus replays and the shadowc binary.
  cmake --build "$build" -j "$(nproc)" --target shadowc tests_dsl tests_spec tests_plan tests_manifest tests_driver \
    tests_architecture tests_cli replay_filter replay_scene replay_manifest
fi
ccache_report sanitize.sh

supp=$root/tests/sanitizers
export ASAN_OPTIONS=detect_leaks=1:check_initialization_order=1:strict_init_order=1
export LSAN_OPTIONS=suppressions=$supp/lsan.supp:print_suppressions=0
export UBSAN_OPTIONS=suppressions=$supp/ubsan.supp:print_stacktrace=1:halt_on_error=1
cd "$build"
source "$root/scripts/ctest_run.sh"
if [[ $labels == all ]]; then
  run_ctest sanitize --output-on-failure -j "$(nproc)" "$@"
else
  run_ctest sanitize --output-on-failure -j "$(nproc)" -L "$labels" "$@"
fi
