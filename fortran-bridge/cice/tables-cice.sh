#!/usr/bin/env bash
# What the simulator's tables do to the ice in CICE: CICE's gbox128 box case (the default
# physics: EVP, Rothrock's strength, exponential participation and redistribution, mushy
# thermodynamics, the box2001 winds and ocean) run for DAYS days in each configuration:
#
#   fortran-bridge/cice/tables-cice.sh /path/to/CICE [DAYS] [CONFIG ...]
#
#   cice     stock CICE, its defaults: C_f = 17, mu_rdg = 3 m^0.5
#   hibler   stock CICE, Hibler's (1979) strength (kstrength = 0)
#   cf       CICE with pressridge swapped in (the use lines only, as run-cice.sh), C_f(h) of
#            data/ridging_table.nc for the strength, mu_rdg = 3 m^0.5
#   mu_rdg   the same, CICE's C_f = 17 and mu_rdg(h) of the table for the redistribution
#   tables   the same, both from the table
#
# The tables are set by a namelist file pressridge_in in the run folder (docs/fortran.md);
# the friction pair is FRICTION (default "1.0 0.6": mu above, mu_w below the water line).
# DAYS defaults to 60; CONFIG to all five. Daily history of the ridging and dynamics fields
# and the thickness distribution (aicen, vicen) goes to $WORK/runs/tables-CONFIG/history;
# CICE's timers and the run's wall time are printed per configuration. The figures and the
# summary: cargo run --release -p pressridge-lab --example cice_tables -- $WORK/runs
# (docs/host-cice.md). About 40 s of one core per model day and configuration.
set -euo pipefail
USAGE_ARGS="[DAYS] [CONFIG ...]"
source "$(dirname "$0")/cice-common.sh"
shift
DAYS=${1:-60}
[ $# -gt 0 ] && shift
[[ $DAYS =~ ^[1-9][0-9]*$ ]] || { echo "tables-cice: DAYS must be a positive whole number of days, not '$DAYS'" >&2; exit 2; }
CONFIGS=("$@")
[ ${#CONFIGS[@]} -gt 0 ] || CONFIGS=(cice hibler cf mu_rdg tables)
read -r MU MU_W <<< "${FRICTION:-1.0 0.6}"
TABLE=$ROOT/data/ridging_table.nc
COMMIT=$(git -C "$ROOT" rev-parse --short HEAD)$(git -C "$ROOT" diff --quiet HEAD -- . || echo "+changes")

# The run length and its history: npt steps of an hour, daily means of the fields, and a
# restart at the end only.
for kind in stock swapped; do
  printf 'npt = %d\ndumpfreq = "d"\ndumpfreq_n = %d\n' $((24 * DAYS)) "$DAYS" \
    > "$WORK/$kind/configuration/scripts/options/set_nml.prdays"
done

# A configuration: its build, CICE's option sets and pressridge_in's tables ("-" for none).
config() {
  case $1 in
    cice) echo "stock short,prhist,prdays - -" ;;
    hibler) echo "stock short,prhist,prdays,prkstrength0 - -" ;;
    cf) echo "swapped short,prhist,prdays $TABLE -" ;;
    mu_rdg) echo "swapped short,prhist,prdays - $TABLE" ;;
    tables) echo "swapped short,prhist,prdays $TABLE $TABLE" ;;
    *) echo "tables-cice: unknown configuration $1 (cice, hibler, cf, mu_rdg or tables)" >&2; return 1 ;;
  esac
}
for name in "${CONFIGS[@]}"; do config "$name" > /dev/null; done

for name in "${CONFIGS[@]}"; do
  read -r kind opts cf mr <<< "$(config "$name")"
  [ -n "${EXE[$kind-opt]:-}" ] || build_exe "$kind" opt
  dir=$(setup_case "$kind" "tables-$name" gbox128 "$opts")
  (cd "$dir" && ./cice.build --exe "${EXE[$kind-opt]}" > build.log 2>&1)
  run=$ICE_PRESSRIDGE_WKDIR/$kind-tables-$name
  if [ "$cf" != - ] || [ "$mr" != - ]; then
    {
      echo "&pressridge_nml"
      [ "$cf" != - ] && echo "  cf_table = '$cf'"
      [ "$mr" != - ] && echo "  mu_rdg_table = '$mr'"
      echo "  friction = $MU, friction_water = $MU_W"
      echo "/"
    } > "$run/pressridge_in"
  fi
  t0=$(date +%s.%N)
  (cd "$dir" && ./cice.run > run.log 2>&1) || true
  wall=$(echo "$(date +%s.%N) - $t0" | bc)
  rm -rf "$ICE_PRESSRIDGE_WKDIR/tables-$name"
  mv "$run" "$ICE_PRESSRIDGE_WKDIR/tables-$name"
  run=$ICE_PRESSRIDGE_WKDIR/tables-$name
  if grep -q "CICE COMPLETED SUCCESSFULLY" "$run"/cice.runlog.* 2> /dev/null; then
    echo "$name: $DAYS days in $(printf %.0f "$wall") s ($(timers "$run")); $(grep -h '^pressridge_icepack:' "$run"/cice.runlog.* | head -n 1 | sed 's/^pressridge_icepack: //')"
  else
    echo "$name: did not complete ($(tail -n 2 "$run"/cice.runlog.* 2> /dev/null | tr '\n' ' '))"
  fi
done
echo "tables-cice: $DAYS days of gbox128 in $WORK/runs/tables-{$(IFS=,; echo "${CONFIGS[*]}")} (CICE $(git -C "$SRC" rev-parse --short HEAD 2>/dev/null || echo '?'), pressridge $COMMIT)"
