//! The committed C header `include/pressridge.h` must be what cbindgen generates from
//! this crate's `src/` now (build.rs writes it to `$OUT_DIR`). Regenerate with
//! `make -C fortran-bridge header` (or `PRESSRIDGE_WRITE_HEADER=1 cargo build -p pressridge-capi`).

#[test]
fn committed_header_is_up_to_date() {
    let generated = std::path::Path::new(env!("OUT_DIR")).join("pressridge.h");
    let committed =
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../include/pressridge.h");
    let generated = std::fs::read_to_string(&generated).unwrap_or_else(|e| {
        panic!(
            "{}: {e}: cbindgen did not generate the header (see the build script's warnings)",
            generated.display()
        )
    });
    let committed = std::fs::read_to_string(&committed)
        .unwrap_or_else(|e| panic!("{}: {e}", committed.display()));
    if generated != committed {
        let line = generated
            .lines()
            .zip(committed.lines())
            .position(|(a, b)| a != b)
            .map_or_else(
                || generated.lines().count().min(committed.lines().count()) + 1,
                |i| i + 1,
            );
        panic!(
            "include/pressridge.h is out of date with crates/capi/src/ (first difference at line \
             {line}); regenerate it with `make -C fortran-bridge header` and commit it"
        );
    }
}

/// Every function, struct and constant is declared once (cbindgen parsing a module twice
/// repeats the whole API: legal C, but a header no one should ship).
#[test]
fn committed_header_declares_each_item_once() {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../include/pressridge.h");
    let text = std::fs::read_to_string(&path).unwrap();
    let mut seen = std::collections::HashSet::new();
    let mut count = 0;
    for line in text.lines() {
        let decl = line.starts_with("int32_t pressridge_")
            || line.starts_with("typedef struct")
            || line.starts_with("#define PRESSRIDGE_");
        if decl {
            count += 1;
            assert!(seen.insert(line.to_string()), "declared twice: {line}");
        }
    }
    assert!(
        count > 20,
        "only {count} declarations found: the header looks empty"
    );
}
