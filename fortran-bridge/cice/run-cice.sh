#!/usr/bin/env bash
# CICE's own box cases with pressridge swapped in, from YOUR CICE checkout with its Icepack
# (github.com/CICE-Consortium/CICE and its icepack submodule; nothing of either is in this
# repository):
#
#   fortran-bridge/cice/run-cice.sh /path/to/CICE [CASE ...]
#
# Copies the checkout twice into $WORK (default fortran-bridge/build/cice): stock, and
# swapped, where the `use icepack_intfc` lines of icepack_step_ridge and icepack_ice_strength
# in ice_step_mod.F90, ice_dyn_evp.F90, ice_dyn_eap.F90 and ice_dyn_vp.F90 name the drop-in
# instead (fortran-bridge/icepack/pressridge_icepack.F90, compiled beside CICE with the
# pressridge module; the changed lines are printed). Adds a serial GNU machine to both copies
# (machines/Macros.conda_pressridge: gfortran, the system's netCDF through nf-config, no MPI;
# CICE's own Makefile and flags: -cpp, -fconvert=big-endian, -ffree-line-length-none, and
# with the debug option -fcheck=bounds -finit-real=nan -ffpe-trap=invalid,zero,overflow) and
# a few option files of its own (options/set_nml.pr*: ridging on, daily history of the
# ridging and dynamics fields, the option variants). Builds CICE once per copy (and once more
# in the debug build) with CICE's cice.setup/cice.build, runs every case in both and compares
# every history and restart file value for value (ncdump, all but the creation date and the
# history line). Prints a line per case and `cice: N of N cases bit-identical` last; exit
# status 1 if any differs. Needs gfortran, tcsh (CICE's scripts are csh), netCDF-Fortran and
# Rust (scripts/setup.sh --cice installs the first three).
# Cases (default): the gbox128 case, base_suite's box cases that need no external data (with
# ridging on and one day), each of kstrength, krdg_partic and krdg_redist at 0, EVP, EAP and
# VP dynamics, and a restart test (two days against one day and a restart). Not by default:
# debug (CICE's debug build) and badstates (bad states injected into a restart; each
# build's outcome printed).
set -euo pipefail
source "$(dirname "$0")/cice-common.sh"
shift

CASES=("$@")
[ ${#CASES[@]} -gt 0 ] || CASES=(gbox128 boxnodyn boxadv boxrestore box2001 boxslotcyl boxchan \
  kstrength0 krdg_partic0 krdg_redist0 eap vp restart)

# A case: grid and CICE option sets (comma-separated; pr* are this script's own, below).
case_options() {
  case $1 in
    gbox128) echo "gbox128 short,prhist" ;;
    boxnodyn) echo "gbox128 boxnodyn,short,prridge,prhist" ;;
    boxadv) echo "gbox128 boxadv,short,prridge,prhist" ;;
    boxrestore) echo "gbox128 boxrestore,short,prridge,prhist" ;;
    box2001) echo "gbox80 box2001,short,prridge,prhist" ;;
    boxslotcyl) echo "gbox80 boxslotcyl,short,prridge,prhist" ;;
    boxchan) echo "gbox12 boxchan,diag1,short,prridge,prhist" ;;
    kstrength0) echo "gbox128 short,prhist,prkstrength0" ;;
    krdg_partic0) echo "gbox128 short,prhist,prpartic0" ;;
    krdg_redist0) echo "gbox128 short,prhist,prredist0" ;;
    eap) echo "gbox128 short,prhist,preap" ;;
    vp) echo "gbox128 short,prhist,prvp" ;;
    restart) echo "gbox128 short,prhist,prtwodays" ;;
    debug) echo "gbox128 short,prhist,debug" ;;
    badstates) echo "gbox128 short,prhist" ;;
    *) echo "unknown case $1" >&2; return 1 ;;
  esac
}

# Continues case dir $2 (run folder $3) for one day from restart file $1: runtype continue
# in the case's ice_in (cice.run copies it into the run folder), the pointer file at $1;
# cice.run's output in the case dir's continue.log.
continue_from() {
  echo "$1" > "$3/ice.restart_file"
  sed -i -e "s/^ *runtype *=.*/    runtype = 'continue'/" -e "s/^ *npt *=.*/    npt = 24/" "$2/ice_in"
  (cd "$2" && ./cice.run) > "$2/continue.log" 2>&1 || true
}

# The bad states of the badstates case: one cell, (i, j) = (64, 64) in Fortran's indices, of
# the one-day run's final restart. $1 the restart file (changed in place), $2 the state.
BAD_STATES=(nan negative roundoff noarea)
bad_state_words() {
  case $1 in
    nan) echo "aicen(64,64,3) = NaN" ;;
    negative) echo "aicen(64,64,3) = -0.1" ;;
    roundoff) echo "aicen(64,64,3) = -1e-14 (advection round-off)" ;;
    noarea) echo "aicen(64,64,4) = 0 with vicen 0.3 m (volume without area)" ;;
  esac
}
bad_state_edit() {
  "$PY" - "$1" "$2" << 'PYEOF'
import sys
import netCDF4
f = netCDF4.Dataset(sys.argv[1], "r+")
a, v = f["aicen"], f["vicen"]  # (ncat, nj, ni)
j = i = 63
state = sys.argv[2]
if state == "nan":
    a[2, j, i] = float("nan")
elif state == "negative":
    a[2, j, i] = -0.1
elif state == "roundoff":
    a[2, j, i] = -1e-14
elif state == "noarea":
    a[3, j, i] = 0.0
    v[3, j, i] = 0.3
f.close()
PYEOF
}

# What a run folder's newest run did: completed, or aborted with CICE's and Icepack's
# messages (the warnings Icepack flushes and abort_ice's error line).
run_outcome() {
  local log
  log=$(last_log "$1")
  if grep -q "CICE COMPLETED SUCCESSFULLY" "$log"; then
    echo "completed"
  else
    echo "aborted: $(grep -e 'pressridge' -e 'error =' -e 'Zap\|zap\|ridge_ice\|shift_ice' "$log" \
      | sed 's/^ *//' | sort -u | head -n 4 | tr '\n' ' ' | head -c 400)"
  fi
}

# Compares two run folders' history and restart files: prints the differing files.
compare_runs() {
  local a=$1 b=$2 f
  # (An aborted run may leave only the history of its initial state.)
  for f in $(cd "$a" && find history restart -name '*.nc' 2> /dev/null | sort); do
    if [ ! -f "$b/$f" ]; then echo "$f (missing)"; continue; fi
    diff -q <(ncdump "$a/$f" | grep -v -e ':date' -e ':history' -e '^netcdf ' -e ':time_stamp') \
      <(ncdump "$b/$f" | grep -v -e ':date' -e ':history' -e '^netcdf ' -e ':time_stamp') \
      > /dev/null || echo "$f"
  done
}

same=0
total=0
for name in "${CASES[@]}"; do
  read -r grid opts <<< "$(case_options "$name")"
  flavour=opt
  [[ ",$opts," == *,debug,* ]] && flavour=debug
  for kind in stock swapped; do
    [ -n "${EXE[$kind-$flavour]:-}" ] || build_exe "$kind" "$flavour"
    dir=$(setup_case "$kind" "$name" "$grid" "$opts")
    (cd "$dir" && ./cice.build --exe "${EXE[$kind-$flavour]}" > build.log 2>&1)
    t0=$(date +%s.%N)
    (cd "$dir" && ./cice.run > run.log 2>&1) || true
    echo "$(date +%s.%N) - $t0" | bc > "$WORK/cases/$kind-$name.seconds"
  done
  total=$((total + 1))
  a=$ICE_PRESSRIDGE_WKDIR/stock-$name
  b=$ICE_PRESSRIDGE_WKDIR/swapped-$name
  times="stock $(printf %.1f "$(cat "$WORK/cases/stock-$name.seconds")") s, swapped $(printf %.1f "$(cat "$WORK/cases/swapped-$name.seconds")") s"
  timing="  $name timers: stock $(timers "$a"); swapped $(timers "$b")"
  if ! grep -q "CICE COMPLETED SUCCESSFULLY" "$a"/cice.runlog.* 2>/dev/null; then
    echo "$name ($grid $opts): the stock build did not complete ($(tail -n 2 "$a"/cice.runlog.* | tr '\n' ' '))"
    continue
  fi
  if ! grep -q "CICE COMPLETED SUCCESSFULLY" "$b"/cice.runlog.* 2>/dev/null; then
    echo "$name ($grid $opts): the swapped build did not complete ($(tail -n 2 "$b"/cice.runlog.* | tr '\n' ' '))"
    continue
  fi
  nfiles=$(cd "$a" && find history restart -name '*.nc' | wc -l)
  diffs=$(compare_runs "$a" "$b")
  extra=""
  if [ "$name" = restart ]; then
    # The restart test: day 2 again from the restart of day 1, in each build, equals the
    # two-day run's final restart.
    for kind in stock swapped; do
      r=$ICE_PRESSRIDGE_WKDIR/$kind-$name
      dir=$WORK/cases/$kind-$name
      first=$(cd "$r/restart" && ls iced.*.nc | sort | head -n 1)
      last=$(cd "$r/restart" && ls iced.*.nc | sort | tail -n 1)
      mkdir -p "$r/twoday" && cp "$r/restart/$last" "$r/twoday/"
      continue_from "$r/restart/$first" "$dir" "$r"
      if ! grep -q "runtype *= *continue" "$(last_log "$r")"; then
        extra="$extra, $kind restart NOT RUN"
        diffs="$diffs restart($kind)"
      elif cmp -s <(ncdump "$r/twoday/$last" | grep -v -e ':date' -e ':history' -e '^netcdf ') \
                <(ncdump "$r/restart/$last" | grep -v -e ':date' -e ':history' -e '^netcdf '); then
        extra="$extra, $kind restart exact"
      else
        extra="$extra, $kind restart DIFFERS"
        diffs="$diffs restart($kind)"
      fi
    done
  fi
  if [ "$name" = badstates ]; then
    # Each bad state: the one-day run's final restart with one cell changed, and a day
    # more from it in each build; both outcomes, and the files of two completed runs
    # compared.
    for st in "${BAD_STATES[@]}"; do
      line="  $st ($(bad_state_words "$st")):"
      for kind in stock swapped; do
        r=$ICE_PRESSRIDGE_WKDIR/$kind-$name
        dir=$WORK/cases/$kind-$name
        last=$(cd "$r/restart" && ls iced.*.nc | sort | head -n 1)
        mkdir -p "$r/bad" && cp "$r/restart/$last" "$r/bad/$st.nc"
        bad_state_edit "$r/bad/$st.nc" "$st"
        rm -rf "$r/bad-$st" && mkdir -p "$r/bad-$st"
        continue_from "$r/bad/$st.nc" "$dir" "$r"
        line="$line $kind $(run_outcome "$r");"
        (cd "$r" && find history restart -name '*.nc' -newer "$r/bad/$st.nc" \
          -exec cp --parents {} "$r/bad-$st/" \;)
      done
      sa=$ICE_PRESSRIDGE_WKDIR/stock-$name/bad-$st
      sb=$ICE_PRESSRIDGE_WKDIR/swapped-$name/bad-$st
      if [ -n "$(ls -A "$sa")" ] && [ -n "$(ls -A "$sb")" ]; then
        d=$(compare_runs "$sa" "$sb")
        if [ -z "$d" ]; then line="$line files bit-identical"; else line="$line files DIFFER: $d"; fi
      fi
      extra="$extra
$line"
    done
  fi
  if [ -z "$diffs" ]; then
    same=$((same + 1))
    echo "$name ($grid $opts): bit-identical ($nfiles history and restart files; $times$extra)"
  else
    echo "$name ($grid $opts): DIFFERS in $(echo $diffs | wc -w) of $nfiles files: $(echo $diffs | head -c 300) ($times$extra)"
  fi
  echo "$timing"
done
echo "cice: $same of $total cases bit-identical (CICE $(git -C "$SRC" rev-parse --short HEAD 2>/dev/null || echo '?'), Icepack $(git -C "$SRC/icepack" rev-parse --short HEAD 2>/dev/null || echo '?'))"
[ "$same" -eq "$total" ]
