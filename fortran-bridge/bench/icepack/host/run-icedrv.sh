#!/usr/bin/env bash
# Icepack's own column driver (icedrv) run with pressridge swapped in (issue 31, item 3),
# from YOUR Icepack checkout (github.com/CICE-Consortium/Icepack; nothing of Icepack is in
# this repository):
#
#   fortran-bridge/bench/icepack/host/run-icedrv.sh /path/to/Icepack [CASE ...]
#
# Builds the driver twice into $BUILD (default fortran-bridge/build/icedrv): stock, and with
# the one `use icepack_intfc, only: icepack_step_ridge` line of icedrv_step.F90 replaced by the
# drop-in (fortran-bridge/icepack/pressridge_icepack.F90). Writes the driver's inputs: its
# namelist icepack_in with each case's option sets (configuration/scripts/options/set_nml.*),
# the built-in `clim` atmosphere, and a deformation file in the SHEBA open/close format
# (make_open_close.py: hourly opening and closing rates whose net closing is 0.3 per year, so
# that the driver's inflow of new ice does not compound into a column kilometres thick). Runs
# every case for a year in both builds and compares every output file: the daily diagnostics
# of the driver's four columns and the monthly restart files byte for byte, the NetCDF
# history (every variable, `history_format = 'nc'`) value for value by ncdump, and times each
# run (wall seconds for the year, the whole driver: thermodynamics and all). Prints a line per case and
# `icedrv: N of N cases bit-identical` last; exit status 1 if any differs. Each case's line
# also says whether `pressridge ridge-step --tracer-layout` reads the stock driver's NetCDF
# history as it is (the layout from what the driver prints of its tracers).
# Cases (default): the driver's defaults and run1year variants of base_suite.ts that need no
# external data.
set -euo pipefail
if [ $# -lt 1 ] || [ ! -d "$1/columnphysics" ] || [ ! -d "$1/configuration/driver" ]; then
  echo "usage: $0 ICEPACK_SOURCE_DIR [CASE ...]  (an Icepack checkout: columnphysics/, configuration/)" >&2
  exit 2
fi
SRC=$(cd "$1" && pwd)
shift
CASES=("$@")
# (alt04 reads CFS atmosphere files, bgcispol and bgcnice the ISPOL and N-ICE forcing: external
# data. zaero is base_suite's biogeochemistry that needs none.)
[ ${#CASES[@]} -gt 0 ] || CASES=(default diag1 thermo1 alt01 alt02 alt03 snwitdrdg isotope modal \
  calcdragio fluxopenw dyn zaero)
HERE=$(cd "$(dirname "$0")" && pwd)
ROOT=$(cd "$HERE/../../../.." && pwd)
BUILD=${BUILD:-$ROOT/fortran-bridge/build/icedrv}
FC=${FC:-gfortran}
# As Icepack's gnu Macros, without the big-endian restart conversion (both builds alike),
# with NetCDF history (USE_NETCDF, the system's netcdf-fortran through nf-config).
FFLAGS="-O2 -ffree-line-length-none -cpp -DFORTRANUNDERSCORE -DUSE_NETCDF $(nf-config --fflags)"
NCLIBS=$(nf-config --flibs)
LIB=$ROOT/target/release
# The library the swapped driver links and the command line that reads its history (a no-op
# when they are up to date).
(cd "$ROOT" && cargo build --release --lib --bin pressridge)
mkdir -p "$BUILD"

# Compiles every .F90 of a folder until all have (the modules depend on each other), with
# the preprocessor definitions $2.
compile_all() {
  local dir=$1 defs=$2 todo left f o
  todo=("$dir"/*.F90)
  for pass in $(seq 1 ${#todo[@]}); do
    left=()
    for f in "${todo[@]}"; do
      o="${f%.F90}.o"
      [ -f "$o" ] && [ "$o" -nt "$f" ] && continue
      (cd "$dir" && $FC $FFLAGS $defs -I"$BUILD/pressridge" -c "$(basename "$f")" \
        -o "$(basename "$o")" 2>/dev/null) || left+=("$f")
    done
    todo=("${left[@]+"${left[@]}"}")
    [ ${#todo[@]} -eq 0 ] && return 0
  done
  echo "could not compile: ${todo[*]}" >&2
  (cd "$dir" && $FC $FFLAGS $defs -I"$BUILD/pressridge" -c "$(basename "${todo[0]}")" -o /dev/null)
  return 1
}

# The driver, stock and swapped, for the sizes of a case (its -D definitions): prints the
# folder holding stock/icepack and swapped/icepack.
build_for() {
  local defs=$1 key d
  key=$(echo "$FFLAGS $defs" | md5sum | cut -c1-10)
  d=$BUILD/build-$key
  for build in stock swapped; do
    mkdir -p "$d/$build"
    for f in "$SRC"/columnphysics/*.F90 "$SRC"/configuration/driver/*.F90; do
      cmp -s "$f" "$d/$build/$(basename "$f")" || cp "$f" "$d/$build/"
    done
  done
  cmp -s "$BUILD/icedrv_step.F90" "$d/swapped/icedrv_step.F90" || cp "$BUILD/icedrv_step.F90" "$d/swapped/"
  cmp -s "$ROOT/fortran-bridge/icepack/pressridge_icepack.F90" "$d/swapped/pressridge_icepack.F90" \
    || cp "$ROOT/fortran-bridge/icepack/pressridge_icepack.F90" "$d/swapped/"
  compile_all "$d/stock" "$defs" >&2
  compile_all "$d/swapped" "$defs" >&2
  [ -x "$d/stock/icepack" ] && [ "$d/stock/icepack" -nt "$d/stock/icedrv_MAIN.o" ] \
    || (cd "$d/stock" && $FC -o icepack *.o $NCLIBS)
  (cd "$d/swapped" && $FC -o icepack *.o "$BUILD"/pressridge/pressridge*.o -L"$LIB" -lpressridge \
    -Wl,-rpath,"$LIB" $NCLIBS)
  echo "$d"
}

# The pressridge module, for the swapped build.
make -s -C "$ROOT/fortran-bridge" module BUILD="$BUILD/pressridge" FC="$FC" FFLAGS="-O2"
# The swap: one line of icedrv_step.F90 (the drop-in is compiled beside the driver).
sed 's/^\( *\)use icepack_intfc, only: icepack_step_ridge *$/\1use pressridge_icepack, only: icepack_step_ridge => pressridge_icepack_step_ridge/' \
  "$SRC/configuration/driver/icedrv_step.F90" > "$BUILD/icedrv_step.F90"
changed=$(diff "$SRC/configuration/driver/icedrv_step.F90" "$BUILD/icedrv_step.F90" | grep -c '^>' || true)
echo "swapped build: $changed changed line(s) in icedrv_step.F90:"
diff "$SRC/configuration/driver/icedrv_step.F90" "$BUILD/icedrv_step.F90" | grep '^[<>]' | sed 's/^/  /' || true

# Inputs: the SHEBA-format deformation file, then per case the namelist.
mkdir -p "$BUILD/data/SHEBA"
python3 "$HERE/make_open_close.py" "$BUILD/data/SHEBA/open_clos_lindsay.dat"
same=0
read_ok=0
for case in "${CASES[@]}"; do
  bin=$(build_for "$(python3 "$HERE/make_case.py" "$SRC" "$case" "$BUILD/data" cppdefs)")
  for build in stock swapped; do
    run=$BUILD/runs/$case/$build
    rm -rf "$run" && mkdir -p "$run/restart" "$run/history"
    python3 "$HERE/make_case.py" "$SRC" "$case" "$BUILD/data" namelist > "$run/icepack_in"
    t0=$(date +%s.%N)
    (cd "$run" && "$bin/$build/icepack" > stdout.txt 2> stderr.txt) || true
    echo "$(date +%s.%N) - $t0" | bc > "$run.seconds"
  done
  times="stock $(printf %.1f "$(cat "$BUILD/runs/$case/stock.seconds")") s, swapped $(printf %.1f "$(cat "$BUILD/runs/$case/swapped.seconds")") s"
  a=$BUILD/runs/$case/stock
  b=$BUILD/runs/$case/swapped
  if ! grep -q 'ICEPACK COMPLETED SUCCESSFULLY' "$a/stdout.txt" "$a"/ice_diag* 2>/dev/null; then
    echo "$case: the stock driver did not complete ($(tail -n 2 "$a/stdout.txt" | tr '\n' ' '))"
    continue
  fi
  files=$(cd "$a" && find . -type f ! -name stdout.txt ! -name stderr.txt ! -name icepack_in | sort)
  diffs=()
  for f in $files; do
    case $f in
      # NetCDF history: every variable and attribute but the file's creation date.
      *.nc) diff -q <(ncdump "$a/$f" | grep -v -e ':date' -e ':history' -e 'netcdf ') \
              <(ncdump "$b/$f" | grep -v -e ':date' -e ':history' -e 'netcdf ') > /dev/null \
              || diffs+=("$f") ;;
      *) cmp -s "$a/$f" "$b/$f" || diffs+=("$f") ;;
    esac
  done
  # The command line on the stock driver's history as the driver wrote it (issue 31, item 4):
  # the packed trcrn in the layout the driver reports of itself, the rates given (icedrv's
  # divu and Tf have no units attribute).
  spec=$(python3 "$HERE/make_case.py" "$SRC" "$case" "$BUILD/data" layout "$a/stdout.txt")
  hist=$(find "$a/history" -name '*.nc' | sort | head -n 1)
  rs=$BUILD/runs/$case/ridge-step.nc
  if "$LIB/pressridge" -q ridge-step --input "$hist" --output "$rs" --dt 3600 \
      --convergence 1e-6 --shear 0 --tf -1.8 --tracer-layout "$spec" 2> "$rs.err"; then
    read_ok=$((read_ok + 1))
    cli="ridge-step reads its history: $(ncdump -h "$rs" | sed -n 's/^.*:tracer_layout = "\(.*\) (packed.*$/\1/p')"
  else
    cli="ridge-step on its history FAILED: $(tail -n 1 "$rs.err")"
  fi
  if [ ${#diffs[@]} -eq 0 ]; then
    same=$((same + 1))
    echo "$case: bit-identical ($(echo "$files" | wc -w) files; $times); $cli"
  else
    why=$(grep -h -m1 'pressridge_icepack' "$b/stdout.txt" | sed 's/^ *//' || true)
    echo "$case: differs in ${#diffs[@]} of $(echo "$files" | wc -w) files${why:+ (the drop-in: $why)}"
  fi
done
echo "ridge-step: $read_ok of ${#CASES[@]} histories read with --tracer-layout"
echo "icedrv: $same of ${#CASES[@]} cases bit-identical"
[ "$same" -eq ${#CASES[@]} ] && [ "$read_ok" -eq ${#CASES[@]} ]
