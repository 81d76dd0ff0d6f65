#!/usr/bin/env bash
# The Python package's checks: lints the extension crate (python/, kept out of the default
# workspace members so that plain cargo never needs Python), builds the command line and the
# extension (release, into .venv with maturin) and runs the pytest suite in python/tests.
# scripts/test.sh calls this when python/pyproject.toml exists; run it alone the same way.
set -euo pipefail
cd "$(dirname "$0")/.."
[ -x .venv/bin/python ] || scripts/setup.sh --python
export VIRTUAL_ENV="$PWD/.venv"
export PATH="$VIRTUAL_ENV/bin:$PATH"
export PYO3_PYTHON="$VIRTUAL_ENV/bin/python"

echo "== cargo clippy -p pressridge-python -- -D warnings"
cargo clippy -p pressridge-python --all-targets -- -D warnings
echo "== cargo build --release --bin pressridge --lib (the CLI and the C library the tests compare against)"
cargo build --release --bin pressridge --lib
echo "== maturin develop --release (python/ into .venv)"
(cd python && maturin develop --release --quiet)

echo "== pytest python/tests"
export PRESSRIDGE_BIN="$PWD/target/release/pressridge"
set +e
python -m pytest python/tests -q -p no:cacheprovider "$@"
rc=$?
set -e
if [ "$rc" -eq 5 ]; then
  echo "test-python: pytest collected no tests; that is a failure here" >&2
  exit 1
fi
exit "$rc"
