#!/usr/bin/env bash
# The one way golden files change: rewrites every golden the tests compare
# against (parse dumps, diagnostics, renders; POV-Ray's references by running
# povray) from the current build, through the golden switch
# ASOS_UPDATE_GOLDENS=1 (tests/unit/goldens.hpp). Review the result with
# `git diff` before committing it (docs/goldens.md).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${ASOS_BUILD_DIR:-build}
cmake --build "$build" -j "$(nproc)"
ASOS_UPDATE_GOLDENS=1 "$build/tests/asos_tests" "[golden]"
