#!/usr/bin/env bash
# Reference columns of Icepack's icepack_step_ridge with snow, isotope and aerosol tracers
# (issue 31, item 2), from YOUR Icepack checkout (github.com/CICE-Consortium/Icepack;
# nothing of Icepack is in this repository):
#
#   fortran-bridge/bench/icepack/reference/make-reference.sh /path/to/Icepack [OUT.jsonl [VARIANT]]
#
# Builds columnphysics/*.F90 as the reference data of tests/data/icepack/ were built
# (gfortran -O2 -ffree-line-length-none, no other flags) with the driver ridge_reference.f90
# into $BUILD (default fortran-bridge/build/icepack-reference), then make_reference.py runs
# the cases of tests/data/icepack/ridge_step_cases.jsonl with the added tracers through it.
# Default output: tests/data/icepack/ridge_step_tracers.jsonl (VARIANT aero); VARIANT topo
# (topography ponds, snow refills, floe size, brine) goes to ridge_step_tracers_topo.jsonl,
# VARIANT bgc (topo with vertically resolved bio tracers) to ridge_step_tracers_bgc.jsonl and
# VARIANT skl (topo with skeletal bio tracers) to ridge_step_tracers_skl.jsonl.
set -euo pipefail
if [ $# -lt 1 ] || [ ! -d "$1/columnphysics" ]; then
  echo "usage: $0 ICEPACK_SOURCE_DIR [OUT.jsonl]  (the directory holding columnphysics/)" >&2
  exit 2
fi
SRC=$(cd "$1" && pwd)
HERE=$(cd "$(dirname "$0")" && pwd)
ROOT=$(cd "$HERE/../../../.." && pwd)
VARIANT=${3:-aero}
DEFAULT=$ROOT/tests/data/icepack/ridge_step_tracers.jsonl
[ "$VARIANT" = aero ] || DEFAULT=$ROOT/tests/data/icepack/ridge_step_tracers_$VARIANT.jsonl
OUT=$(realpath -m "${2:-$DEFAULT}")
BUILD=${BUILD:-$ROOT/fortran-bridge/build/icepack-reference}
FC=${FC:-gfortran}
FFLAGS="-O2 -ffree-line-length-none"
mkdir -p "$BUILD"
cd "$BUILD"
"$HERE/../build-icepack.sh" "$SRC"
$FC $FFLAGS -c "$HERE/ridge_reference.f90" -o ridge_reference.o
$FC -o ridge_reference ridge_reference.o icepack_*.o
echo "Icepack: $(cat "$SRC/columnphysics/version.txt" 2>/dev/null) $(git -C "$SRC" describe --always 2>/dev/null || true), $($FC --version | head -1)"
python3 "$HERE/make_reference.py" "$BUILD/ridge_reference" \
  "$ROOT/tests/data/icepack/ridge_step_cases.jsonl" "$OUT" "$VARIANT"
