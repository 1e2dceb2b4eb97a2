#!/usr/bin/env bash
# Deterministic in-world figures: instructions (callgrind) of Box2D's narrow phase
# (b2ContactManager::Collide), of its time-of-impact pass (b2World::SolveTOI) and of the whole step
# (b2World::Step), inclusive, and the time-of-impact work counted in calls (b2TimeOfImpact calls,
# and contact updates made by SolveTOI: one per time-of-impact event, plus one per contact it
# re-checks), for scenes run under Box2D's own contact (the plug-in not installed) and under each
# backend given. Instruction counts do not move with the load of a shared machine as wall time
# does; they ignore cache misses and mispredictions (callgrind's simulations count those:
# CALLGRIND_FLAGS="--cache-sim=yes --branch-sim=yes").
#   scripts/collide_instructions.sh [STEPS] [SCENE...]   (defaults: 150 steps; pyramid
#   stack-concave rain rain-tall tumbler). STEPS "full" runs each scene for its own length (the
#   catalogue's full run, what `dyop scene` and `dyop compare` run: 250 to 900 steps, e.g. rain
#   900, rain-tall 250); 150 steps are the first 2.5 s, mostly bodies falling, where fewer
#   manifolds are kept than over a whole run. A SCENE of the form rain:N is the rain with N falling
#   triangles (the rain scaling's sizes: rain:100 ... rain:3000). BACKENDS (default "dyop") names
#   the backends run beside box2d-own; SCENE_FLAGS (e.g. "--recycle 0.005") are given to their
#   runs; WORLD_FLAGS (e.g. "--spawn-far") to every run, Box2D's own included; SEED (default 0) is every run's seed, Box2D's own included (chaotic scenes such as
#   stack-concave differ from seed to seed); DYOP (default build/bin/dyop) is the program run,
#   e.g. another tree's to compare builds.
#   Columns: instructions and their ratio to box2d-own (x_own). KEEP=DIR keeps callgrind's files
#   there (for callgrind_annotate, e.g. the cache misses of one function).
# Needs valgrind and a built tree (build/bin/dyop). The scene's probe (depth errors, untimed) runs
# outside Step and is not counted.
set -euo pipefail
cd "$(dirname "$0")/.."
command -v valgrind >/dev/null || { echo "collide_instructions: valgrind not found" >&2; exit 2; }
steps="${1:-150}"
shift || true
scenes=("$@")
[ ${#scenes[@]} -gt 0 ] || scenes=(pyramid stack-concave rain rain-tall tumbler)
backends=(${BACKENDS:-dyop})
if [ -n "${KEEP:-}" ]; then
  out=$KEEP
  mkdir -p "$out"
else
  out=$(mktemp -d)
  trap 'rm -rf "$out"' EXIT
fi
inclusive() {  # file function-pattern -> instructions (reads all: no SIGPIPE under pipefail)
  callgrind_annotate --inclusive=yes "$1" 2>/dev/null |
    awk -v pattern="$2" '!found && $0 ~ pattern { gsub(",", "", $1); print $1; found = 1 }'
}
toi_calls() {  # file -> "b2TimeOfImpact-calls SolveTOI-contact-updates", from the call records
  awk '
    function resolve(spec,   id) {  # "(id) name" defines a compressed name, "(id)" reuses it
      if (match(spec, /^\([0-9]+\)/)) {
        id = substr(spec, 2, RLENGTH - 2)
        if (length(spec) > RLENGTH) names[id] = substr(spec, RLENGTH + 2)
        return names[id]
      }
      return spec
    }
    /^fn=/ { caller = resolve(substr($0, 4)) }
    /^cfn=/ { callee = resolve(substr($0, 5)) }
    /^calls=/ {
      split(substr($0, 7), n, " ")
      if (callee ~ /^b2TimeOfImpact\(/) toi += n[1]
      if (caller ~ /^b2World::SolveTOI\(/ && callee ~ /^b2Contact::Update\(/) updates += n[1]
    }
    END { print toi + 0, updates + 0 }' "$1"
}
ratio() { awk -v a="$1" -v o="$2" 'BEGIN { printf "%.3f", (o > 0 ? a / o : 0) }'; }
printf '%-14s %-10s %14s %7s %14s %7s %14s %7s %10s %9s\n' scene runner collide_Ir x_own \
  solve_toi_Ir x_own step_Ir x_own toi_calls toi_upd
declare -A collide=() toi=() step=()
for scene in "${scenes[@]}"; do
  collide=() toi=() step=()
  for b in box2d-own "${backends[@]}"; do
    f="$out/$scene.$b.out"
    # shellcheck disable=SC2086  # CALLGRIND_FLAGS is a list of flags
    size=()
    name=$scene
    if [[ $scene == *:* ]]; then name=${scene%%:*}; size=(--falling "${scene#*:}"); fi
    flags=(${WORLD_FLAGS:-})
    if [ "$b" != box2d-own ]; then flags+=(${SCENE_FLAGS:-}); fi
    length=(--steps "$steps")
    if [ "$steps" = full ]; then length=(); fi
    valgrind --tool=callgrind ${CALLGRIND_FLAGS:-} --callgrind-out-file="$f" \
      "${DYOP:-build/bin/dyop}" scene "$name" --runner "$b" "${length[@]}" "${size[@]}" \
      --seed "${SEED:-0}" "${flags[@]}" >/dev/null 2>&1
    collide[$b]=$(inclusive "$f" 'b2ContactManager::Collide\(\)')
    toi[$b]=$(inclusive "$f" 'b2World::SolveTOI\(')
    step[$b]=$(inclusive "$f" 'b2World::Step\(')
    read -r calls updates < <(toi_calls "$f")
    printf '%-14s %-10s %14s %7s %14s %7s %14s %7s %10s %9s\n' "$scene" "$b" "${collide[$b]}" \
      "$(ratio "${collide[$b]}" "${collide[box2d-own]}")" "${toi[$b]:-0}" \
      "$(ratio "${toi[$b]:-0}" "${toi[box2d-own]:-0}")" "${step[$b]}" \
      "$(ratio "${step[$b]}" "${step[box2d-own]}")" "$calls" "$updates"
  done
done
