#!/usr/bin/env bash
# shadowc sweep in N shards with GNU parallel, then merged (docs/sweep.md "On a cluster").
#
#   scripts/slurm/sweep_parallel.sh samples/sweeps/default.json out/sweep 4
#   scripts/slurm/sweep_parallel.sh SPEC OUT 8 --sshloginfile hosts.txt   # across machines
#
# Extra arguments go to parallel. On one machine the shards run one at a time (-j1 unless you
# pass -j): shards running side by side share the CPUs and disturb each other's timings. With
# --sshloginfile each host runs shards on its own (SPEC, the binary and OUT must be on a shared
# file system). SHADOWC = the shadowc binary (default: shadowc on PATH).
set -euo pipefail
SPEC=${1:?usage: sweep_parallel.sh SPEC OUTDIR N [parallel options]}
OUT=${2:?usage: sweep_parallel.sh SPEC OUTDIR N [parallel options]}
N=${3:?usage: sweep_parallel.sh SPEC OUTDIR N [parallel options]}
shift 3
SHADOWC=${SHADOWC:-shadowc}
mkdir -p "$OUT"
seq 0 $((N - 1)) | parallel -j1 --halt now,fail=1 "$@" \
  "$SHADOWC" sweep "$SPEC" -o "$OUT/shard-{}" --shard "{}/$N" --progress lines
"$SHADOWC" sweep merge "$OUT"/shard-* -o "$OUT/merged"
