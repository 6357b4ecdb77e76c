#!/usr/bin/env bash
# The corpus side by side: every POV-Ray example scene that asos renders
# (tests/golden/corpus/first_blockers.tsv says "renders") is rendered at
# 160 x 120 by asos with one ray per pixel (--method single) and by POV-Ray
# 3.7 with one ray per pixel (-A), each in the scene's own folder, and the
# two images are compared with OpenImageIO's test-suite thresholds (idiff
# -fail 0.004 -failpercent 0.02 -hardfail 0.012, as the golden tests do).
# Writes the table (scene, verdict, mean and max error, share of pixels over
# 0.004, and the explanation kept in tests/golden/corpus/differences.tsv for
# a scene that does not match) between the markers of docs/results.md's
# section "The POV-Ray corpus side by side", and prints the counts.
#   scripts/corpus-compare.sh [SCENE…]     (scenes relative to the corpus folder;
#                                          default: all that render; a list
#                                          prints the rows and leaves the docs)
# Images and logs go to ${ASOS_COMPARE_DIR:-build/corpus-compare}.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
asos=$root/${ASOS_BUILD_DIR:-build}/asos
corpus=/usr/share/povray-3.7/scenes
out=$root/${ASOS_COMPARE_DIR:-build/corpus-compare}
notes=tests/golden/corpus/differences.tsv
results=docs/results.md
[[ -x $asos ]] || { echo "corpus-compare: no $asos; build first" >&2; exit 1; }
command -v povray > /dev/null || { echo "corpus-compare: povray is not installed" >&2; exit 1; }
[[ -d $corpus ]] || { echo "corpus-compare: no corpus in $corpus (povray-examples)" >&2; exit 1; }
mkdir -p "$out"

if [[ $# -gt 0 ]]; then
  scenes=("$@")
  write_docs=0
else
  mapfile -t scenes < <(awk -F'\t' '$2 == "renders" { print $1 }' tests/golden/corpus/first_blockers.tsv)
  write_docs=1
fi

note_of() {  # the explanation kept for a scene, if any
  awk -F'\t' -v s="$1" '$1 == s { print $2 }' "$notes" 2> /dev/null || true
}

rows=$out/rows.md
: > "$rows"
match=0 total=0
for scene in "${scenes[@]}"; do
  name=${scene//\//_}
  name=${name%.pov}
  dir=$corpus/$(dirname "$scene")
  file=$(basename "$scene")
  a=$out/$name.asos.png p=$out/$name.povray.png
  rm -f "$a" "$p"
  total=$((total + 1))
  (cd "$dir" && timeout 300 "$asos" render "$file" -o "$a" -W 160 -H 120 --method single --quiet) \
    > "$out/$name.asos.log" 2>&1 || true
  (cd "$dir" && timeout 300 povray -D -GA +I"$file" +O"$p" +W160 +H120 -A +FN8 +L/usr/share/povray-3.7/include) \
    > "$out/$name.povray.log" 2>&1 || true
  if [[ ! -s $a || ! -s $p ]]; then
    verdict="no image ($([[ -s $a ]] && echo povray || echo asos) failed)"
    mean="" max="" over=""
  else
    report=$(idiff -v -fail 0.004 -failpercent 0.02 -hardfail 0.012 -warn 0.008 "$a" "$p" 2>&1 || true)
    mean=$(awk '/Mean error/ { print $4 }' <<< "$report")
    max=$(awk '/Max error/ { print $4 }' <<< "$report")
    over=$(awk '/pixels .* over 0.004/ { print $3 }' <<< "$report" | tr -d '()')
    [[ -z $over ]] && over=0%
    if grep -q "^PASS\|^WARNING" <<< "$(tail -1 <<< "$report")"; then
      verdict=matches
      match=$((match + 1))
    else
      verdict=differs
    fi
  fi
  note=$(note_of "$scene")
  if [[ $verdict != matches && -z $note ]]; then note="(not yet explained)"; fi
  [[ $verdict == matches ]] && note=""
  printf '| `%s` | %s | %s | %s | %s | %s |\n' "$scene" "$verdict" "$mean" "$max" "$over" "$note" >> "$rows"
  printf '%-45s %-10s mean %-10s max %-10s over %s\n' "$scene" "$verdict" "$mean" "$max" "$over"
done
summary="$match of $total corpus scenes that asos renders match POV-Ray 3.7 (one ray per pixel, 160 × 120)"
echo "corpus-compare: $summary"

if [[ $write_docs == 1 ]]; then
  table=$out/table.md
  {
    echo "<!-- corpus: begin (scripts/corpus-compare.sh writes this part) -->"
    echo "$summary."
    echo
    echo "| scene | verdict | mean error | max error | pixels over 0.004 | why it differs |"
    echo "| --- | --- | --- | --- | --- | --- |"
    cat "$rows"
    echo "<!-- corpus: end -->"
  } > "$table"
  if grep -q '^<!-- corpus: begin' "$results"; then
    awk -v table="$table" '
      /^<!-- corpus: begin/ { while ((getline line < table) > 0) print line; skip = 1; next }
      /^<!-- corpus: end/ { skip = 0; next }
      !skip { print }
    ' "$results" > "$out/results.md"
    cp "$out/results.md" "$results"
    echo "corpus-compare: the table is in $results"
  else
    echo "corpus-compare: $results has no corpus markers; the table is in $table" >&2
  fi
fi
