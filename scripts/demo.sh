#!/usr/bin/env bash
# The README's first command: set up, build, and run the main job on the built-in default.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bash "$root/scripts/build.sh"
"${SHADOWC_BUILD_DIR:-$root/build}/cli/shadowc" demo "$@"
