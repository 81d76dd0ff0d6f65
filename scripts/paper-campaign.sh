#!/usr/bin/env bash
# The paper's whole experiment campaign (Hopkins 1994, Table 1): every set of
# data/campaigns/ — thickness, friction, modulus, floe, speed, the lookup table's extension
# to 0.10-6.00 m (thickness-scaled: the scene scaled with the sheet above the paper's range,
# thickness-scaled-thick its 4-6 m with the floe at half the ratio, thickness-thin), the
# checks of rafting and of the floe (thickness-thick with the 2 m floe, sheet-length,
# thickness-thick-floe, thickness-scaled-floe) and the friction pairs at 0.20 and 0.45 m
# (friction-thickness) — seven seeds each (twelve for friction), one set after the other on
# all cores, at today's model and step, into OUT_ROOT/<set>/ (default runs/paper5).
# Resumable: finished runs are kept and re-running continues where it stopped (a run cut off
# mid-way starts again), also on another machine from the records committed under
# PAPER_RECORDS/<set> (default crates/lab/records/paper5, the decided model at the refined
# full step; older archives under crates/lab/records/ hold former models or steps, whose
# scenes differ, and are refused). Each set's progress goes to OUT_ROOT/<set>.log. About
# ten CPU-hours for the whole list (docs/performance.md); run it under nohup:
#   nohup scripts/paper-campaign.sh [THREADS] [OUT_ROOT] > runs/paper5.log 2>&1 &
# PAPER_SETS="friction modulus" runs only those sets (in that order). PAPER_EXTRA names more
# archives to take finished runs from (space-separated; one not made yet is skipped), e.g.
# runs/paper5/thickness for the friction set, whose default pair at 0.30 m is the thickness
# set's: a run of the same scene and seed is taken whatever its id. PRESSRIDGE_BIN names a
# built binary (a copy, so that rebuilding does not change a running campaign).
# Then tabulate a set with `pressridge tabulate --campaign runs/paper5/<set> ...`
# (crates/lab/records/README.md gives the commands behind each committed archive and report).
set -euo pipefail
cd "$(dirname "$0")/.."
threads=${1:-$(nproc)}
root=${2:-runs/paper5}
records=${PAPER_RECORDS:-crates/lab/records/paper5}
bin=${PRESSRIDGE_BIN:-./target/release/pressridge}
[ -n "${PRESSRIDGE_BIN:-}" ] || cargo build --release --bin pressridge
mkdir -p "$root"
echo "paper campaign: $("$bin" --version 2>/dev/null || echo pressridge), commit $(git rev-parse --short HEAD), $threads threads, $(date -u +%FT%TZ)"
# Thickness first (it feeds the default lookup table), then the table's thick end (cheap:
# few, heavy blocks; thickness-scaled, 56 runs in about an hour on one core, and
# thickness-scaled-thick, 21 runs in minutes), the 2 m floe
# thick end, the sheet-length and floe checks of rafting, the friction set (the
# table's friction coordinates) and its pairs at 0.20 and 0.45 m, the other sets, the long
# slow-speed runs, and last the thin end (many small blocks: the costliest runs).
sets=${PAPER_SETS:-thickness thickness-scaled thickness-scaled-thick thickness-thick sheet-length thickness-thick-floe thickness-scaled-floe friction friction-thickness modulus floe speed thickness-thin}
for set in $sets; do
  echo "== $set ($(date -u +%T))"
  # Runs committed under $records/<set> (a finished or interrupted campaign's records)
  # are taken, not run again.
  resume=()
  [ -d "$records/$set" ] && resume=(--resume-from "$records/$set")
  # An extra archive that does not exist yet (a set this campaign has still to run) or is
  # this set's own output is skipped.
  for extra in ${PAPER_EXTRA:-}; do
    if [ -f "$extra/plan.json" ] && [ "$extra" != "$root/$set" ]; then
      resume+=(--resume-from "$extra")
    fi
  done
  "$bin" campaign --spec "data/campaigns/$set.toml" --out "$root/$set" "${resume[@]}" \
    --threads "$threads" --progress-interval 60 2> "$root/$set.log"
done
echo "paper campaign done $(date -u +%FT%TZ)"
