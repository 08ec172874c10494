#!/usr/bin/env bash
# The CMake package from outside the tree (ctest label `integration`; tests/integration/CMakeLists.txt).
# usage: consumer_test.sh STEP SHADOWC_BUILD_DIR SOURCE_DIR GENERATOR
# (run for Ninja and Unix Makefiles: they read depfiles differently, and Ninja is the stricter)
#   install      cmake --install the shadowc build into an install prefix in the build dir
#   first_build  configure tests/integration/consumer against it, build: both filters' outputs
#   noop         build again, nothing changed: no output is rewritten
#   touch_one    touch esm.shadow, build: exactly esm's outputs are rewritten, pcf_poisson16's not
#   interface    an existing INTERFACE library as TARGET: building `all` compiles its filters
#   intree       the same function in shadowc's own build (shadowc::shadowc is the in-tree
#                executable, as after add_subdirectory): byte-identical outputs
set -euo pipefail
step=$1 bin=$2 src=$3 gen=$4
work=$bin/integration/${gen// /_}
prefix=$work/prefix proj=$work/consumer build=$work/consumer-build
out=$build/shaders
fail() { echo "FAIL: $*" >&2; exit 1; }
outputs_newer_than() { find "$out" -type f -newer "$1" | sort; }

case $step in
install)
  rm -rf "$prefix"
  cmake --install "$bin" --prefix "$prefix"
  [[ -x $prefix/bin/shadowc ]] || fail "no executable in $prefix/bin"
  for f in shadowc-config.cmake shadowc-config-version.cmake shadowc-targets.cmake ShadowcFilters.cmake; do
    [[ -f $prefix/lib/cmake/shadowc/$f ]] || fail "$f not installed"
  done
  [[ -f $prefix/include/shadowc/frame.h ]] || fail "the integration header is not installed"
  grep -q "shadowc::frame" "$prefix/lib/cmake/shadowc/shadowc-targets.cmake" || fail "no shadowc::frame target"
  ;;
first_build)
  rm -rf "$proj" "$build"
  mkdir -p "$proj/filters"
  cp "$src/tests/integration/consumer/CMakeLists.txt" "$proj/"
  cp "$src/samples/filters/esm.shadow" "$src/samples/filters/pcf_poisson16.shadow" "$proj/filters/"
  cmake -S "$proj" -B "$build" -G "$gen" -DCMAKE_PREFIX_PATH="$prefix" -DFILTER_DIR="$proj/filters"
  grep -q "^shadowc_DIR:PATH=$prefix/lib/cmake/shadowc\$" "$build/CMakeCache.txt" ||
    fail "the consumer did not find the installed package"
  cmake --build "$build"
  for f in esm pcf_poisson16; do
    for o in manifest.json ${f}_lookup.glsl $f.d; do
      [[ -s $out/$f/$o ]] || fail "missing $out/$f/$o"
    done
    ls "$out/$f"/*.spv >/dev/null || fail "no SPIR-V for $f"
    grep -q "\"filter\": \"$f\"" "$out/$f/manifest.json" || fail "$f/manifest.json names another filter"
  done
  ;;
noop)
  marker=$work/noop.marker
  touch "$marker"
  cmake --build "$build"
  newer=$(outputs_newer_than "$marker")
  [[ -z $newer ]] || fail "a no-op build rewrote: $newer"
  ;;
touch_one)
  marker=$work/touch.marker
  touch "$marker"
  touch "$proj/filters/esm.shadow"
  cmake --build "$build"
  newer=$(outputs_newer_than "$marker")
  expected=$(find "$out/esm" -type f | sort)
  [[ -n $newer ]] || fail "touching esm.shadow rebuilt nothing"
  [[ $newer == "$expected" ]] || fail "rebuilt: [$newer], expected exactly esm's outputs: [$expected]"
  ;;
interface)
  # An existing INTERFACE library as TARGET: `all` builds its filters (it builds nothing itself).
  iproj=$work/interface iout=$work/interface-build/shaders/esm
  rm -rf "$iproj" "$work/interface-build"
  mkdir -p "$iproj"
  cp "$src/samples/filters/esm.shadow" "$iproj/"
  cat >"$iproj/CMakeLists.txt" <<'CMAKE'
cmake_minimum_required(VERSION 3.25)
project(shadowc_interface LANGUAGES NONE)
find_package(shadowc 0.1 CONFIG REQUIRED)
add_library(engine_shaders INTERFACE)
shadowc_add_filters(TARGET engine_shaders FILES ${CMAKE_CURRENT_SOURCE_DIR}/esm.shadow OUTPUT_DIR shaders)
CMAKE
  cmake -S "$iproj" -B "$work/interface-build" -G "$gen" -DCMAKE_PREFIX_PATH="$prefix"
  cmake --build "$work/interface-build"
  [[ -s $iout/manifest.json && -s $iout/esm_lookup.glsl ]] || fail "the INTERFACE target's filters were not built"
  ;;
intree)
  cmake --build "$bin" --target shadowc_intree_filters
  [[ -s $bin/tests/integration/intree/esm/manifest.json ]] || fail "no in-tree manifest"
  # The depfiles name their own paths; every other file must be the same bytes.
  diff -r -x '*.d' "$bin/tests/integration/intree/esm" "$out/esm" || fail "in-tree and installed outputs differ"
  ;;
*) fail "unknown step '$step'" ;;
esac
echo "PASS: $step"
