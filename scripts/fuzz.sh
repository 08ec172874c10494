#!/usr/bin/env bash
# Builds the libFuzzer targets (SHADOWC_FUZZ=ON: clang-14, ASan + UBSan, own build dir) and runs
# each from its checked-in seed corpus for a bounded time. Any crash, hang (-timeout), memory
# blow-up (-rss_limit_mb) or sanitizer report stops the run and fails this script; the input is
# left in $build/findings/<target>/ (make it a negative test: docs/integration.md, "Fuzzing").
# usage: scripts/fuzz.sh [TARGET...]   (default: filter scene manifest)
#   SHADOWC_FUZZ_SECONDS   seconds per target (default 60)
#   SHADOWC_FUZZ_BUILD_DIR build dir (default build-fuzz/)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${SHADOWC_FUZZ_BUILD_DIR:-$root/build-fuzz}
seconds=${SHADOWC_FUZZ_SECONDS:-60}
targets=("$@")
((${#targets[@]})) || targets=(filter scene manifest)

source "$root/scripts/ccache.sh"
CC=clang-14 CXX=clang++-14 cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSHADOWC_FUZZ=ON \
  -DBUILD_TESTING=OFF "${ccache_args[@]}" >/dev/null
cmake --build "$build" -j "$(nproc)" --target "${targets[@]/#/fuzz_}"
ccache_report fuzz.sh

export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
for t in "${targets[@]}"; do
  seeds=$root/tests/fuzz/corpus/$t
  work=$build/corpus/$t        # what the run adds; the checked-in seeds stay as they are
  findings=$build/findings/$t
  mkdir -p "$work" "$findings"
  echo "fuzz: $t for ${seconds}s from $(ls "$seeds" | wc -l) seeds"
  if ! "$build/tests/fuzz/fuzz_$t" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=16384 \
    -print_final_stats=1 -artifact_prefix="$findings/" "$work" "$seeds" >"$build/fuzz_$t.log" 2>&1; then
    tail -n 60 "$build/fuzz_$t.log" >&2
    echo "fuzz: $t FAILED; inputs in $findings/" >&2
    exit 1
  fi
  grep -E "^stat::number_of_executed_units|^stat::peak_rss_mb|^#[0-9]+.*DONE" "$build/fuzz_$t.log" || true
done
echo "fuzz: ${targets[*]}: no finding"
