#!/usr/bin/env bash
# The main job: install what is missing, build, and run the built-in default scene.
# Output goes to runs/default (summary.json, time series, figures, final state), replacing
# an earlier run there.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
cargo build --release --bin pressridge
out=${1:-runs/default}
# --overwrite: running the job again replaces the earlier run there (only its files).
./target/release/pressridge simulate --out "$out" --overwrite
echo "results in $out"
