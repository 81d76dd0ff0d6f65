# Shared by run-cice.sh and tables-cice.sh (sourced, with CICE's checkout as "$1"): the
# checkout's two sandboxes (stock, and swapped by the use lines, which it prints), CICE's
# set-up and build of a case, and the run log's timers. Sets SRC, HERE, ROOT, WORK, LIB, PY.
USAGE_ARGS=${USAGE_ARGS:-"[CASE ...]"}
if [ $# -lt 1 ] || [ ! -f "$1/cice.setup" ] || [ ! -d "$1/icepack/columnphysics" ]; then
  echo "usage: $0 CICE_SOURCE_DIR $USAGE_ARGS  (a CICE checkout with its icepack submodule)" >&2
  exit 2
fi
SRC=$(cd "$1" && pwd)
HERE=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
ROOT=$(cd "$HERE/../.." && pwd)
WORK=${WORK:-$ROOT/fortran-bridge/build/cice}

mkdir -p "$WORK"
LIB=$ROOT/target/release
(cd "$ROOT" && cargo build --release -p pressridge-clib)
export PRESSRIDGE_LIBS="-L$LIB -lpressridge -Wl,-rpath,$LIB"
export ICE_PRESSRIDGE_WKDIR=$WORK/runs
# The badstates case edits restart files with netCDF4-python (the test environment's).
PY=$ROOT/.venv/bin/python
[ -x "$PY" ] || PY=python3

# The two sandboxes: copies of the checkout (its sources, scripts and Icepack), then the
# machine and the option files of this script.
for kind in stock swapped; do
  mkdir -p "$WORK/$kind"
  (cd "$SRC" && tar cf - --exclude=.git --exclude=doc cice.setup cicecore configuration icepack) \
    | (cd "$WORK/$kind" && tar xf -)
  cp "$HERE/Macros.conda_pressridge" "$HERE/env.conda_pressridge" \
    "$WORK/$kind/configuration/scripts/machines/"
  for f in "$HERE"/options/set_nml.*; do cp "$f" "$WORK/$kind/configuration/scripts/options/"; done
done

# The swap: the use lines only.
dyn=cicecore/cicedyn/dynamics
swap_strength='use pressridge_icepack, only: icepack_ice_strength => pressridge_icepack_ice_strength'
sed -i 's/^\( *\)use icepack_intfc, only: icepack_step_ridge *$/\1use pressridge_icepack, only: icepack_step_ridge => pressridge_icepack_step_ridge/' \
  "$WORK/swapped/cicecore/cicedyn/general/ice_step_mod.F90"
sed -i "s/^\( *\)use icepack_intfc, only: icepack_ice_strength *\$/\1$swap_strength/" \
  "$WORK/swapped/$dyn/ice_dyn_eap.F90"
for f in ice_dyn_evp.F90 ice_dyn_vp.F90; do
  sed -i "s/^\( *\)use icepack_intfc, only: icepack_ice_strength, icepack_query_parameters *\$/\1use icepack_intfc, only: icepack_query_parameters\n\1$swap_strength/" \
    "$WORK/swapped/$dyn/$f"
done
changed=0
for f in cicecore/cicedyn/general/ice_step_mod.F90 $dyn/ice_dyn_eap.F90 $dyn/ice_dyn_evp.F90 \
  $dyn/ice_dyn_vp.F90; do
  n=$(diff "$SRC/$f" "$WORK/swapped/$f" | grep -c '^>' || true)
  changed=$((changed + n))
done
echo "swapped build: $changed changed line(s) in CICE:"
for f in cicecore/cicedyn/general/ice_step_mod.F90 $dyn/ice_dyn_eap.F90 $dyn/ice_dyn_evp.F90 \
  $dyn/ice_dyn_vp.F90; do
  diff "$SRC/$f" "$WORK/swapped/$f" | grep '^[<>]' | sed "s|^|  $(basename "$f"): |" || true
done
# The pressridge module and the drop-in, as CICE's Makefile compiles them: .F90 files named
# after the module each holds (its dependency generator finds a module by its file's name).
rm -rf "$WORK/pressridge-src" && mkdir -p "$WORK/pressridge-src"
for f in "$ROOT"/fortran-bridge/src/*.f90 "$ROOT/fortran-bridge/icepack/pressridge_icepack.F90"; do
  m=$(sed -n 's/^ *module \([a-z_0-9]*\) *$/\1/p' "$f" | head -n 1)
  cp "$f" "$WORK/pressridge-src/$m.F90"
done

# Sets up a case in a sandbox: $1 stock|swapped, $2 case name, $3 grid, $4 options.
setup_case() {
  # The case's name (hence its run folder under $ICE_PRESSRIDGE_WKDIR) says its sandbox.
  local kind=$1 name=$2 grid=$3 opts=$4 dir=$WORK/cases/$1-$2
  rm -rf "$dir" "$ICE_PRESSRIDGE_WKDIR/$kind-$name"
  mkdir -p "$WORK/cases"
  (cd "$WORK/$kind" && ./cice.setup -m conda -e pressridge -c "$dir" -g "$grid" -p 1x1 -s "$opts" \
    > "$dir.setup.log" 2>&1) || { tail -5 "$dir.setup.log" >&2; return 1; }
  # The drop-in's sources in the swapped build's path.
  if [ "$kind" = swapped ]; then
    sed -i "s|^\${ICE_SANDBOX}/icepack/columnphysics\$|&\n$WORK/pressridge-src|" "$dir/cice.build"
  fi
  echo "$dir"
}

# One executable per sandbox and build type (CICE's grids are set at run time), built when a
# case first needs it.
declare -A EXE
build_exe() {
  local kind=$1 flavour=$2 opts="short" dir
  [ "$flavour" = debug ] && opts="short,debug"
  dir=$(setup_case "$kind" "build-$flavour" gbox128 "$opts")
  (cd "$dir" && ./cice.build > build.log 2>&1) || { tail -20 "$dir/build.log" >&2; return 1; }
  EXE[$kind-$flavour]=$ICE_PRESSRIDGE_WKDIR/$kind-build-$flavour/cice
}

# The newest run log of run folder $1.
last_log() { ls "$1"/cice.runlog.* | sort | tail -n 1; }

# CICE's own timers of run folder $1's first run (s): the ridging step's (Ridging, around
# icepack_step_ridge), the dynamics' (Dynamics, whose EVP/EAP/VP solvers call
# icepack_ice_strength) and the whole run's.
timers() {
  awk '/^Timer +[0-9]+: +(Total|Dynamics|Ridging) /{printf "%s %s s, ", $3, $4}' \
    "$(ls "$1"/cice.runlog.* | sort | head -n 1)" | sed 's/, $//'
}

