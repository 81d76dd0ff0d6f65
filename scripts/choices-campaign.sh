#!/usr/bin/env bash
# The register of open modelling choices (issue 30, docs/choices.md): each probe of
# data/campaigns/choices/ (a choice moved from its default, at mu = 0.4 and mu = 1.0 with
# mu_w = 0.6, four seeds each), one after the other on all cores, into runs/choices/<probe>/.
# Resumable like every campaign: re-running continues where it stopped. Run it under nohup:
#   nohup scripts/choices-campaign.sh [THREADS] [OUT_ROOT] > runs/choices.log 2>&1 &
# CHOICES="baseline tip-bevel" runs only those probes (in that order). CHOICES_DIR picks
# the folder of specs: data/campaigns/choices (the first look, on the 20-m floe; the default),
# data/campaigns/choices40 (eight seeds on model revision 1 with the 40-m floe, whose
# baseline is taken from the friction set's records in crates/lab/records/paper2/friction) or
# data/campaigns/choices-r2 (model revision 2; the baseline's later seeds, baseline-more, run
# after the probes so that a first look at every probe comes first). Then
#   pressridge findings --choices runs/choices
# compares each probe with the baseline (docs/choices.md); scripts/archive-records.sh keeps
# the records for the repository (crates/lab/records/choices/).
set -euo pipefail
cd "$(dirname "$0")/.."
threads=${1:-$(nproc)}
root=${2:-runs/choices}
bin=${PRESSRIDGE_BIN:-./target/release/pressridge}
[ -n "${PRESSRIDGE_BIN:-}" ] || cargo build --release --bin pressridge
mkdir -p "$root"
echo "choices campaign: commit $(git rev-parse --short HEAD), $threads threads, $(date -u +%FT%TZ)"
dir=${CHOICES_DIR:-data/campaigns/choices}
if [ "$dir" = data/campaigns/choices ]; then
  default="baseline baseline-more tip-bevel nose-bevel drag floe-length floe-length-more floe-length-80 floe-damping eq8-length crack-speed floe-stiffness floe-pin gap floe-blocks"
else
  # The baseline first, its later seeds (baseline-more) last.
  all=$(cd "$dir" && ls *.toml | sed 's/\.toml$//' | sort)
  default="$(echo "$all" | grep -vx baseline-more | tr '\n' ' ')$(echo "$all" | grep -x baseline-more || true)"
fi
probes=${CHOICES:-$default}
for p in $probes; do
  echo "== $p ($(date -u +%T))"
  resume=()
  # The revision-1 register's baseline is the friction set's two pairs: taken, not run again.
  [ "$dir" = data/campaigns/choices40 ] && [ "$p" = baseline ] && [ -d crates/lab/records/paper2/friction ] &&
    resume=(--resume-from crates/lab/records/paper2/friction)
  # On model revision 2 (choices-r2*), the probe's committed records (a finished or
  # interrupted campaign archived under data/<folder of specs>/<probe>) are taken, not run
  # again; the older registers' archives are of revision 1, which a campaign refuses.
  archive="data/$(basename "$dir")/$p"
  case "$dir" in *choices-r2*) [ -f "$archive/campaign.json" ] && resume+=(--resume-from "$archive") ;; esac
  "$bin" campaign --spec "$dir/$p.toml" --out "$root/$p" "${resume[@]}" \
    --threads "$threads" --progress-interval 60 2> "$root/$p.log"
done
echo "choices campaign done $(date -u +%FT%TZ)"
