#!/usr/bin/env bash
# The Python package's checks: lints the extension crate (python/, kept out of the default
# workspace members so that plain cargo never needs Python), builds the command line, the C
# library and the extension (into .venv with maturin) and runs the pytest suite in
# python/tests. The Cargo profile is PRESSRIDGE_PROFILE (release by default; scripts/test.sh
# sets `ci`, whose build it has already made). scripts/test.sh calls this when
# python/pyproject.toml exists; run it alone the same way.
set -euo pipefail
cd "$(dirname "$0")/.."
[ -x .venv/bin/python ] || scripts/setup.sh --python
export VIRTUAL_ENV="$PWD/.venv"
export PATH="$VIRTUAL_ENV/bin:$PATH"
export PYO3_PYTHON="$VIRTUAL_ENV/bin/python"

echo "== cargo clippy -p pressridge-python -- -D warnings"
cargo clippy -p pressridge-python --all-targets -- -D warnings
profile=${PRESSRIDGE_PROFILE:-release}
echo "== cargo build --profile $profile -p pressridge-cli -p pressridge-clib --bin pressridge --lib (the CLI and the C library the tests compare against)"
cargo build --profile "$profile" -p pressridge-cli -p pressridge-clib --bin pressridge --lib
echo "== maturin develop --profile $profile (python/ into .venv)"
(cd python && maturin develop --profile "$profile" --quiet)

echo "== pytest python/tests"
export PRESSRIDGE_BIN="$PWD/target/$profile/pressridge"
export PRESSRIDGE_LIB="$PWD/target/$profile/libpressridge.so"
set +e
python -m pytest python/tests -q -p no:cacheprovider "$@"
rc=$?
set -e
if [ "$rc" -eq 5 ]; then
  echo "test-python: pytest collected no tests; that is a failure here" >&2
  exit 1
fi
exit "$rc"
