#!/usr/bin/env bash
# Regenerates the speed-against-error table (docs/speed-vs-error.md): runs the ensembles of
# data/campaigns/speed-vs-error/ (resumable: finished runs are kept, re-running continues)
# into runs/speed-vs-error/, then compares every configuration with the reference.
#   scripts/speed-vs-error.sh [THREADS]      (several CPU-hours: run it under nohup)
# The reference (and implicit-0.8) specs fix their step through the stable-limit estimate
# of commit 0278a19: their published records were made with that commit's binary (see the
# specs). The current binary runs them with another step; to remake the reference exactly,
# build 0278a19 and run its campaign into runs/speed-vs-error/reference first (finished
# runs are kept).
set -euo pipefail
cd "$(dirname "$0")/.."
threads=${1:-$(nproc)}
cargo build --release --bin pressridge --example speed_vs_error
configs=(reference default)
for c in "${configs[@]}"; do
  ./target/release/pressridge campaign --spec "data/campaigns/speed-vs-error/$c.toml" \
    --out "runs/speed-vs-error/$c" --threads "$threads"
done
args=()
for c in "${configs[@]}"; do args+=("$c=runs/speed-vs-error/$c"); done
./target/release/examples/speed_vs_error "${args[@]}"
