#!/usr/bin/env bash
# Builds Icepack's columnphysics/*.F90 from a user's checkout into the current directory, as
# the reference data of tests/data/icepack/ were built ($FC, default gfortran, with
# $FFLAGS, default -O2 -ffree-line-length-none): the modules depend on each other, so every
# file is compiled until all have; an object newer than its source is kept.
#   build-icepack.sh ICEPACK_SOURCE_DIR
# Used by run.sh, reference/make-reference.sh and reference/check-dropin.sh.
set -euo pipefail
SRC=$1
FC=${FC:-gfortran}
FFLAGS=${FFLAGS:-"-O2 -ffree-line-length-none"}
todo=("$SRC"/columnphysics/*.F90)
for pass in $(seq 1 ${#todo[@]}); do
  left=()
  for f in "${todo[@]}"; do
    o=$(basename "${f%.F90}").o
    [ -f "$o" ] && [ "$o" -nt "$f" ] && continue
    $FC $FFLAGS -c "$f" -o "$o" 2>/dev/null || left+=("$f")
  done
  todo=("${left[@]+"${left[@]}"}")
  [ ${#todo[@]} -eq 0 ] && break
done
if [ ${#todo[@]} -ne 0 ]; then
  echo "could not compile: ${todo[*]}" >&2
  $FC $FFLAGS -c "${todo[0]}" -o /dev/null
  exit 1
fi
