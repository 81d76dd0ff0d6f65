#!/usr/bin/env bash
# Installs what pressridge needs on a fresh Debian 12 machine, and only what is missing.
#   scripts/setup.sh            system packages + Rust components
#   scripts/setup.sh --python   also the Python virtual environment (.venv) used by the tests
#   scripts/setup.sh --cice     also tcsh and bc, for CICE's csh scripts and the CICE host
#                               run (fortran-bridge/cice/run-cice.sh)
set -euo pipefail
cd "$(dirname "$0")/.."

apt_pkgs=(pkg-config gfortran libnetcdf-dev libnetcdff-dev libhdf5-dev netcdf-bin fonts-dejavu-core ffmpeg)
[ "${1:-}" = "--cice" ] && apt_pkgs+=(tcsh bc)
missing=()
for p in "${apt_pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  sudo=""; [ "$(id -u)" -ne 0 ] && sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

if command -v rustup >/dev/null; then
  for c in rustfmt clippy; do
    rustup component list --installed 2>/dev/null | grep -q "^$c" || rustup component add "$c"
  done
fi

if [ "${1:-}" = "--python" ]; then
  py=${PYTHON:-python3}
  [ -x .venv/bin/python ] || "$py" -m venv .venv
  req=python/requirements-dev.txt
  if [ -f "$req" ]; then
    # pip is quiet and quick when everything is already satisfied.
    .venv/bin/python -m pip install -q --disable-pip-version-check -r "$req"
  fi
fi
