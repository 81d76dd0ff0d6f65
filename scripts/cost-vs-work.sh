#!/usr/bin/env bash
# Cost against work (docs/performance.md): the wall time per simulated second as the ridge
# grows, with the bodies and contacts, for the Figure 5 scene at h = 0.20, 0.45, 1 and 3 m
# (the thick sheets scaled with h as in data/campaigns/thickness-scaled.toml), at each step
# configuration given (default: the default step, half the stable limit). One run at a time,
# pinned to one core; prints the machine, the load and each run's totals, and writes one CSV
# per run (crates/lab/research/cost_vs_work.rs) into OUT_DIR.
#   scripts/cost-vs-work.sh OUT_DIR [CONFIG ...]
#   CONFIG: a name and its settings, e.g. half:numerics.time_step_safety=0.5
#           refined:numerics.time_step_safety=1.0,numerics.refine_window=0.05
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:?output directory}; shift
configs=("$@")
[ ${#configs[@]} -gt 0 ] || configs=("default:")
cargo build --release --example cost_vs_work >&2
bin=target/release/examples/cost_vs_work
mkdir -p "$out"
thick=(
  "0.20:sheet.thickness=0.20 sheet.block_width=0.20"
  "0.45:sheet.thickness=0.45 sheet.block_width=0.30"
  "1.00:sheet.thickness=1.00 sheet.block_width=0.67 sheet.length=83.33 floe.thickness=6.67 floe.length=133.33 floe.block_width=3.33 floe.nose_bevel=1.67"
  "3.00:sheet.thickness=3.00 sheet.block_width=2.00 sheet.length=250.00 floe.thickness=20.00 floe.length=400.00 floe.block_width=10.00 floe.nose_bevel=5.00"
)
echo "machine: $(nproc) cores, $(lscpu | sed -n 's/^Model name: *//p'), $(date -u +%F)"
echo "commit: $(git rev-parse --short HEAD)$(git diff --quiet || echo ' (modified)')"
for t in "${thick[@]}"; do
  h=${t%%:*}; read -r -a sets <<< "${t#*:}"
  for c in "${configs[@]}"; do
    name=${c%%:*}; extra=${c#*:}
    IFS=, read -r -a more <<< "$extra"
    echo "h = $h m, $name; load before: $(cut -d' ' -f1-3 /proc/loadavg)"
    taskset -c 0 "$bin" 400 25 "$out/h$h-$name.csv" "${sets[@]}" "${more[@]}" 2>/dev/null
  done
done
