#!/usr/bin/env bash
# Runs the benchmarks and rewrites their tables in docs/results.md: each table
# stands between `<!-- results:NAME begin -->` and `<!-- results:NAME end -->`,
# and only what lies between the markers is replaced (the prose around them is
# kept). Each table is preceded by the command that made it, the machine, the
# load average and the commit.
#
#   scripts/results.sh [--quick] [--only parse,bvh,intersect,render,lights,povray,scenes]
#                      [--file docs/results.md] [--output FILE]
#
#   --quick   small sizes and one pass, to check the script and the benchmarks
#             in a few minutes; its figures are not the ones to publish, so it
#             writes build/results-quick.md unless --output says otherwise
#   --only    the tables to regenerate (default: all)
#   --output  where the rewritten document goes (default: --file itself)
#
# The benchmark program is ${ASOS_BENCH:-build/asos-bench} (its value is split
# into words, so a wrapper with arguments can stand in for it); the
# POV-Ray comparison renders with the asos program of the same build
# (scripts/compare-povray.sh) and needs povray and idiff. Only a Release build
# is accepted: figures from another build type measure the wrong thing.
# Progress goes to stderr. A full run takes about an hour on two cores, most of
# it the light references (kept in build/results-cache between runs) and
# POV-Ray's converged renders.
set -euo pipefail
cd "$(dirname "$0")/.."

all_tables=(parse bvh intersect render lights povray scenes)
quick=0
only=""
file=docs/results.md
output=""
usage() { echo "usage: scripts/results.sh [--quick] [--only ${all_tables[*]// /,}] [--file F] [--output F]" >&2; exit 1; }
while [[ $# -gt 0 ]]; do
  case $1 in
    --quick) quick=1; shift ;;
    --only) [[ $# -ge 2 ]] || usage; only=$2; shift 2 ;;
    --file) [[ $# -ge 2 ]] || usage; file=$2; shift 2 ;;
    --output) [[ $# -ge 2 ]] || usage; output=$2; shift 2 ;;
    *) usage ;;
  esac
done
progress() { echo "results: $*" >&2; }
fail() { echo "results: error: $*" >&2; exit 1; }

tables=()
if [[ -z $only ]]; then
  tables=("${all_tables[@]}")
else
  IFS=, read -ra tables <<<"$only"
  for t in "${tables[@]}"; do
    [[ " ${all_tables[*]} " == *" $t "* ]] || fail "unknown table '$t' (known: ${all_tables[*]})"
  done
fi
[[ -f $file ]] || fail "$file does not exist"
if [[ -z $output ]]; then
  if [[ $quick == 1 ]]; then output=build/results-quick.md; else output=$file; fi
fi

# The benchmark program, and the Release build it belongs to.
read -ra bench <<<"${ASOS_BENCH:-build/asos-bench}"
[[ ${#bench[@]} -gt 0 && -x ${bench[0]} ]] || fail "no benchmark program '${bench[0]:-}' (build first, or set ASOS_BENCH)"
build_dir=$(cd "$(dirname "${bench[0]}")" && pwd)
while [[ ! -f $build_dir/CMakeCache.txt && $build_dir != / ]]; do build_dir=$(dirname "$build_dir"); done
[[ -f $build_dir/CMakeCache.txt ]] || fail "cannot find the CMake build of ${bench[0]}"
build_type=$(sed -n 's/^CMAKE_BUILD_TYPE:[A-Z]*=//p' "$build_dir/CMakeCache.txt")
[[ $build_type == Release ]] || fail "$build_dir is a '${build_type:-no type}' build; figures need -DCMAKE_BUILD_TYPE=Release"
bench_name="${bench[*]}"

work=build/results
cache=build/results-cache
mkdir -p "$work" "$cache" "$(dirname "$output")"
cp "$file" "$work/document.md"

commit=$(git rev-parse --short HEAD 2>/dev/null || echo unknown)
git diff --quiet HEAD 2>/dev/null || commit="$commit with local changes"
cpu=$(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo | head -1)
mode=$([[ $quick == 1 ]] && echo "quick run (small sizes: not figures to publish)" || echo "full run")

# The line above a table: what made it, where and when.
provenance() {  # command...
  local load
  load=$(cut -d' ' -f1-3 /proc/loadavg)
  # shellcheck disable=SC2016 # the backquotes are Markdown's
  printf '`%s` — %s, %s, %s cores, load average %s at the start; %s, commit %s.\n' \
    "$*" "$(date -u +%Y-%m-%d)" "${cpu:-unknown CPU}" "$(nproc)" "$load" "$mode" "$commit"
}

# A table whose columns are separated by two or more spaces, from the line that
# starts with $1 (the header) to the next blank line; rows matching $2 are left out.
spaced_table() {  # header-word skip-regex
  awk -v head="$1" -v skip="$2" '
    function row(line,   n, i, f, out) {
      sub(/^ +/, "", line); sub(/ +$/, "", line)
      n = split(line, f, /  +/); out = "|"
      for (i = 1; i <= n; i++) out = out " " f[i] " |"
      return out
    }
    !on && index($0, head) == 1 { on = 1; print row($0); n = split($0, h, /  +/); s = "|"
                                  for (i = 1; i <= n; i++) s = s " --- |"; print s; next }
    on && /^[[:space:]]*$/ { on = 0; exit }
    on && (skip == "" || $0 !~ skip) { print row($0) }'
}

# Every table of the output whose header starts with $1, columns separated by white space.
plain_tables() {  # header-word
  awk -v head="$1" '
    function row(   i, out) { out = "|"; for (i = 1; i <= NF; i++) out = out " " $i " |"; return out }
    index($0, head) == 1 { if (printed) print ""; on = 1; printed = 1; print row(); s = "|"
                           for (i = 1; i <= NF; i++) s = s " --- |"; print s; next }
    on && /^[[:space:]]*$/ { on = 0; next }
    on && !/^\(/ { print row() }'
}

# Replaces what lies between the markers of table $1 with the file $2.
replace_block() {  # name content-file
  local begin="<!-- results:$1 begin -->" end="<!-- results:$1 end -->"
  if ! grep -qxF "$begin" "$work/document.md" || ! grep -qxF "$end" "$work/document.md"; then
    fail "$file has no markers '$begin' ... '$end'"
  fi
  awk -v begin="$begin" -v end="$end" -v content="$2" '
    $0 == begin { print; print ""; while ((getline line < content) > 0) print line; print ""; inside = 1; next }
    $0 == end { inside = 0 }
    !inside { print }' "$work/document.md" >"$work/document.next"
  mv "$work/document.next" "$work/document.md"
}

run_bench() {  # log-file args...
  local log=$1; shift
  progress "  ${bench_name} $*"
  "${bench[@]}" "$@" >"$log" 2>"$log.stderr" || { cat "$log.stderr" >&2; fail "${bench_name} $* failed (output in $log)"; }
}

table_parse() {
  local args=(parse --max-exponent 6) content=$work/parse.md
  [[ $quick == 1 ]] && args=(parse --max-exponent 4)
  if command -v povray >/dev/null; then args+=(--povray); else progress "  povray not found: asos's columns only"; fi
  run_bench "$work/parse.log" "${args[@]}"
  { provenance "${bench_name} ${args[*]}"; echo
    awk '
      /^case / { pov = index($0, "|") > 0
                 printf "| case | spheres | file MiB | wall s | CPU s | peak MiB |%s\n", pov ? " POV-Ray wall s | POV-Ray CPU s | POV-Ray peak MiB |" : ""
                 printf "| --- | ---: | ---: | ---: | ---: | ---: |%s\n", pov ? " ---: | ---: | ---: |" : ""; next }
      /^(explicit|loop|macro) / { out = "|"; for (i = 1; i <= NF; i++) if ($i != "|") out = out " " $i " |"; print out }' \
      "$work/parse.log"
  } >"$content"
  replace_block parse "$content"
}

table_bvh() {
  local args=(bvh --passes 3 --scenes both) content=$work/bvh.md
  # shellcheck disable=SC2054 # the sizes are one argument
  [[ $quick == 1 ]] && args=(bvh --sizes 1000,10000 --width 256 --random-rays 65536 --cones 4096 --passes 1 --scenes both)
  run_bench "$work/bvh.log" "${args[@]}"
  { provenance "${bench_name} ${args[*]}"; echo; plain_tables "scene " <"$work/bvh.log"; } >"$content"
  replace_block bvh "$content"
}

table_intersect() {
  local args=(intersect) content=$work/intersect.md
  [[ $quick == 1 ]] && args=(intersect --queries 1024 --probes 256)
  run_bench "$work/intersect.log" "${args[@]}"
  { provenance "${bench_name} ${args[*]}"; echo; plain_tables "primitive " <"$work/intersect.log"; } >"$content"
  replace_block intersect "$content"
}

table_render() {
  local size=() repeat=(--repeat 3) name scene args content
  [[ $quick == 1 ]] && size=(-W 160 -H 120) repeat=(--repeat 1)
  for scene in examples/default.pov examples/bench/spheres.pov; do
    name=render
    [[ $scene == */spheres.pov ]] && name=render-spheres
    content=$work/$name.md
    args=(render "$scene" "${size[@]}" "${repeat[@]}")
    run_bench "$work/$name.log" "${args[@]}"
    { provenance "${bench_name} ${args[*]}"; echo; spaced_table "method " "" <"$work/$name.log"; } >"$content"
    replace_block "$name" "$content"
  done
}

table_lights() {
  local runs content=$work/lights.md i=0 args
  if [[ $quick == 1 ]]; then
    runs=("lights -W 80 -H 60 --reference 8 --lights rectangular,spherical,linear --eps 1/64 --grids 4,16 --passes 1")
  else
    runs=("lights --lights rectangular,spherical --eps 1/64 --grids 4,8,16 --passes 3 --cache $cache/lights"
          "lights --lights linear --eps 1/64,1/256 --grids 4,16 --passes 3 --cache $cache/lights")
    progress "  (the references take minutes on the first run; $cache/lights keeps them)"
  fi
  : >"$content.tables"
  for run in "${runs[@]}"; do
    read -ra args <<<"$run"
    run_bench "$work/lights-$i.log" "${args[@]}"
    provenance "${bench_name} ${args[*]}" >>"$content.head"
    # Rows after the first run's header only; the reference rows are the reference itself.
    if [[ $i == 0 ]]; then
      spaced_table "light " "^[a-z]+ +reference " <"$work/lights-$i.log" >>"$content.tables"
    else
      spaced_table "light " "^[a-z]+ +reference " <"$work/lights-$i.log" | tail -n +3 >>"$content.tables"
    fi
    i=$((i + 1))
  done
  { awk 'NR > 1 { print "" } { print }' "$content.head"; echo; cat "$content.tables"; } >"$content"
  rm -f "$content.head" "$content.tables"
  replace_block lights "$content"
}

table_povray() {
  if ! command -v povray >/dev/null || ! command -v idiff >/dev/null; then
    fail "the POV-Ray comparison needs povray and idiff"
  fi
  local size=(-W 320 -H 240) content=$work/povray.md scene label plain=$work/default-plain.pov
  [[ $quick == 1 ]] && size=(-W 80 -H 60)
  # The default scene once more with a plain floor: the error of outlines alone.
  sed 's/pigment { checker color rgb 0.85, color rgb 0.3 }/pigment { color rgb 0.75 }/' examples/default.pov >"$plain"
  cmp -s examples/default.pov "$plain" && fail "examples/default.pov has no checkered floor to replace"
  local scenes=("examples/default.pov" "$plain" "tests/golden/povray/primitives.pov" "examples/bench/spheres.pov")
  local labels=("\`examples/default.pov\`" "the same with a plain floor (\`pigment { color rgb 0.75 }\`)"
                "\`tests/golden/povray/primitives.pov\`" "1600 spheres (\`examples/bench/spheres.pov\`)")
  {
    provenance "scripts/compare-povray.sh ${size[*]} SCENE"; echo
    echo "| scene | comparison | mean | max | > 0.004 |"
    echo "| --- | --- | ---: | ---: | ---: |"
  } >"$content"
  for i in "${!scenes[@]}"; do
    scene=${scenes[$i]} label=${labels[$i]}
    if [[ ! -f $scene ]]; then progress "  $scene does not exist: left out"; continue; fi
    progress "  scripts/compare-povray.sh ${size[*]} $scene"
    ASOS_BUILD_DIR=$build_dir ASOS_COMPARE_DIR=$work/compare-povray scripts/compare-povray.sh "${size[@]}" "$scene" \
      >"$work/povray-$i.log" 2>&1 || { cat "$work/povray-$i.log" >&2; fail "compare-povray.sh $scene failed"; }
    awk -v label="$label" '
      /^  / { line = $0; sub(/^  +/, "", line)
              split(line, part, / +mean /); rest = part[2]
              split(rest, f, / +/)  # value, "max", value, "over-0.004", "(p%)"
              over = f[5]; gsub(/[()]/, "", over)
              what = part[1]
              sub(/^asos-patterns /, "asos, pattern edges, MAX 3 ", what); sub(/^jitter4 /, "jitter 4 × 4 ", what)
              sub(/^asos-paper /, "asos without the pattern filter ", what)
              sub(/ converged povray$/, " converged", what)
              printf "| %s | %s | %s | %s | %s |\n", first ? "" : label, what, f[1], f[3], over; first = 1 }' \
      "$work/povray-$i.log" >>"$content"
  done
  replace_block povray "$content"
}

table_scenes() {
  local size=(-W 320 -H 240) quick_flag=() content=$work/scenes.md
  [[ $quick == 1 ]] && size=(-W 80 -H 60) quick_flag=(--quick)
  progress "  scripts/bench-scenes.sh ${size[*]} ${quick_flag[*]}"
  ASOS_BUILD_DIR=$build_dir ASOS_BENCH_DIR=$cache/bench-scenes scripts/bench-scenes.sh "${size[@]}" "${quick_flag[@]}" \
    >"$work/scenes.log" 2>&1 || { cat "$work/scenes.log" >&2; fail "bench-scenes.sh failed"; }
  {
    provenance "scripts/bench-scenes.sh ${size[*]} ${quick_flag[*]}"; echo
    sed -n '/^| scene /,$p' "$cache/bench-scenes/summary.md"
  } >"$content"
  replace_block scenes "$content"
}

progress "benchmark program: ${bench_name} (Release build in $build_dir); $mode"
for t in "${tables[@]}"; do
  start=$SECONDS
  progress "[$t]"
  "table_$t"
  progress "[$t] done in $((SECONDS - start)) s"
done
cp "$work/document.md" "$output"
progress "wrote $output"
