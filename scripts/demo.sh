#!/usr/bin/env bash
# The README's first command: set up, build what the demo runs (the shadowc executable alone, not
# the test suite: scripts/test.sh builds everything), and run the main job on the built-in default.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bash "$root/scripts/build.sh" shadowc
"${SHADOWC_BUILD_DIR:-$root/build}/cli/shadowc" demo "$@"
