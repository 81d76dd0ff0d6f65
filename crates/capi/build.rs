//! Generates the C header of the C ABI (this crate's `src/`) with cbindgen.
//!
//! The header is written to `$OUT_DIR/pressridge.h` on every build that changes `src/`.
//! The committed copy `include/pressridge.h` (at the top of the repository) is only rewritten
//! when the environment variable `PRESSRIDGE_WRITE_HEADER=1` is set (`make -C fortran-bridge header`), so that CI never
//! overwrites it silently: `tests/header.rs` compares the two and fails when the committed
//! header is out of date.

use std::path::PathBuf;

fn main() {
    println!("cargo:rerun-if-changed=src");
    println!("cargo:rerun-if-changed=cbindgen.toml");
    println!("cargo:rerun-if-changed=build.rs");
    println!("cargo:rerun-if-env-changed=PRESSRIDGE_WRITE_HEADER");
    let dir = PathBuf::from(std::env::var("CARGO_MANIFEST_DIR").expect("set by cargo"));
    let out = PathBuf::from(std::env::var("OUT_DIR").expect("set by cargo")).join("pressridge.h");
    let config = match cbindgen::Config::from_file(dir.join("cbindgen.toml")) {
        Ok(c) => c,
        Err(e) => {
            println!("cargo:warning=cbindgen.toml: {e}");
            return;
        }
    };
    // Only the C ABI is parsed: its root `src/lib.rs`, from which cbindgen follows the
    // `mod` declarations into the submodules (passing those files too would declare every
    // item twice), so that no other item of the crate leaks into the header.
    let builder = cbindgen::Builder::new()
        .with_config(config)
        .with_src(dir.join("src").join("lib.rs"));
    match builder.generate() {
        Ok(bindings) => {
            bindings.write_to_file(&out);
            if std::env::var("PRESSRIDGE_WRITE_HEADER").is_ok_and(|v| v == "1") {
                bindings.write_to_file(dir.join("../../include/pressridge.h"));
            }
        }
        Err(e) => {
            // Leave no stale header behind: tests/header.rs then fails with this cause.
            let _ = std::fs::remove_file(&out);
            println!("cargo:warning=cbindgen could not generate pressridge.h: {e}");
        }
    }
}
