#!/usr/bin/env bash
# The README's second command (and .ci/run): set up, build, run every test, then the hardening
# stages. Validation layers are on for every GPU test (tests/CMakeLists.txt sets SHADOWC_VALIDATION=1).
#   suite     scripts/build.sh, then the whole ctest suite (extra arguments go to this ctest)
#   sanitize  scripts/sanitize.sh: the suite built and run with ASan + UBSan (build-asan/)
#   fuzz      scripts/fuzz.sh: each libFuzzer target for SHADOWC_FUZZ_SECONDS (default 60; build-fuzz/)
# SHADOWC_TEST_STAGES picks stages (default "suite fuzz"; e.g. SHADOWC_TEST_STAGES="suite sanitize fuzz").
# The sanitize stage is not in the default yet: on this tree only its fuzz label (the corpus
# replays) has run clean so far; the other labels were not yet built instrumented (docs/integration.md).
# Prints each stage's wall time; stops at the first failing stage.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${SHADOWC_BUILD_DIR:-$root/build}
stages=${SHADOWC_TEST_STAGES:-suite fuzz}
times=()

suite() {
  bash "$root/scripts/build.sh"
  (cd "$build" && ctest --output-on-failure -j "$(nproc)" "$@")
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
  sanitize) run_stage sanitize bash "$root/scripts/sanitize.sh" ;;
  fuzz) run_stage fuzz bash "$root/scripts/fuzz.sh" ;;
  *) echo "test.sh: unknown stage '$stage' (suite, sanitize, fuzz)" >&2; exit 2 ;;
  esac
done
echo "test.sh: all passed (${times[*]/%/;} total $SECONDS s)"
