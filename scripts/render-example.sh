#!/usr/bin/env bash
# The README's first command: sets up (installs missing Debian packages,
# configures, builds) and renders the default example scene. Until the
# renderer exists it parses examples/default.pov and prints the scene
# description; the renderer issue switches it to a render.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
build=${ASOS_BUILD_DIR:-build}
exec "$build/asos" parse examples/default.pov "$@"
