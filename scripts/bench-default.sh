#!/usr/bin/env bash
# End-to-end benchmark of the simulator (docs/performance.md): the README's main job, the
# built-in default scene (the paper's Figure 5 experiment, 400 s), without figures, on one
# core. Prints the machine, the load before and after, the wall and CPU time and the steps.
#   scripts/bench-default.sh [EXTRA simulate ARGS, e.g. --set numerics.time_step_safety=0.5]
#   PRESSRIDGE_BIN=path/to/pressridge scripts/bench-default.sh   # another binary, not rebuilt
set -euo pipefail
cd "$(dirname "$0")/.."
bin=${PRESSRIDGE_BIN:-./target/release/pressridge}
[ -n "${PRESSRIDGE_BIN:-}" ] || cargo build --release --bin pressridge >&2
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
echo "machine: $(nproc) cores, $(lscpu | sed -n 's/^Model name: *//p'), $(date -u +%F)"
echo "binary: $bin"
echo "commit: $(git rev-parse --short HEAD)$(git diff --quiet || echo ' (modified)')"
echo "load before: $(cut -d' ' -f1-3 /proc/loadavg)"
/usr/bin/time -f "wall %e s, user %U s, sys %S s" \
  taskset -c 0 "$bin" simulate --no-figures --out "$out" "$@"
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)"
