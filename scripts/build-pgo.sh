#!/usr/bin/env bash
# A profile-guided build of the simulator for long campaigns (docs/performance.md, "Profile-
# guided build"): same source, same results bit for bit, ~9 % fewer instructions per step.
#
#   scripts/build-pgo.sh            # -> target/pgo/release/pressridge
#   PRESSRIDGE_BIN=target/pgo/release/pressridge scripts/paper-campaign.sh
#
# 1. builds an instrumented binary (target/pgo-gen), 2. trains it on the default scene
# (the paper's Figure 5 run for TRAIN_SECONDS of simulated time, default 200 s, and a thin
# and a thick sheet for 40 s each), 3. merges the profile with the toolchain's own
# llvm-profdata (rustup component llvm-tools, added when missing), 4. builds
# target/pgo/release/pressridge with it, 5. refuses the result unless a 20-s run of the
# default scene gives the same state.json and series.csv as the plain release build: the
# optimiser may reorder code, never floating-point arithmetic.
# Costs two release builds of the dependencies (about 20 min on 2 cores). The merged profile
# stays in target/pgo/pgo.profdata: other targets build with it by the same RUSTFLAGS, e.g.
#   RUSTFLAGS=-Cprofile-use=$PWD/target/pgo/pgo.profdata cargo build --release \
#     --target-dir target/pgo --example step_profile
set -euo pipefail
cd "$(dirname "$0")/.."
train=${TRAIN_SECONDS:-200}
host=$(rustc -vV | sed -n 's/^host: //p')
profdata="$(rustc --print sysroot)/lib/rustlib/$host/bin/llvm-profdata"
if [ ! -x "$profdata" ]; then
  command -v rustup > /dev/null || { echo "build-pgo: needs llvm-profdata of rustc's LLVM (rustup component llvm-tools)" >&2; exit 1; }
  rustup component add llvm-tools >&2
fi
data=$PWD/target/pgo-data
rm -rf "$data"
echo "build-pgo: instrumented build ($(date -u +%T))" >&2
RUSTFLAGS="-Cprofile-generate=$data" cargo build --release --bin pressridge --target-dir target/pgo-gen >&2
# The build scripts of the instrumented build wrote profiles too: keep only the training's.
rm -rf "$data"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
echo "build-pgo: training ($(date -u +%T))" >&2
gen=target/pgo-gen/release/pressridge
"$gen" simulate --no-figures -q --set duration="$train" --out "$tmp/t0"
"$gen" simulate --no-figures -q --set duration=40 --set sheet.thickness=0.10 --set sheet.block_width=0.10 --out "$tmp/t1"
"$gen" simulate --no-figures -q --set duration=40 --set sheet.thickness=0.45 --set sheet.block_width=0.30 --out "$tmp/t2"
mkdir -p target/pgo
"$profdata" merge -o target/pgo/pgo.profdata "$data"
rm -rf "$data"
echo "build-pgo: optimised build ($(date -u +%T))" >&2
RUSTFLAGS="-Cprofile-use=$PWD/target/pgo/pgo.profdata" cargo build --release --bin pressridge --target-dir target/pgo >&2
echo "build-pgo: checking results against the plain build ($(date -u +%T))" >&2
cargo build --release --bin pressridge >&2
for b in release pgo; do
  bin=target/release/pressridge
  [ "$b" = pgo ] && bin=target/pgo/release/pressridge
  "$bin" simulate --no-figures -q --set duration=20 --out "$tmp/check-$b"
done
for f in state.json series.csv; do
  cmp -s "$tmp/check-release/$f" "$tmp/check-pgo/$f" || {
    echo "build-pgo: $f differs from the plain build's: profile-guided binary refused" >&2
    rm -f target/pgo/release/pressridge
    exit 1
  }
done
echo "build-pgo: target/pgo/release/pressridge, bit-identical to the plain build ($(date -u +%T))"
