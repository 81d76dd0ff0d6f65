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
#   scripts/speed-vs-error.sh --candidate
#                                        prints the test of the candidate step (the full
#                                        limit refined ahead of and after fracture,
#                                        r2-refine-load.toml) against a quarter of the limit
#                                        on model revision 2 (r2-quarter.toml) from their
#                                        committed archives: seconds
#   scripts/speed-vs-error.sh --run-candidate [N]
#                                        resumes both campaigns from their archives at once
#                                        (N threads between them, default all), archives
#                                        what they made back into
#                                        crates/lab/records/speed-vs-error/ with the command
#                                        and commit, and prints the test: CPU-hours (about 5
#                                        for the quarter-limit arm), under nohup; a stopped
#                                        run keeps every finished run in runs/, archived by
#                                        the next --run-candidate or by scripts/archive-records.sh
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
recs=crates/lab/records/speed-vs-error
candidate() {
  "$table" quarter="$1/r2-quarter@numerics.time_step_safety=0.25" \
    refined="$2/r2-refine-load@numerics.time_step_safety=1.0"
}
case "${1:-}" in
  --candidate) candidate "$recs" "$recs" ;;
  --run-candidate)
    threads=${2:-$(nproc)}
    half=$(( threads > 1 ? threads / 2 : 1 ))
    commit=$(git rev-parse --short HEAD)
    mkdir -p runs/speed-vs-error
    pids=()
    for c in r2-quarter r2-refine-load; do
      resume=(); [ -d "$recs/$c" ] && resume=(--resume-from "$recs/$c")
      ./target/release/pressridge campaign --spec "data/campaigns/speed-vs-error/$c.toml" \
        --out "runs/speed-vs-error/$c" "${resume[@]}" --threads "$half" \
        > "runs/speed-vs-error/$c.log" 2>&1 &
      pids+=($!)
    done
    status=0
    for p in "${pids[@]}"; do wait "$p" || status=1; done
    for c in r2-quarter r2-refine-load; do
      scripts/archive-records.sh "runs/speed-vs-error/$c" "$recs/$c" \
        "Made by scripts/speed-vs-error.sh --run-candidate $threads (pressridge campaign --spec data/campaigns/speed-vs-error/$c.toml, resumed from this archive), release binary of $commit, $(date -u +%F), $(nproc) cores: $(lscpu | sed -n 's/^Model name: *//p')."
    done
    candidate "$recs" "$recs"
    exit $status
    ;;
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
  *) echo "speed-vs-error: unknown option $1 (--run [N], --candidate, --run-candidate [N] or --former)" >&2; exit 2 ;;
esac
