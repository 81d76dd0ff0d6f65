#!/usr/bin/env bash
# End-to-end benchmark of the simulator (docs/performance.md): the README's main job, the
# built-in default scene (the paper's Figure 5 experiment, 400 s), without figures, on one
# core. Prints the machine, the load before and after, the wall and CPU time and the steps.
#   scripts/bench-default.sh [EXTRA simulate ARGS, e.g. --set numerics.time_step_safety=0.5]
#   PRESSRIDGE_BIN=path/to/pressridge scripts/bench-default.sh   # another binary, not rebuilt
# Side by side in one run (a change against the present code): the baseline, then the
# candidate, one after the other on the same core, then the ratio of their times:
#   scripts/bench-default.sh --compare "BASE ARGS" "CANDIDATE ARGS"
#   BASE_BIN=old/pressridge scripts/bench-default.sh --compare "" ""   # two binaries
set -euo pipefail
cd "$(dirname "$0")/.."
bin=${PRESSRIDGE_BIN:-./target/release/pressridge}
[ -n "${PRESSRIDGE_BIN:-}" ] || cargo build --release --bin pressridge >&2
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
echo "machine: $(nproc) cores, $(lscpu | sed -n 's/^Model name: *//p'), $(date -u +%F)"
echo "binary: $bin"
echo "commit: $(git rev-parse --short HEAD)$(git diff --quiet || echo ' (modified)')"

# One timed run: BIN then simulate's extra arguments. Prints its line and leaves the wall
# time (s) in $wall.
timed() {
  local b=$1; shift
  echo "load before: $(cut -d' ' -f1-3 /proc/loadavg)"
  # The run's progress goes to a file, shown only if the run fails.
  /usr/bin/time -o "$out/time" -f "%e %U %S" \
    taskset -c 0 "$b" simulate --no-figures --out "$out/run" --overwrite "$@" \
    > /dev/null 2> "$out/stderr" || { cat "$out/stderr" >&2; return 1; }
  read -r wall user sys < "$out/time"
  steps=$(sed -n 's/.*"steps": *\([0-9]*\).*/\1/p' "$out/run/summary.json" | head -1)
  echo "wall $wall s, user $user s, sys $sys s, $steps steps ($b ${*:-default scene})"
}

if [ "${1:-}" = "--compare" ]; then
  base=${BASE_BIN:-$bin}
  read -r -a a <<< "${2:-}"; read -r -a c <<< "${3:-}"
  timed "$base" "${a[@]}"; w0=$wall
  timed "$bin" "${c[@]}"; w1=$wall
  echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)"
  echo "ratio candidate/baseline: $(awk -v a="$w1" -v b="$w0" 'BEGIN { printf "%.3f", a / b }') (wall $w1 s against $w0 s)"
else
  timed "$bin" "$@"
  echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)"
fi
