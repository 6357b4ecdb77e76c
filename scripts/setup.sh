#!/usr/bin/env bash
# Installs the Debian 12 packages asos needs (only those missing), then
# configures and builds a Release tree in ./build. Safe to run repeatedly.
#   scripts/setup.sh            library, command line and tests
#   ASOS_EXTRA_PACKAGES="..."   more packages to install
#   ASOS_SETUP_ONLY_PACKAGES=1  install the packages, build nothing
# POV-Ray comes too: its include files are what `#include "colors.inc"` finds,
# the tests compare with it, and its example scenes are the corpus test's.
# GNU parallel runs docs/manual/farm.md's recipe in the farm test; gnuplot
# draws `asos-bench accuracy`'s charts (docs/performance.md); clang-14 and
# its runtimes (the sanitizers', libFuzzer's: libclang-rt-14-dev) build the
# sanitizer half of CI and the fuzz targets (scripts/sanitize.sh, fuzz.sh).
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(build-essential cmake ninja-build pkg-config
          tao-pegtl-dev libglm-dev libopenimageio-dev openimageio-tools
          catch2 libtbb-dev libcli11-dev povray povray-includes povray-examples
          parallel gnuplot-nox clang-14 libclang-rt-14-dev
          ${ASOS_EXTRA_PACKAGES:-})
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}" >&2
  sudo=; [ "$(id -u)" -eq 0 ] || sudo=sudo
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

[[ -n ${ASOS_SETUP_ONLY_PACKAGES:-} ]] && exit 0  # the packages only (scripts/fuzz.sh)

build=${ASOS_BUILD_DIR:-build}
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" -j "$(nproc)"
