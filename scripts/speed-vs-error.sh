#!/usr/bin/env bash
# The speed-against-error table (docs/speed-vs-error.md).
#
#   scripts/speed-vs-error.sh            prints the table from the committed records
#                                        (data/speed-vs-error/<config>, records-only
#                                        archives): seconds
#   scripts/speed-vs-error.sh --run [N]  first runs the ensembles of the configurations the
#                                        current code makes (default, step-1.0) into
#                                        runs/speed-vs-error/<config> on N threads, taking
#                                        every committed run (--resume-from), then prints
#                                        the table from those directories: CPU-hours, run
#                                        it under nohup
#
# The reference (and implicit-0.8) rows were made by older binaries (commits 0278a19 and
# b4f38ab, named in their specs): the stable-limit estimate changed after them, so the
# current code would run their specs with another step. To add reference runs, build
# 0278a19 and run its campaign with a spec of the missing seeds (`first_seed`, as
# data/campaigns/speed-vs-error/reference-more.toml), then keep the result as a
# records-only archive data/speed-vs-error/<config>-more (docs/speed-vs-error.md).
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build --release --bin pressridge --example speed_vs_error
table=./target/release/research/speed_vs_error
# A configuration's runs: its archive, plus the archives of its extra seeds where there are
# any (<config>-more: seeds 13-26 at h = 0.30 m; <config>-more-045: the same at 0.45 m),
# pooled by the table (`NAME=DIR1+DIR2+...`).
runs_of() {
  local root=$1 c=$2 d="$1/$2" x
  for x in "$root/$c-more" "$root/$c-more-045"; do
    [ -d "$x" ] && d="$d+$x"
  done
  echo "$d"
}
if [ "${1:-}" = "--run" ]; then
  threads=${2:-$(nproc)}
  for c in default default-more default-more-045 step-1.0 step-1.0-more step-1.0-more-045; do
    resume=()
    [ -d "data/speed-vs-error/$c" ] && resume=(--resume-from "data/speed-vs-error/$c")
    ./target/release/pressridge campaign --spec "data/campaigns/speed-vs-error/$c.toml" \
      --out "runs/speed-vs-error/$c" "${resume[@]}" --threads "$threads"
  done
  "$table" reference="$(runs_of data/speed-vs-error reference)" \
    default="$(runs_of runs/speed-vs-error default)" \
    step-1.0="$(runs_of runs/speed-vs-error step-1.0)" \
    implicit-2.32e-4=data/speed-vs-error/implicit-0.8
else
  "$table" reference="$(runs_of data/speed-vs-error reference)" \
    default="$(runs_of data/speed-vs-error default)" \
    step-1.0="$(runs_of data/speed-vs-error step-1.0)" \
    step-0.25=data/speed-vs-error/step-0.25 \
    implicit-2.32e-4=data/speed-vs-error/implicit-0.8
fi
