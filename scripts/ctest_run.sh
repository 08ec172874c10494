# Sourced by test.sh and sanitize.sh: `run_ctest NAME ARGS...` runs ctest in the current build dir
# with ARGS, slowest tests first, and prints the ten slowest of the run at the end (and appends
# them to $SHADOWC_SLOWEST_LOG when set: test.sh repeats them after its last stage).
# Slowest first: ctest orders a parallel run by Testing/Temporary/CTestCostData.txt (each test's
# mean time in earlier runs), so -j2 does not end on one long test while the other core idles.
# A fresh clone has none, so the file is kept beside the compiler cache, outside the clone, one per
# NAME (the instrumented and the plain suite differ), and copied in before and out after the run.
#   SHADOWC_CTEST_COST_DIR  where (default ${XDG_CACHE_HOME:-$HOME/.cache}/shadowc-ctest)
run_ctest() {
  local name=$1
  shift
  local store=${SHADOWC_CTEST_COST_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/shadowc-ctest}
  local cost=Testing/Temporary/CTestCostData.txt kept log rc=0
  kept=$store/$name-CTestCostData.txt
  log=$(mktemp)
  mkdir -p Testing/Temporary "$store"
  [[ -f $cost || ! -f $kept ]] || cp "$kept" "$cost"
  ctest "$@" 2>&1 | tee "$log" || rc=$?
  [[ -f $cost ]] && cp "$cost" "$kept.tmp" && mv "$kept.tmp" "$kept"
  # "  12/1259 Test  #345: Suite.Name ......   Passed   12.34 sec": name and seconds.
  local slowest
  slowest=$(awk '/ Test +#[0-9]+: / { for (i = 1; i <= NF; ++i) if ($i ~ /^#[0-9]+:$/) n = $(i + 1);
         if ($NF == "sec") printf "%10.2f s  %s\n", $(NF - 1), n }' "$log" | sort -rn | awk 'NR <= 10')
  rm -f "$log"
  printf '%s: the ten slowest tests of this run\n%s\n' "$name" "$slowest" | tee -a "${SHADOWC_SLOWEST_LOG:-/dev/null}"
  return "$rc"
}
