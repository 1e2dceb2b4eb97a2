#!/usr/bin/env bash
# Instructions per answer afresh, act by act: a scene's triangle-pair answers recorded under the
# plug-in and replayed (build/bin/dyop_answers_bench) through `collide_polygons` and through
# `b2CollidePolygons`, each under callgrind with collection on inside that call only. Prints one
# row per act: its instructions per call (inclusive of what it calls, less the acts listed below
# it), and the totals of both.
#   scripts/answer_instructions.sh [SCENE] [STEPS]   (default: tile-map-unfixed, its own steps)
# Needs valgrind and a built tree (cmake --build build --target dyop_answers_bench).
set -euo pipefail
cd "$(dirname "$0")/.."
command -v valgrind >/dev/null || { echo "answer_instructions: valgrind not found" >&2; exit 2; }
bench=build/bin/dyop_answers_bench
[ -x "$bench" ] || { echo "answer_instructions: build $bench first" >&2; exit 2; }
export DYOP_ANSWERS_SCENE="${1:-tile-map-unfixed}"
[ -n "${2:-}" ] && export DYOP_ANSWERS_STEPS="$2"
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

run() {  # run NAME FILTER TOGGLE
  valgrind --tool=callgrind --toggle-collect="$3" --callgrind-out-file="$out/$1" \
    "$bench" --benchmark_filter="$2" --benchmark_min_time=0.2 >/dev/null 2>"$out/$1.log"
}
run plugin 'plugin$' 'dyop::box2d::collide_polygons*'
run box2d 'box2d$' 'b2CollidePolygons*'

inclusive() {  # FILE PATTERN -> instructions of the functions matching PATTERN, inclusive
  callgrind_annotate --inclusive=yes "$1" 2>/dev/null |
    awk -v pat="$2" '$0 ~ pat { gsub(",", "", $1); s += $1 } END { print s + 0 }'
}
calls() {  # FILE PATTERN -> calls into the function matching PATTERN
  callgrind_annotate --inclusive=yes --tree=calling "$1" 2>/dev/null | grep -E ">   .*$2" |
    grep -oE '\([0-9,]+x\)' | tr -d '(),x' | awk '{ s += $1 } END { print s + 0 }'
}

n=$(calls "$out/plugin" 'dyop::box2d::collide_polygons\(')
nb=$(calls "$out/box2d" 'b2CollidePolygons\(')
total=$(inclusive "$out/plugin" ':dyop::box2d::collide_polygons\(')
answer=$(inclusive "$out/plugin" 'answer<dyop::box2d::detail::TrianglePair>')
solve=$(inclusive "$out/plugin" 'TrianglePair::solve\(')
method=$(inclusive "$out/plugin" ':dyop::Result<float> dyop::dyop<float>\(')
certify=$(inclusive "$out/plugin" 'certify_allowed_axes<')
allowed=$(inclusive "$out/plugin" ':dyop::detail::AllowedAxes<float> dyop::detail::allowed_axes<')
axis=$(inclusive "$out/plugin" 'bool dyop::detail::axis_allowed<float>')
clip=$(inclusive "$out/plugin" 'clip_manifold<float>')
write=$(inclusive "$out/plugin" 'TrianglePair::write\(')
box2d=$(inclusive "$out/box2d" ':b2CollidePolygons\(')

per() { awk -v x="$1" -v n="$2" 'BEGIN { printf "%.0f", x / n }'; }
echo "scene $DYOP_ANSWERS_SCENE: $(grep -o '[0-9]* answers' "$out/plugin.log" | head -1) recorded;" \
     "$n plug-in calls, $nb b2CollidePolygons calls replayed under callgrind"
printf '| act | instructions per call |\n|---|--:|\n'
printf '| entry: pose, skip tests, memory | %s |\n' "$(per $((total - answer)) "$n")"
printf '| answer: masks taken, counters, result | %s |\n' "$(per $((answer - solve - write)) "$n")"
printf '| the two triangles placed in A'"'"'s frame, the method'"'"'s entry | %s |\n' "$(per $((solve - method)) "$n")"
printf '| DyOP-PD: six overlaps, status, reference face | %s |\n' \
       "$(per $((method - certify - axis - clip)) "$n")"
printf '| rule: allowed axes (`allowed_axes`, `axis_allowed`) | %s |\n' \
       "$(per $((allowed + axis)) "$n")"
printf '| rule: certification over the allowed axes | %s |\n' \
       "$(per $((certify - allowed)) "$n")"
printf '| manifold: clipping | %s |\n' "$(per "$clip" "$n")"
printf '| manifold written as Box2D'"'"'s | %s |\n' "$(per "$write" "$n")"
printf '| **plug-in, all** | **%s** |\n' "$(per "$total" "$n")"
printf '| **`b2CollidePolygons`, same pairs** | **%s** |\n' "$(per "$box2d" "$nb")"
