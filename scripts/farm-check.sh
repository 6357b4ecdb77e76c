#!/usr/bin/env bash
# Runs the commands of docs/manual/farm.md on this machine at a small size
# and checks what the manual promises: frames rendered by GNU parallel, one
# job a frame, equal those of one run byte for byte; four tiles rendered by
# GNU parallel (--region) and joined by oiiotool equal one render of the
# whole image pixel for pixel (idiff). Exits non-zero on the first
# difference. The ctest `farm` runs it where parallel, oiiotool and idiff are
# installed.
#   scripts/farm-check.sh [ASOS] [DIR]     (default build/asos, build/farm-check)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
asos=$(realpath "${1:-$root/build/asos}")
dir=${2:-$root/build/farm-check}
rm -rf "$dir" && mkdir -p "$dir" && cd "$dir"
cp "$root/examples/figure9.pov" .
export PATH="$(dirname "$asos"):$PATH"

# Frames 1-6 of the 48, one job each, two at a time; then the same frames by one run.
parallel -j2 --halt now,fail=1 asos render figure9.pov --frames 1-48 --clock-to 0.979167 --subset {} \
  -W 72 -H 49 --quiet -o 'figure9_####.png' ::: $(seq 1 6)
asos render figure9.pov --frames 1-48 --clock-to 0.979167 --subset 1-6 -W 72 -H 49 --quiet -o 'serial_####.png'
for n in 0001 0002 0003 0004 0005 0006; do
  cmp "figure9_$n.png" "serial_$n.png"
done
echo "frames: the 6 frames of parallel equal those of one run, byte for byte"

# A 160 x 120 still in four 80 x 60 tiles, joined by oiiotool's mosaic (row by row).
W=160 H=120 TW=80 TH=60
for y in $(seq 0 $TH $((H - 1))); do
  for x in $(seq 0 $TW $((W - 1))); do echo "$x $y $((x + TW)) $((y + TH))"; done
done > tiles.txt
parallel -j2 --colsep ' ' --halt now,fail=1 asos render figure9.pov --clock 0.125 -W $W -H $H \
  --region {1},{2},{3},{4} --quiet -o tile_{#}.png :::: tiles.txt
oiiotool tile_1.png tile_2.png tile_3.png tile_4.png --mosaic $((W / TW))x$((H / TH)) -o joined.png
asos render figure9.pov --clock 0.125 -W $W -H $H --quiet -o whole.png
idiff -fail 0 -warn 0 whole.png joined.png
echo "tiles: the four tiles joined equal the whole render, pixel for pixel"
