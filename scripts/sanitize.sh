#!/usr/bin/env bash
# The sanitizer half of CI (docs/robustness.md): one clang-14 build at -O1
# with AddressSanitizer, UndefinedBehaviorSanitizer and libFuzzer's coverage
# (ASOS_FUZZ) in ./build-sanitize, whose objects serve both the unit tests
# and the fuzz targets; then the tests labelled `sanitize` and each fuzz
# target for SECONDS (default 60) over its seeds.
#   scripts/sanitize.sh [SECONDS]
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
build=${ASOS_SANITIZE_BUILD_DIR:-build-sanitize}
ASOS_SETUP_ONLY_PACKAGES=1 scripts/setup.sh
# -O1 without -g: the cheapest build the sanitizers are useful at.
cmake -S . -B "$build" -G Ninja -DCMAKE_CXX_COMPILER=clang++-14 -DCMAKE_BUILD_TYPE=Release \
      "-DCMAKE_CXX_FLAGS_RELEASE=-O1 -DNDEBUG" -DASOS_FUZZ=ON >/dev/null
cmake --build "$build" -j "$(nproc)"
ctest --test-dir "$build" -L sanitize --output-on-failure -j "$(nproc)"
ASOS_FUZZ_BUILD_DIR=$build ASOS_FUZZ_CONFIGURED=1 scripts/fuzz.sh "$seconds"
