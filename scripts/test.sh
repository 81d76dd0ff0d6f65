#!/usr/bin/env bash
# Every check a clean checkout must pass: formatting, lints, Rust tests (unit, integration,
# doc), and the Python, Fortran and C suites where present. CI runs exactly this (.ci/run).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh $( [ -f python/pyproject.toml ] && echo --python )

echo "== cargo fmt --check"
cargo fmt --all -- --check
echo "== cargo clippy --all-targets -- -D warnings"
cargo clippy --all-targets -- -D warnings
echo "== cargo test"
cargo test --all-targets
cargo test --doc

if [ -f fortran-bridge/Makefile ]; then
  echo "== Fortran and C bridge tests"
  make -C fortran-bridge test
fi
if [ -f python/pyproject.toml ]; then
  echo "== Python tests"
  scripts/test-python.sh
fi
