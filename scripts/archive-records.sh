#!/usr/bin/env bash
# Copies a campaign's run records into a records-only archive for the repository: its
# campaign.json, plan.json and every runs/<point>/seed-NN/run.json, without the final states
# (state.json, ~1 MB each), and a RECORDS-ONLY marker saying what they are and which command
# and commit made them. `pressridge tabulate`, `pressridge findings` and `--resume-from` read
# such an archive as the campaign itself.
#   scripts/archive-records.sh RUN_DIR ARCHIVE_DIR "what made them (command, commit, date)"
# Into an existing archive it adds the runs it lacks and appends the line to RECORDS-ONLY.
set -euo pipefail
src=${1:?campaign result directory}; dst=${2:?archive directory}; what=${3:?provenance text}
[ -f "$src/campaign.json" ] || { echo "archive-records: $src is not a campaign directory" >&2; exit 1; }
mkdir -p "$dst"
cp "$src/campaign.json" "$src/plan.json" "$dst/"
(cd "$src" && find runs -name run.json) | while read -r f; do
  mkdir -p "$dst/$(dirname "$f")"
  cp "$src/$f" "$dst/$f"
done
# An archive filled over several sessions keeps each one's line.
if [ -f "$dst/RECORDS-ONLY" ]; then
  printf '%s\n' "$what" >> "$dst/RECORDS-ONLY"
else
  printf 'Run records (run.json) of campaign %s, without the final states the runs wrote.\n%s\n' \
    "$(basename "$src")" "$what" > "$dst/RECORDS-ONLY"
fi
echo "archived $(cd "$dst" && find runs -name run.json | wc -l) records into $dst"
