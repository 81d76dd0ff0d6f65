#!/usr/bin/env bash
# Undefined-behaviour checks of the library's unsafe code (issue 32, docs/failure.md).
#
#   scripts/check-ub.sh [miri]   Miri runs the unit and C-ABI tests that reach unsafe code
#   scripts/check-ub.sh asan     the C and Fortran tests built with -fsanitize=address,undefined
#                                against the static library built with Rust's AddressSanitizer
#   scripts/check-ub.sh tsan     the thread tests of crates/capi/tests/abi.rs and the C test's 8 threads
#                                under ThreadSanitizer (installs clang-16 for the C test)
#   scripts/check-ub.sh fuzz     each libFuzzer target of fuzz/ for FUZZ_SECONDS (default 30),
#                                FUZZ_JOBS (default 2) at a time, FUZZ_TARGETS (default all);
#                                the stable toolchain suffices
#
# Installs what it needs: the nightly toolchain's miri and rust-src components (rustup).
# Miri interprets the program and reports any undefined behaviour it executes: out-of-bounds
# or misaligned reads, use after free, invalid values, data races, leaks. It cannot run calls
# into C libraries (NetCDF) or the AVX2 intrinsics' runtime detection; under Miri the feature
# checks report no AVX2, so the portable lanes, which compute the same bits, run instead.
# What runs and what is left out, with the reason: docs/failure.md, "Undefined behaviour: what the tools check".
set -euo pipefail
cd "$(dirname "$0")/.."
stage=${1:-miri}

ensure_nightly() {
  local have
  have=$(rustup +nightly component list --installed 2>/dev/null || true)
  for c in "$@"; do
    grep -q "^$c" <<<"$have" || rustup component add --toolchain nightly "$c"
  done
}

case "$stage" in
  miri)
    ensure_nightly miri rust-src
    cargo +nightly miri setup
    # Miri's default checks (Stacked Borrows included); isolation stays on (no files, no
    # clock). Deterministic floats: Miri otherwise perturbs exp, powf and the like by an ulp at
    # random on each call, and the tests compare paths bit for bit.
    export MIRIFLAGS="-Zmiri-deterministic-floats ${MIRIFLAGS:-}"
    echo "== miri: unit tests of the modules with unsafe code ($SECONDS s)"
    # the C ABI (the options cache, the C layouts, the error protocol), the strength routines and
    # the joint lanes (their portable twins under Miri); the strength routines are the column
    # crate's (crates/column). Its vexp is left out: its only unsafe code is the AVX2+FMA
    # path, which Miri cannot run, and its portable path is f64::exp. The batched strength's
    # lanes and unchecked gather run in crates/capi/tests/abi.rs below.
    cargo +nightly miri test -p pressridge-capi --lib
    cargo +nightly miri test -p pressridge-sim --lib -- dem::joint::lanes
    cargo +nightly miri test -p pressridge-column --lib -- strength
    echo "== miri: the C ABI called from Rust on in-memory data ($SECONDS s)"
    # Every test of crates/capi/tests/abi.rs (their sample grid is synthetic under Miri) but the two that
    # read and write NetCDF files, 4 threads and a tiny scene run included.
    cargo +nightly miri test -p pressridge-capi --test abi -- \
      --skip cf_tables_load_query_free --skip ridge_tables_load_query_and_give_cf_tables
    cargo +nightly miri test -p pressridge-capi --test ridge_step
    # The μ_rdg table handle (issue 34): built from memory, looked up, freed, refused.
    cargo +nightly miri test -p pressridge-capi --test mu_rdg_table -- \
      --skip tables_from_files_open_look_up_and_name_what_is_missing
    echo "== miri: clean in $SECONDS s"
    ;;
  asan)
    ensure_nightly rust-src
    target=x86_64-unknown-linux-gnu
    # The library and the standard library it links, instrumented (-Zbuild-std: a sanitizer
    # needs std built with it too); its own target folder, so no other build is disturbed.
    echo "== asan: the static library with AddressSanitizer ($SECONDS s)"
    RUSTFLAGS="-Zsanitizer=address" cargo +nightly build -Zbuild-std --target $target \
      -p pressridge-clib --profile ci --target-dir target/asan
    lib=$PWD/target/asan/$target/ci
    # The command line computes the Fortran tests' reference files (not instrumented).
    cargo build --profile ci --bin pressridge
    san="-fsanitize=address,undefined -fno-omit-frame-pointer"
    # Two of gfortran 12's UBSan checks report its own code for absent optional array
    # arguments, which the standard allows and the bridge passes on (docs/failure.md): the
    # null check on an absent CONTIGUOUS array passed to an optional dummy (an eight-line
    # program shows it), and the overflow check on the contiguity test it evaluates from
    # the uninitialised extents of an absent assumed-shape array before it tests presence
    # (-fdump-tree-original of pressridge_ridging.f90). Both are off for the Fortran sources
    # only; a real null or wild access still stops the run under ASan.
    fnull="-fno-sanitize=null,signed-integer-overflow"
    echo "== asan: C and Fortran tests, instrumented, on the static library ($SECONDS s)"
    rm -rf fortran-bridge/build/asan
    make -C fortran-bridge BUILD=build/asan PROFILE=ci CARGO_BUILD=true LIBDIR="$lib" \
      CFLAGS="-O1 -g -std=c11 -Wall -Wextra -Werror $san" \
      FFLAGS="-O1 -g -std=f2008 -Wall -Wno-unused-dummy-argument -Wno-maybe-uninitialized $san $fnull" \
      LDEXTRA="$san" static
    export ASAN_OPTIONS=detect_leaks=1:abort_on_error=0 UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1
    b=fortran-bridge/build/asan
    $b/test_capi_static | tail -n 1
    $b/test_pressridge_static data/sample_itd.nc $b | tail -n 1
    OMP_NUM_THREADS=2 $b/host_loop_static data/sample_itd.nc $b/strength_default.nc $b/ridged.nc | tail -n 1
    $b/example_c_static > /dev/null
    echo "== asan: clean in $SECONDS s"
    ;;
  tsan)
    ensure_nightly rust-src
    target=x86_64-unknown-linux-gnu
    echo "== tsan: the thread tests of crates/capi/tests/abi.rs with ThreadSanitizer ($SECONDS s)"
    # 16 threads on the per-cell entry points with changing options, and 4 threads on the
    # batched ones with their own errors, each checked against one thread's results.
    RUSTFLAGS="-Zsanitizer=thread" TSAN_OPTIONS=halt_on_error=1 \
      cargo +nightly test -Zbuild-std --target $target --profile ci --target-dir target/tsan \
      -p pressridge-capi --test abi -- per_cell_calls_from_16_threads calls_from_many_threads
    echo "== tsan: the C test, 8 threads sharing a C_f table, on the instrumented library ($SECONDS s)"
    # clang 16's runtime: gcc 12's libtsan lacks __tsan_memcpy, which Rust's instrumented
    # code calls (docs/failure.md).
    command -v clang-16 > /dev/null || {
      sudo=""; [ "$(id -u)" = 0 ] || sudo=sudo
      $sudo apt-get install -y -q clang-16 libclang-rt-16-dev > /dev/null
    }
    RUSTFLAGS="-Zsanitizer=thread" cargo +nightly build -Zbuild-std --target $target -p pressridge-clib \
      --profile ci --target-dir target/tsan
    rm -rf fortran-bridge/build/tsan
    make -C fortran-bridge BUILD=build/tsan PROFILE=ci CARGO_BUILD=true CC=clang-16 \
      LIBDIR="$PWD/target/tsan/$target/ci" LDEXTRA="-fsanitize=thread" \
      CFLAGS="-O1 -g -std=c11 -Wall -Wextra -Werror -fsanitize=thread -fno-omit-frame-pointer" \
      build/tsan/test_capi_static
    TSAN_OPTIONS=halt_on_error=1 fortran-bridge/build/tsan/test_capi_static | tail -n 1
    echo "== tsan: clean in $SECONDS s"
    ;;
  fuzz)
    secs=${FUZZ_SECONDS:-30}
    jobs=${FUZZ_JOBS:-2}
    # The libFuzzer targets of fuzz/ (its own workspace), built as cargo-fuzz builds them
    # (AddressSanitizer, coverage counters, debug assertions) but with cargo itself, so that
    # neither cargo-fuzz nor the nightly toolchain is needed: RUSTC_BOOTSTRAP=1 lets the
    # stable compiler take -Zsanitizer (a fresh machine has only the stable toolchain).
    # `cargo +nightly fuzz run TARGET` does the same for long runs.
    target=x86_64-unknown-linux-gnu
    cov="-Cpasses=sancov-module -Cllvm-args=-sanitizer-coverage-level=4"
    cov+=" -Cllvm-args=-sanitizer-coverage-inline-8bit-counters -Cllvm-args=-sanitizer-coverage-pc-table"
    cov+=" -Cllvm-args=-sanitizer-coverage-trace-compares -Cllvm-args=-sanitizer-coverage-stack-depth"
    echo "== fuzz: building the targets ($SECONDS s)"
    RUSTC_BOOTSTRAP=1 RUSTFLAGS="$cov --cfg fuzzing -Zsanitizer=address -Cdebug-assertions" \
      ASAN_OPTIONS=detect_odr_violation=0 \
      cargo build --manifest-path fuzz/Cargo.toml --target $target --profile smoke --bins \
      --target-dir fuzz/target/ub
    bin=fuzz/target/ub/$target/smoke
    # Each target with its seeds (the repository's own files, or inputs made from them);
    # what libFuzzer finds goes to the ignored fuzz/corpus/<target>, a failing input to
    # fuzz/artifacts/<target>. Inputs that once failed (fuzz/findings/<target>) run first.
    run_target() {
      local t=$1; shift
      local seeds=("$@")
      [ -d "fuzz/findings/$t" ] && seeds+=("fuzz/findings/$t")
      mkdir -p "fuzz/corpus/$t" "fuzz/artifacts/$t"
      ASAN_OPTIONS=detect_odr_violation=0 "$bin/$t" "fuzz/corpus/$t" "${seeds[@]}" \
        -max_total_time="$secs" -print_final_stats=1 -artifact_prefix="fuzz/artifacts/$t/" \
        > "fuzz/artifacts/$t.log" 2>&1 || true
      local runs
      runs=$(grep -o "stat::number_of_executed_units: *[0-9]*" "fuzz/artifacts/$t.log" | grep -o "[0-9]*$" || echo 0)
      if [ -n "$(ls -A "fuzz/artifacts/$t" 2>/dev/null)" ] || grep -qE "ERROR: |panicked" "fuzz/artifacts/$t.log"; then
        grep -E "ERROR|panicked|SUMMARY" "fuzz/artifacts/$t.log" | head -5 >&2
        echo "fuzz: $t FAILED: a failing input in fuzz/artifacts/$t (log fuzz/artifacts/$t.log)" >&2
        return 1
      fi
      echo "fuzz: $t: $runs inputs in $secs s, no finding"
    }
    targets=(
      "scene_toml data/scenes"
      "strength_cell fuzz/seeds/strength_cell"
      "strength_grid fuzz/seeds/strength_grid"
      "ridge_cell fuzz/seeds/ridge_cell"
      "itd_netcdf fuzz/seeds/itd_netcdf"
      "cf_table fuzz/seeds/cf_table"
    )
    echo "== fuzz: ${#targets[@]} targets for $secs s each, $jobs at a time ($SECONDS s)"
    fail=0 pids=()
    for ts in "${targets[@]}"; do
      # FUZZ_TARGETS="a b" runs only those.
      [ -z "${FUZZ_TARGETS:-}" ] || [[ " $FUZZ_TARGETS " == *" ${ts%% *} "* ]] || continue
      # shellcheck disable=SC2086
      run_target $ts & pids+=($!)
      if [ "${#pids[@]}" -ge "$jobs" ]; then
        wait "${pids[0]}" || fail=1
        pids=("${pids[@]:1}")
      fi
    done
    for p in "${pids[@]}"; do wait "$p" || fail=1; done
    [ "$fail" = 0 ] || exit 1
    echo "== fuzz: clean in $SECONDS s"
    ;;
  *)
    echo "check-ub.sh: unknown stage '$stage' (miri, asan, tsan, fuzz)" >&2
    exit 2
    ;;
esac
