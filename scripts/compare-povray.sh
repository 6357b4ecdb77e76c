#!/usr/bin/env bash
# Renders scenes with POV-Ray 3.7 and with asos side by side and prints how
# far apart the images are (idiff: mean and max error, pixels over
# OpenImageIO's failure threshold 0.004), so that differences between the
# two renderers can be told from differences between methods:
#   single    asos --method single    vs  povray -A            (same rays: should match)
#   adaptive  asos --method adaptive  vs  povray +A0.3 +AM2 +R3 -J   (same method)
#   am1       asos --method am1       vs  povray +A0.3 +AM1 +R3 -J   (same method)
#   and asos (also without its pattern filter, the paper's method, and with
#   --pattern-edges on --max 3), adaptive, am1, 4x4 jitter
#   and single against a converged POV-Ray reference (+A0.0 +AM2 +R5: 17 x 17
#   samples in every pixel).
#   scripts/compare-povray.sh [-W 320 -H 240] SCENE.pov...
# Images and logs go to ${ASOS_COMPARE_DIR:-build/compare-povray}.
set -euo pipefail
cd "$(dirname "$0")/.."
width=320 height=240
while [[ $# -gt 0 && $1 == -* ]]; do
  case $1 in
    -W) width=$2; shift 2 ;;
    -H) height=$2; shift 2 ;;
    *) echo "compare-povray: unknown option $1" >&2; exit 1 ;;
  esac
done
if [[ $# -eq 0 ]]; then echo "usage: scripts/compare-povray.sh [-W w -H h] SCENE.pov..." >&2; exit 1; fi
asos=${ASOS_BUILD_DIR:-build}/asos
out=${ASOS_COMPARE_DIR:-build/compare-povray}
mkdir -p "$out"

# "mean max over-threshold%" of idiff between two images.
difference() {
  idiff -v -fail 0.004 -warn 0.004 "$1" "$2" 2>/dev/null | awk '
    /Mean error/ { mean = $4 }
    /Max error/ { max = $4 }
    /pixels .* over 0.004/ { over = $3 }
    END { printf "mean %-12s max %-10s over-0.004 %s\n", mean, max, over }'
}

for scene in "$@"; do
  name=$(basename "$scene" .pov)
  p="$out/$name"
  povray() { command povray -D -GA +I"$scene" +W"$width" +H"$height" +FN8 "$@" >"$p.povray.log" 2>&1; }
  povray +O"$p.pov-single.png" -A
  povray +O"$p.pov-am2.png" +A0.3 +AM2 +R3 -J
  povray +O"$p.pov-am1.png" +A0.3 +AM1 +R3 -J
  povray +O"$p.pov-reference.png" +A0.0 +AM2 +R5 -J
  render() { "$asos" render "$scene" -W "$width" -H "$height" --quiet "$@"; }
  render -o "$p.single.png" --method single
  render -o "$p.adaptive.png" --method adaptive
  render -o "$p.am1.png" --method am1
  render -o "$p.asos.png" --method asos
  render -o "$p.asos-paper.png" --method asos --pattern-filter off
  render -o "$p.asos-patterns.png" --method asos --pattern-edges on --max 3
  render -o "$p.jitter4.png" --method jitter --samples 4
  echo "== $scene ($width x $height)"
  printf '  %-34s %s\n' "single vs povray -A" "$(difference "$p.pov-single.png" "$p.single.png")"
  printf '  %-34s %s\n' "adaptive vs povray +AM2" "$(difference "$p.pov-am2.png" "$p.adaptive.png")"
  printf '  %-34s %s\n' "am1 vs povray +AM1" "$(difference "$p.pov-am1.png" "$p.am1.png")"
  for m in asos asos-paper asos-patterns adaptive am1 jitter4 single; do
    printf '  %-34s %s\n' "$m vs converged povray" "$(difference "$p.pov-reference.png" "$p.$m.png")"
  done
  printf '  %-34s %s\n' "povray +AM2 vs converged povray" "$(difference "$p.pov-reference.png" "$p.pov-am2.png")"
  printf '  %-34s %s\n' "povray +AM1 vs converged povray" "$(difference "$p.pov-reference.png" "$p.pov-am1.png")"
done
