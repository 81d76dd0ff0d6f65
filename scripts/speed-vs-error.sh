#!/usr/bin/env bash
# Regenerates the speed-against-error table (docs/speed-vs-error.md): runs the ensembles of
# data/campaigns/speed-vs-error/ (resumable: finished runs are kept, re-running continues)
# into runs/speed-vs-error/, then compares every configuration with the reference.
#   scripts/speed-vs-error.sh [THREADS]      (several CPU-hours: run it under nohup)
set -euo pipefail
cd "$(dirname "$0")/.."
threads=${1:-$(nproc)}
cargo build --release --bin pressridge --example speed_vs_error
configs=(reference implicit-0.8)
for c in "${configs[@]}"; do
  ./target/release/pressridge campaign --spec "data/campaigns/speed-vs-error/$c.toml" \
    --out "runs/speed-vs-error/$c" --threads "$threads"
done
args=()
for c in "${configs[@]}"; do args+=("$c=runs/speed-vs-error/$c"); done
./target/release/examples/speed_vs_error "${args[@]}"
