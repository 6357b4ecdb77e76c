#!/usr/bin/env bash
# The README's first command: sets up (installs missing Debian packages,
# configures, builds) and renders the default example scene with ASOS to
# build/default.png (640 x 480). Extra arguments go to `asos render`, e.g.
#   scripts/render-example.sh --stats --method jitter -o build/jitter.png
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
build=${ASOS_BUILD_DIR:-build}
"$build/asos" render examples/default.pov -o "$build/default.png" "$@"
echo "render-example: wrote $build/default.png (or the -o you gave)" >&2
