#!/usr/bin/env bash
# Builds the libFuzzer targets (clang-14, AddressSanitizer and
# UndefinedBehaviorSanitizer) in ./build-fuzz and runs each for SECONDS
# (default 60) from a seed corpus of the examples and the test scenes.
#   scripts/fuzz.sh [SECONDS]      run both targets, side by side
#   ASOS_FUZZ_TARGETS=fuzz_cone    only these
#   ASOS_FUZZ_CONFIGURED=1         use ASOS_FUZZ_BUILD_DIR as it is configured
#                                  (scripts/sanitize.sh's build)
# A finding is written to build-fuzz/findings/ (libFuzzer's crash-* file)
# and the script exits non-zero; docs/robustness.md says how to replay one.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
build=${ASOS_FUZZ_BUILD_DIR:-build-fuzz}
if [[ -z ${ASOS_FUZZ_CONFIGURED:-} ]]; then
  ASOS_SETUP_ONLY_PACKAGES=1 scripts/setup.sh
  cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++-14 \
        -DASOS_FUZZ=ON -DASOS_BUILD_TESTS=OFF >/dev/null
fi
targets=(${ASOS_FUZZ_TARGETS:-fuzz_scene fuzz_cone})
cmake --build "$build" -j "$(nproc)" --target "${targets[@]}"

seeds=$build/seeds
mkdir -p "$seeds" "$build/findings"
# Named by their paths: the golden folders share file names.
for f in examples/*.pov examples/bench/*.pov tests/golden/*/*.pov; do cp "$f" "$seeds/${f//\//_}"; done
# Each target on a core of its own; the corpus starts from the findings
# (fuzz/findings/) and, for the scenes, the seeds.
pids=()
for target in "${targets[@]}"; do
  corpus=$build/corpus/$target
  mkdir -p "$corpus"
  cp fuzz/findings/"$target"-* "$corpus/" 2>/dev/null || true
  inputs=("$corpus")
  [[ $target == fuzz_scene ]] && inputs+=("$seeds")
  echo "fuzz: $target for $seconds s" >&2
  # -timeout: one input taking 10 s is a finding (a hang); the memory limit
  # likewise.
  "$build/fuzz/$target" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=16384 \
      -artifact_prefix="$build/findings/$target-" -print_final_stats=1 "${inputs[@]}" \
      2>"$build/$target.log" &
  pids+=($!)
done
status=0
for i in "${!targets[@]}"; do
  target=${targets[$i]}
  if ! wait "${pids[$i]}"; then
    status=1
    tail -40 "$build/$target.log" >&2
  fi
  echo "fuzz: $target: $(grep -E '^#[0-9]+.*(DONE|cov:)' "$build/$target.log" | tail -1)" >&2
done
exit $status
