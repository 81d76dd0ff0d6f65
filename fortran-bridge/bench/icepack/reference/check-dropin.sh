#!/usr/bin/env bash
# The Fortran drop-in (fortran-bridge/icepack/pressridge_icepack.F90) against Icepack itself
# (issue 31, item 1), from YOUR Icepack checkout (nothing of Icepack is in this repository):
#
#   fortran-bridge/bench/icepack/reference/check-dropin.sh /path/to/Icepack
#
# Builds the reference driver ridge_reference.f90 twice: as it is (Icepack's
# icepack_step_ridge and icepack_ice_strength) and with its `use icepack_intfc` line for them
# replaced by
#   use pressridge_icepack, only: icepack_step_ridge => pressridge_icepack_step_ridge, &
#        icepack_ice_strength => pressridge_icepack_ice_strength
# (the one line a host changes), and a call of pressridge_icepack_refresh() after each case's
# icepack_init_parameters (the driver changes Icepack's parameters between calls, which a
# host does not), then runs the reference cases (make_reference.py) in four tracer layouts
# (snow, isotopes and aerosols; topography ponds, floe size and brine; the latter with
# vertically resolved and with skeletal bio tracers) through both and compares every output. Prints a line per case and
# `drop-in: N of N cases bit-identical` last (the typical and hard cases; the stress cases,
# where Icepack returns negative amounts, are listed with what each does); exit status 1 if
# any differs.
set -euo pipefail
if [ $# -lt 1 ] || [ ! -d "$1/columnphysics" ]; then
  echo "usage: $0 ICEPACK_SOURCE_DIR  (the directory holding columnphysics/)" >&2
  exit 2
fi
SRC=$(cd "$1" && pwd)
HERE=$(cd "$(dirname "$0")" && pwd)
ROOT=$(cd "$HERE/../../../.." && pwd)
BUILD=${BUILD:-$ROOT/fortran-bridge/build/icepack-dropin}
FC=${FC:-gfortran}
FFLAGS="-O2 -ffree-line-length-none"
mkdir -p "$BUILD"
# Icepack as the reference data were built, and the reference driver on it.
BUILD=$BUILD/icepack "$HERE/make-reference.sh" "$SRC" "$BUILD/icepack.jsonl" > /dev/null
for variant in topo bgc skl; do
  BUILD=$BUILD/icepack "$HERE/make-reference.sh" "$SRC" "$BUILD/icepack_$variant.jsonl" $variant > /dev/null
done
cd "$BUILD"
cp icepack/icepack_*.o icepack/*.mod .
LIB=$ROOT/target/release
# The library as a host builds it (a no-op when it is current).
(cd "$ROOT" && cargo build --release -p pressridge-clib)
make -s -C "$ROOT/fortran-bridge" module BUILD="$BUILD" FC="$FC" FFLAGS="-O2"
$FC $FFLAGS -c "$ROOT/fortran-bridge/icepack/pressridge_icepack.F90" -o dropin_module.o
# The swap: one line of the driver.
sed -e 's/^  use icepack_intfc, only: icepack_step_ridge, icepack_ice_strength, /  use pressridge_icepack, only: icepack_step_ridge => pressridge_icepack_step_ridge, icepack_ice_strength => pressridge_icepack_ice_strength, pressridge_icepack_refresh\n  use icepack_intfc, only: /' \
    -e 's/^     d1 = 0; d2 = 0/     call pressridge_icepack_refresh()\n&/' \
  "$HERE/ridge_reference.f90" > ridge_dropin.f90
diff "$HERE/ridge_reference.f90" ridge_dropin.f90 | grep '^[<>]' | sed 's/^/  swapped: /' || true
$FC $FFLAGS -c ridge_dropin.f90 -o ridge_dropin.o
$FC -o ridge_dropin ridge_dropin.o dropin_module.o pressridge*.o icepack_*.o \
  -L"$LIB" -lpressridge -Wl,-rpath,"$LIB"
for variant in aero topo bgc skl; do
  python3 "$HERE/make_reference.py" "$BUILD/ridge_dropin" \
    "$ROOT/tests/data/icepack/ridge_step_cases.jsonl" "$BUILD/dropin_$variant.jsonl" $variant > /dev/null
done
python3 - "$BUILD" <<'PY'
import json, sys
same = n = 0
for variant, ref in (("aero", "icepack.jsonl"), ("topo", "icepack_topo.jsonl"),
                     ("bgc", "icepack_bgc.jsonl"), ("skl", "icepack_skl.jsonl")):
    print(f"== {variant}: " + {"aero": "41 tracers, level-ice ponds, snow, 3 isotope and 2 aerosol species",
                                "topo": "37 tracers, topography ponds, snow refills, floe size, brine",
                                "bgc": "47 tracers, the topo layout and 2 vertically resolved bio tracers",
                                "skl": "39 tracers, the topo layout and 2 skeletal bio tracers"}[variant])
    a = [json.loads(l) for l in open(f"{sys.argv[1]}/{ref}")][1:]
    b = [json.loads(l) for l in open(f"{sys.argv[1]}/dropin_{variant}.jsonl")][1:]
    for x, y in zip(a, b):
        ox, oy = x["outputs"], y["outputs"]
        if x["group"] == "stress":
            # Where Icepack returns negative amounts or aborts, pressridge refuses (an abort
            # through Icepack's warnings) or gives a conserving answer: docs/strength.md.
            print(f"{x['case']} (stress): Icepack {'aborts' if ox['aborted'] else 'answers'}, "
                  f"the drop-in {'aborts' if oy['aborted'] else 'answers'} (documented)")
            continue
        n += 1
        if ox["aborted"]:
            ok = oy["aborted"]
            what = "Icepack aborts; the drop-in " + ("aborts too" if ok else "does not")
        else:
            diff = [k for k in ox if k != "warnings" and ox[k] != oy.get(k)]
            ok = not diff and not oy["aborted"]
            what = "bit-identical" if ok else "differs: " + ", ".join(diff or ["aborted"])
        same += ok
        print(f"{x['case']} ({x['group']}): {what}")
print(f"drop-in: {same} of {n} cases bit-identical")
sys.exit(0 if same == n else 1)
PY
