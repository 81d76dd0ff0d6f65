#!/usr/bin/env bash
# Every check a clean checkout must pass: formatting, lints, the API docs' links, Rust tests
# (unit, integration, doc), and the Python, Fortran and C suites where present. CI runs exactly this (.ci/run).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh $( [ -f python/pyproject.toml ] && echo --python )

echo "== cargo fmt --check ($SECONDS s)"
cargo fmt --all -- --check
echo "== cargo clippy --all-targets -- -D warnings ($SECONDS s)"
cargo clippy --all-targets -- -D warnings
echo "== cargo doc of the Rust API, warnings denied (broken links) ($SECONDS s)"
# The three Rust libraries and the lab, `pressridge` with its figures (feature `plot`, which its default
# leaves out); the C ABI's crates and the command line (crates/cli) are no Rust API (and the C
# library's lib name, `pressridge`, would overwrite the library's pages).
# The builds' feature pins (crates/pins, no code) join so that the dependencies are checked with
# the features every other build here resolves.
RUSTDOCFLAGS="-D warnings" cargo doc --no-deps --lib -p pressridge -p pressridge-sim -p pressridge-column -p pressridge-lab -p pressridge-pins --features pressridge/plot
echo "== docs/validation.md: its tables are the committed reports' numbers ($SECONDS s)"
python3 scripts/validation-tables.py --check docs/validation.md
# --write remakes the page: a copy with the first table's first row taken out comes back whole.
page_copy=$(mktemp)
awk '/^scripts\/validation-tables.py/ { s = 1 } s && /^\|/ && ++n == 3 { s = 0; next } { print }' \
  docs/validation.md > "$page_copy"
if cmp -s "$page_copy" docs/validation.md; then echo "test.sh: the row was not taken out" >&2; exit 1; fi
python3 scripts/validation-tables.py --write "$page_copy"
cmp "$page_copy" docs/validation.md
rm "$page_copy"
# The friction slopes docs/validation.md quotes use `pressridge findings`' method: on the
# records docs/findings.md reads, they are its d1 rows (W at μ_w = 0.6, W/ΔPE at 0.3).
slopes=$(python3 scripts/friction-slopes.py --thickness 0.3 crates/lab/records/paper4/friction)
for row in "W: -342.7 [-683.5, -1.8]" "W/ΔPE: +3.8 [+1.0, +6.6]"; do
  grep -qF -- "$row" <<< "$slopes" || { echo "test.sh: friction-slopes.py lacks '$row'" >&2; exit 1; }
done
grep -qF -- "-342.7 [-683.5, -1.8]" docs/findings.md
# One build for everything below: the `ci` profile (Cargo.toml) serves the Rust tests, the
# Fortran/C bridge, the command line and the Python extension.
export PRESSRIDGE_PROFILE=ci
echo "== cargo test --profile ci ($SECONDS s)"
cargo test --profile ci --all-targets
cargo test --profile ci --doc

if [ -f fortran-bridge/Makefile ]; then
  echo "== Fortran and C bridge tests ($SECONDS s)"
  make -C fortran-bridge test PROFILE=ci
fi
if [ -f python/pyproject.toml ]; then
  echo "== Python tests ($SECONDS s)"
  scripts/test-python.sh
fi
if [ -f fuzz/Cargo.toml ]; then
  echo "== fuzz smoke: every libFuzzer target for 30 s ($SECONDS s)"
  FUZZ_SECONDS=30 scripts/check-ub.sh fuzz
fi
echo "== all checks passed in $SECONDS s"
