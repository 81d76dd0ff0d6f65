#!/usr/bin/env bash
# Opt-in side-by-side benchmark of the complete ridging step against Icepack.
#
#   fortran-bridge/bench/icepack/run.sh /path/to/Icepack [NCOL]
#
# Builds Icepack's columnphysics/*.F90 from YOUR checkout (github.com/CICE-Consortium/Icepack;
# nothing of Icepack is in this repository) with gfortran -O2 -ffree-line-length-none, the
# pressridge Fortran module and bench_icepack_ridge.f90 into $BUILD (default
# fortran-bridge/build/icepack-bench), links target/release/libpressridge.so
# (cargo build --release --lib) and runs it. Prints ns per cell for Icepack per cell,
# pressridge per cell, the Icepack drop-in (icepack/pressridge_icepack.F90) per cell and
# pressridge batched, on the same columns in the same run.
set -euo pipefail
if [ $# -lt 1 ] || [ ! -d "$1/columnphysics" ]; then
  echo "usage: $0 ICEPACK_SOURCE_DIR [NCOL]  (the directory holding columnphysics/)" >&2
  exit 2
fi
SRC=$(cd "$1" && pwd)
NCOL=${2:-100000}
HERE=$(cd "$(dirname "$0")" && pwd)
ROOT=$(cd "$HERE/../../.." && pwd)
BUILD=${BUILD:-$ROOT/fortran-bridge/build/icepack-bench}
FC=${FC:-gfortran}
FFLAGS="-O2 -ffree-line-length-none"
mkdir -p "$BUILD"
cd "$BUILD"
"$HERE/build-icepack.sh" "$SRC"
LIB=$ROOT/target/release
[ -f "$LIB/libpressridge.so" ] || (cd "$ROOT" && cargo build --release --lib)
# The pressridge module (fortran-bridge/src/, in the Makefile's order): *.mod and pressridge*.o.
make -s -C "$ROOT/fortran-bridge" module BUILD="$BUILD" FC="$FC" FFLAGS="-O2"
# The drop-in module (built with Icepack's modules, as a host builds it).
$FC -O2 -ffree-line-length-none -c "$ROOT/fortran-bridge/icepack/pressridge_icepack.F90" -o dropin_module.o
$FC -O2 -ffree-line-length-none -c "$HERE/bench_icepack_ridge.f90" -o bench_icepack_ridge.o
$FC -o bench_icepack_ridge bench_icepack_ridge.o dropin_module.o pressridge*.o icepack_*.o \
  -L"$LIB" -lpressridge -Wl,-rpath,"$LIB"
./bench_icepack_ridge "$NCOL"
