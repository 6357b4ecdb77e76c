#!/usr/bin/env bash
# The one way golden files change: rewrites every golden the tests compare
# against (parse dumps, diagnostics, renders) from the current build. Review
# the result with `git diff` before committing it.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${ASOS_BUILD_DIR:-build}
cmake --build "$build" -j "$(nproc)"
ASOS_UPDATE_GOLDENS=1 "$build/tests/asos_tests" "[golden]"
