#!/usr/bin/env bash
# Deterministic in-world figures: instructions (callgrind) of Box2D's narrow phase
# (b2ContactManager::Collide) and of the whole step (b2World::Step), inclusive, for scenes run
# under Box2D's own contact (the plug-in not installed) and under each backend given. Instruction
# counts do not move with the load of a shared machine as wall time does; they ignore cache misses
# and mispredictions (callgrind's branch simulation counts the latter: --branch-sim=yes).
#   scripts/collide_instructions.sh [STEPS] [SCENE...]   (defaults: 150 steps; pyramid
#   stack-concave rain tumbler); BACKENDS (default "dyop") names the backends (runners beside box2d-own).
# Needs valgrind and a built tree (build/bin/dyop). The scene's probe (depth errors, untimed) runs
# outside Step and is not counted.
set -euo pipefail
cd "$(dirname "$0")/.."
command -v valgrind >/dev/null || { echo "collide_instructions: valgrind not found" >&2; exit 2; }
steps="${1:-150}"
shift || true
scenes=("$@")
[ ${#scenes[@]} -gt 0 ] || scenes=(pyramid stack-concave rain tumbler)
backends=(${BACKENDS:-dyop})
out=$(mktemp -d)
inclusive() {  # file function-pattern -> instructions (reads all: no SIGPIPE under pipefail)
  callgrind_annotate --inclusive=yes "$1" 2>/dev/null |
    awk -v pattern="$2" '!found && $0 ~ pattern { gsub(",", "", $1); print $1; found = 1 }'
}
printf '%-14s %-10s %14s %8s %14s %8s\n' scene backend collide_Ir x_own step_Ir x_own
for scene in "${scenes[@]}"; do
  declare -A collide=() step=()
  for b in box2d-own "${backends[@]}"; do
    f="$out/$scene.$b.out"
    valgrind --tool=callgrind --callgrind-out-file="$f" \
      build/bin/dyop scene "$scene" --runner "$b" --steps "$steps" >/dev/null 2>&1
    collide[$b]=$(inclusive "$f" 'b2ContactManager::Collide\(\)')
    step[$b]=$(inclusive "$f" 'b2World::Step\(')
    printf '%-14s %-10s %14s %8s %14s %8s\n' "$scene" "$b" "${collide[$b]}" \
      "$(awk -v a="${collide[$b]}" -v o="${collide[box2d-own]}" 'BEGIN{printf "%.3f", a/o}')" \
      "${step[$b]}" "$(awk -v a="${step[$b]}" -v o="${step[box2d-own]}" 'BEGIN{printf "%.3f", a/o}')"
  done
  unset collide step
done
rm -rf "$out"
