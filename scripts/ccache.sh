# Sourced by build.sh, sanitize.sh and fuzz.sh: compile through ccache when it is installed, with
# one cache outside the clone, so that a fresh clone of the same commit (in any folder) on the same
# machine reuses what an earlier build compiled. Without ccache nothing changes.
#   SHADOWC_CCACHE_DIR  the cache (default ${XDG_CACHE_HOME:-$HOME/.cache}/shadowc-ccache)
#   SHADOWC_CCACHE=0    build without it
# Hits across clone paths (ccache(1), "Compiling in different directories"): base_dir makes the
# absolute -I, source and -MF paths under the clone relative before hashing; -fdebug-prefix-map
# writes the clone as "." into the debug info, so a cached object names no other clone's folder
# and the working directory drops out of the hash. Set by the caller: $root (the clone).
# After sourcing: ${ccache_args[@]} for cmake's configure line; ccache_report STAGE prints the
# hits and misses since the source.
ccache_args=()
ccache_before=""
if [[ ${SHADOWC_CCACHE:-1} != 0 ]] && command -v ccache >/dev/null; then
  export CCACHE_DIR=${SHADOWC_CCACHE_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/shadowc-ccache}
  export CCACHE_BASEDIR=$root
  # Three builds (plain, ASan, fuzz) of about 1.3 GiB of objects each, with room for a few commits.
  export CCACHE_MAXSIZE=${CCACHE_MAXSIZE:-12G}
  mkdir -p "$CCACHE_DIR"
  ccache_args=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache "-DSHADOWC_PREFIX_MAP_FLAGS=-fdebug-prefix-map=$root=.")
  ccache_before=$(ccache --print-stats 2>/dev/null || true)
else
  # A cache used before must not stay set in the build dir when ccache is gone or turned off.
  ccache_args=(-UCMAKE_CXX_COMPILER_LAUNCHER -DSHADOWC_PREFIX_MAP_FLAGS=)
fi

# ccache --print-stats: one "name<TAB>value" line per counter; the stage's share is after - before.
ccache_counter() { awk -v k="$1" -F'\t' '$1 == k { print $2; found = 1 } END { if (!found) print 0 }'; }
ccache_report() {
  [[ -n $ccache_before ]] || { echo "$1: ccache not used"; return 0; }
  local after hits misses
  after=$(ccache --print-stats 2>/dev/null || true)
  hits=$(($(ccache_counter direct_cache_hit <<<"$after") + $(ccache_counter preprocessed_cache_hit <<<"$after") -
    $(ccache_counter direct_cache_hit <<<"$ccache_before") - $(ccache_counter preprocessed_cache_hit <<<"$ccache_before")))
  misses=$(($(ccache_counter cache_miss <<<"$after") - $(ccache_counter cache_miss <<<"$ccache_before")))
  if ((hits + misses == 0)); then
    echo "$1: ccache: nothing compiled (the build was up to date)"
  else
    echo "$1: ccache: $hits hits, $misses misses, hit rate $((100 * hits / (hits + misses))) % ($CCACHE_DIR)"
  fi
}
