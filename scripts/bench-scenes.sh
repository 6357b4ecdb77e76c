#!/usr/bin/env bash
# asos against POV-Ray 3.7 on the scenes people build (examples/bench/room.pov,
# textured.pov, contact.pov by default), one thread each, at 320 x 240:
#   * a converged POV-Ray render is the reference (+A0.0 +AM2 +R4, 17 x 17 light
#     points, every one traced: LightN=17 LightAdaptive=100), cached under the
#     scene text's hash;
#   * POV-Ray's ladder: +AM1 and +AM2, +A 0.3/0.1/0.03, +R 2/3/4, light points
#     3/5/9 (adaptive 1); its fastest setting with RMSE <= 0.005 is "POV-Ray best";
#   * asos with its defaults, and with the options given after --asos.
# For each: wall time, eye and shadow rays per pixel (asos), RMSE and the share
# of pixels more than 1/64 off (OpenImageIO's idiff, on 8-bit encoded values).
#   scripts/bench-scenes.sh [-W w -H h] [--quick] [SCENE.pov...] [--asos OPTIONS...]
# --quick: POV-Ray's ladder cut to +AM2 +R3 at 0.3/0.1 and 5/9 light points.
# Images, logs and summary.md go to ${ASOS_BENCH_DIR:-build/bench-scenes}.
set -euo pipefail
cd "$(dirname "$0")/.."
width=320 height=240 quick=0 scenes=() asos_extra=()
while [[ $# -gt 0 ]]; do
  case $1 in
    -W) width=$2; shift 2 ;;
    -H) height=$2; shift 2 ;;
    --quick) quick=1; shift ;;
    --asos) shift; asos_extra=("$@"); break ;;
    -*) echo "bench-scenes: unknown option $1" >&2; exit 1 ;;
    *) scenes+=("$1"); shift ;;
  esac
done
[[ ${#scenes[@]} -gt 0 ]] || scenes=(examples/bench/room.pov examples/bench/textured.pov examples/bench/contact.pov)
for tool in povray idiff; do
  command -v "$tool" >/dev/null || { echo "bench-scenes: needs $tool (scripts/setup.sh installs it)" >&2; exit 1; }
done
asos=${ASOS_BUILD_DIR:-build}/asos
[[ -x $asos ]] || { echo "bench-scenes: no $asos: build first" >&2; exit 1; }
out=${ASOS_BENCH_DIR:-build/bench-scenes}
mkdir -p "$out/ref"
TIMEFORMAT=%R

# "rmse share-over-1/64" of two images.
errors() {
  idiff -v -fail 0.015625 -warn 0.015625 "$1" "$2" 2>/dev/null | awk '
    /RMS error/ { rmse = $4 }
    /pixels .* over/ { over = $3; gsub(/[()%]/, "", over) }
    END { printf "%.4f %s\n", rmse, over }'
}
# Seconds of wall time the command took (its output goes to $log).
timed() {
  local log=$1; shift
  { time "$@" >"$log" 2>&1; } 2>&1 | tail -1
}
povray_render() {
  local scene=$1 image=$2 log=$3; shift 3
  timed "$log" povray -D -GA +WT1 +I"$scene" +O"$image" +W"$width" +H"$height" "$@"
}

summary=$out/summary.md
{
  echo "scripts/bench-scenes.sh -W $width -H $height$([[ $quick = 1 ]] && echo ' --quick') — $(date -u +%F), $(git rev-parse --short HEAD), $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg)"
  echo
  echo "| scene | renderer, setting | time (s) | eye rays/px | shadow rays/px | RMSE | > 1/64 |"
  echo "| --- | --- | ---: | ---: | ---: | ---: | ---: |"
} >"$summary"

for scene in "${scenes[@]}"; do
  name=$(basename "$scene" .pov)
  hash=$(cat "$scene" | sha256sum | cut -c1-12)
  ref=$out/ref/$name-$hash-${width}x$height.png
  if [[ ! -f $ref ]]; then
    echo "== $name: the converged POV-Ray reference (slow; cached in $ref)" >&2
    t=$(povray_render "$scene" "$ref.tmp.png" "$out/$name.ref.log" +FN16 +A0.0 +AM2 +R4 +WT"$(nproc)" Declare=LightN=17 Declare=LightAdaptive=100)
    mv "$ref.tmp.png" "$ref"
    echo "   $t s" >&2
  fi

  # POV-Ray's ladder.
  if [[ $quick = 1 ]]; then ams=(2) thresholds=(0.3 0.1) depths=(3) lights=(5 9)
  else ams=(1 2) thresholds=(0.3 0.1 0.03) depths=(2 3 4) lights=(3 5 9); fi
  best="" best_time=""
  for am in "${ams[@]}"; do for a in "${thresholds[@]}"; do for r in "${depths[@]}"; do for n in "${lights[@]}"; do
    setting="+AM$am +A$a +R$r, ${n}x$n light"
    image=$out/$name.pov-am$am-a$a-r$r-l$n.png
    t=$(povray_render "$scene" "$image" "$out/$name.pov.log" +FN8 +AM"$am" +A"$a" +R"$r" -J Declare=LightN="$n")
    read -r rmse over <<<"$(errors "$ref" "$image")"
    echo "   povray $setting: $t s, RMSE $rmse" >&2
    if awk -v e="$rmse" 'BEGIN { exit !(e <= 0.005) }' &&
       { [[ -z $best_time ]] || awk -v t="$t" -v b="$best_time" 'BEGIN { exit !(t < b) }'; }; then
      best="$setting|$t|$rmse|$over" best_time=$t
    fi
  done; done; done; done
  if [[ -n $best ]]; then
    IFS='|' read -r setting t rmse over <<<"$best"
    echo "| $name | POV-Ray best under RMSE 0.005: \`$setting\` | $t | | | $rmse | $over % |" >>"$summary"
  else
    echo "| $name | POV-Ray: no setting of the ladder under RMSE 0.005 | | | | | |" >>"$summary"
  fi

  # asos.
  run_asos() {
    local label=$1; shift
    local image=$out/$name.asos-$label.png json=$out/$name.asos-$label.json
    t=$(timed "$out/$name.asos.log" "$asos" render "$scene" -W "$width" -H "$height" --threads 1 --quiet \
          --stats-json "$json" -o "$image" "$@")
    read -r rmse over <<<"$(errors "$ref" "$image")"
    read -r eye shadow <<<"$(awk -v px=$((width * height)) '
      /"rays"/ { match($0, /"eye": [0-9]+/); e = substr($0, RSTART + 7, RLENGTH - 7)
                 match($0, /"reflected": [0-9]+/); r = substr($0, RSTART + 13, RLENGTH - 13)
                 match($0, /"shadow": [0-9]+/); s = substr($0, RSTART + 10, RLENGTH - 10)
                 printf "%.1f %.1f\n", (e + r) / px, s / px }' "$json")"
    echo "   asos $*: $t s, RMSE $rmse" >&2
    echo "| $name | asos ${*:-default} | $t | $eye | $shadow | $rmse | $over % |" >>"$summary"
  }
  run_asos default
  [[ ${#asos_extra[@]} -eq 0 ]] || run_asos extra "${asos_extra[@]}"
done
cat "$summary"
