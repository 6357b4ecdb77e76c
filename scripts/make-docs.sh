#!/usr/bin/env bash
# Makes every picture of the manual (docs/manual/pictures/*.png), never by
# hand, from two sources:
#   * the manual's own ```pov snippets: a snippet whose closing fence is
#     followed (blank lines aside) by a line `![…](pictures/NAME.png)` is
#     rendered as NAME.png, on the stage of examples/manual/stage.inc (a
#     camera, a light, a floor; a snippet's own camera wins, as the last
#     camera of a scene does);
#   * the renders listed below, of scenes in examples/: the first render and
#     its heat map, the heat maps at several EPS and MAX, and asos beside
#     POV-Ray 3.7 (`povray`).
# Pictures are PNG, at most 320 pixels wide. `tests/unit/docs_test.cpp`
# checks that every picture the manual links exists.
#   scripts/make-docs.sh            (uses build/asos; ASOS_BUILD_DIR to change)
set -euo pipefail
cd "$(dirname "$0")/.."
asos=$PWD/${ASOS_BUILD_DIR:-build}/asos
pictures=docs/manual/pictures
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$pictures"
[[ -x $asos ]] || { echo "make-docs: no $asos; build first" >&2; exit 1; }

render() {  # render SCENE NAME [asos options...]: pictures/NAME.png
  local scene=$1 name=$2
  shift 2
  "$asos" render "$scene" -o "$pictures/$name.png" --quiet "$@"
}

# The snippets: each becomes work/NAME.pov, the stage and then the snippet.
for page in docs/manual/*.md; do
  awk -v work="$work" -v stage="$PWD/examples/manual/stage.inc" '
    /^```pov/ && !open { open = 1; text = ""; next }
    open && /^```/ { open = 0; pending = 1; next }
    open { text = text $0 "\n"; next }
    pending && /^[[:space:]]*$/ { next }
    pending && match($0, /^!\[[^]]*\]\(pictures\/[A-Za-z0-9_-]+\.png\)/) {
      name = substr($0, RSTART, RLENGTH)
      sub(/^.*\(pictures\//, "", name); sub(/\.png\)$/, "", name)
      file = work "/" name ".pov"
      printf "#version 3.7;\n#include \"%s\"\n%s", stage, text > file
      close(file)
      print name
    }
    { pending = 0 }
  ' "$page"
done > "$work/snippets"
while read -r name; do
  render "$work/$name.pov" "$name" -W 160 -H 120
done < "$work/snippets"
echo "make-docs: $(wc -l < "$work/snippets") snippet pictures"

# Getting started: the first render and its heat map.
render examples/first.pov first -W 320 -H 240 --aov samples="$pictures/first-samples.png"

# Getting started: the house after the paper's Figure 7.
render examples/figure7.pov figure7 -W 320 -H 240

# The asos chapter: one scene at three settings of EPS and MAX, with heat maps.
for setting in "16 2" "64 4" "256 6"; do
  read -r eps max <<< "$setting"
  render examples/figure6.pov "eps${eps}-max${max}" -W 240 -H 180 --eps "1/$eps" --max "$max" \
    --aov samples="$pictures/eps${eps}-max${max}-samples.png"
done

# The paper's Figure 8: the office four ways, in the paper's places (ASOS at
# MAX 3 upper left, random MAX-cones lower left, 3 x 3 and 4 x 4 jittered
# sampling on the right), joined by oiiotool.
for setting in "asos:--max 3" "random:--max 3 --jitter on" "3x3:--method jitter --samples 3" \
               "4x4:--method jitter --samples 4"; do
  # shellcheck disable=SC2086  # the options are words
  "$asos" render examples/figure8.pov -o "$work/f8-${setting%%:*}.png" -W 160 -H 107 --quiet ${setting#*:}
done
oiiotool --nosoftwareattrib "$work/f8-asos.png" "$work/f8-3x3.png" "$work/f8-random.png" "$work/f8-4x4.png" \
  --mosaic 2x2 --eraseattrib ".*" -o "$pictures/figure8.png"

# asos beside POV-Ray 3.7, both at 160 x 120: POV-Ray with its own default
# antialiasing (+A0.3, method 1), asos with its default, ASOS.
if command -v povray > /dev/null; then
  for scene in default figure6 patterns lights; do
    render "examples/$scene.pov" "povray-$scene-asos" -W 160 -H 120
    povray -D -GA +I"examples/$scene.pov" +O"$work/povray.png" +W160 +H120 +FN8 \
      +A0.3 +WT1 > "$work/povray.log" 2>&1 || { cat "$work/povray.log" >&2; exit 1; }
    # One thread (POV-Ray jitters area lights from a generator per thread) and
    # no render date in the file, so that a second run writes the same bytes.
    oiiotool --nosoftwareattrib "$work/povray.png" --eraseattrib ".*" -o "$pictures/povray-$scene-povray.png"
  done
else
  echo "make-docs: povray is not installed; the POV-Ray pictures are left as they are" >&2
fi
echo "make-docs: pictures in $pictures"
