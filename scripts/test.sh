#!/usr/bin/env bash
# The README's second command (and .ci/run): set up, build, run every test, then fuzz.
# Validation layers are on for every GPU test (tests/CMakeLists.txt sets SHADOWC_VALIDATION=1).
#   sanitize  scripts/sanitize.sh: install what is missing, build everything with ASan + UBSan
#             (build-asan/) and run the whole ctest suite in it (extra arguments go to this ctest)
#   fuzz      scripts/fuzz.sh: each libFuzzer target for SHADOWC_FUZZ_SECONDS (default 60; build-fuzz/)
#   suite     scripts/build.sh (all of build/, where the demo builds shadowc alone), then the whole
#             suite uninstrumented there
# SHADOWC_TEST_STAGES picks stages (default "sanitize fuzz"; e.g. SHADOWC_TEST_STAGES=suite).
# Why the default runs the suite only instrumented: the same 1083 tests, once, every one also
# checked for memory errors, leaks and undefined behaviour; a second, uninstrumented build and run
# would take CI past its 45-minute budget (measured 2026-12-02 on 2 cores: the suite 145 s plain,
# 464 s instrumented; docs/integration.md "Sanitizers").
# Prints each stage's wall time and compiler-cache hit rate (scripts/ccache.sh), and at the end the
# ten slowest tests of each ctest run (scripts/ctest_run.sh); stops at the first failing stage.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${SHADOWC_BUILD_DIR:-$root/build}
stages=${SHADOWC_TEST_STAGES:-sanitize fuzz}
times=()
# Each ctest run's ten slowest tests (scripts/ctest_run.sh), printed again at the end.
export SHADOWC_SLOWEST_LOG=$(mktemp)
trap 'rm -f "$SHADOWC_SLOWEST_LOG"' EXIT

source "$root/scripts/ctest_run.sh"
suite() {
  bash "$root/scripts/build.sh"
  (cd "$build" && run_ctest suite --output-on-failure -j "$(nproc)" "$@")
}
run_stage() {
  local name=$1 start=$SECONDS
  shift
  echo "test.sh: stage $name"
  "$@"
  times+=("$name $((SECONDS - start)) s")
  echo "test.sh: stage $name passed in $((SECONDS - start)) s"
}

for stage in $stages; do
  case $stage in
  suite) run_stage suite suite "$@" ;;
  sanitize) run_stage sanitize bash "$root/scripts/sanitize.sh" "$@" ;;
  fuzz) run_stage fuzz bash "$root/scripts/fuzz.sh" ;;
  *) echo "test.sh: unknown stage '$stage' (suite, sanitize, fuzz)" >&2; exit 2 ;;
  esac
done
cat "$SHADOWC_SLOWEST_LOG"
echo "test.sh: all passed (${times[*]/%/;} total $SECONDS s)"
