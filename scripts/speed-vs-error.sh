#!/usr/bin/env bash
# The speed-against-error tables (docs/speed-vs-error.md).
#
#   scripts/speed-vs-error.sh            prints the step table of the model as it is now
#                                        (issue 30, item 3: a quarter, half, 0.8 and the
#                                        full stable limit) from the committed records
#                                        (crates/lab/records/speed-vs-error/decided-*, records-only
#                                        archives): seconds
#   scripts/speed-vs-error.sh --run [N]  first runs what those campaigns still lack (their
#                                        specs hold more seeds than were run) into
#                                        runs/speed-vs-error/decided-* on N threads, taking
#                                        every committed run (--resume-from), then prints
#                                        the table from those directories: CPU-hours, run
#                                        it under nohup and stop it when enough seeds are in
#   scripts/speed-vs-error.sh --former   prints the former model's table (k_te per
#                                        thickness, the 20-m floe;
#                                        docs/notes/speed-vs-error-former-model.md) from
#                                        crates/lab/records/speed-vs-error/<config>[-more]
#
# The former model's records were made by binaries and scenes the current code no longer
# makes (its k_te reading is gone from the options), so they are read, never resumed.
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build --release --bin pressridge --example speed_vs_error
table=./target/release/examples/speed_vs_error
runs_of() {
  local root=$1 c=$2 d="$1/$2" x
  for x in "$root/$c-more" "$root/$c-more-045"; do
    [ -d "$x" ] && d="$d+$x"
  done
  echo "$d"
}
decided() {
  local root=$1
  "$table" quarter="$root/decided-steps@numerics.time_step_safety=0.25" \
    half="$root/decided-half@numerics.time_step_safety=0.5" \
    default="$root/decided-default@numerics.time_step_safety=0.8" \
    full="$root/decided-steps@numerics.time_step_safety=1.0"
}
case "${1:-}" in
  --run)
    threads=${2:-$(nproc)}
    for c in decided-steps decided-half decided-default; do
      ./target/release/pressridge campaign --spec "data/campaigns/speed-vs-error/$c.toml" \
        --out "runs/speed-vs-error/$c" --resume-from "crates/lab/records/speed-vs-error/$c" \
        --threads "$threads"
    done
    decided runs/speed-vs-error
    ;;
  --former)
    "$table" reference="$(runs_of crates/lab/records/speed-vs-error reference)" \
      default="$(runs_of crates/lab/records/speed-vs-error default)" \
      step-1.0="$(runs_of crates/lab/records/speed-vs-error step-1.0)" \
      step-0.25=crates/lab/records/speed-vs-error/step-0.25 \
      implicit-2.32e-4=crates/lab/records/speed-vs-error/implicit-0.8
    ;;
  "") decided crates/lab/records/speed-vs-error ;;
  *) echo "speed-vs-error: unknown option $1 (--run [N] or --former)" >&2; exit 2 ;;
esac
