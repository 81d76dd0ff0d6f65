//! The library's layers (`docs/architecture.md`): every `crate::` path in a top-level module
//! names a module of a lower layer, so that no import points up and no two modules import
//! each other. Read from the sources as text (comments left out), so a new upward import
//! fails here, naming the file.

use std::collections::BTreeSet;
use std::path::Path;

/// Bottom to top; a module may use only modules of the layers before its own.
const LAYERS: &[&[&str]] = &[
    &["limits", "interp", "eta", "energy"],
    &["dem", "itd"],
    &["scene", "observe"],
    &["simulation"],
    &["record"],
    &["table"],
    &["io"],
    &["plot", "campaign", "ffi"],
];

fn layer_of(module: &str) -> Option<usize> {
    LAYERS.iter().position(|l| l.contains(&module))
}

/// Every `.rs` file under `dir`.
fn sources(dir: &Path, out: &mut Vec<std::path::PathBuf>) {
    for e in std::fs::read_dir(dir).unwrap() {
        let p = e.unwrap().path();
        if p.is_dir() {
            sources(&p, out);
        } else if p.extension().is_some_and(|x| x == "rs") {
            out.push(p);
        }
    }
}

/// `src/` and every `.rs` file under it.
fn src_files() -> (std::path::PathBuf, Vec<std::path::PathBuf>) {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files = Vec::new();
    sources(&src, &mut files);
    (src, files)
}

#[test]
fn no_import_points_up() {
    let (src, files) = src_files();
    let mut bad = BTreeSet::new();
    let mut seen = BTreeSet::new();
    for f in &files {
        let rel = f.strip_prefix(&src).unwrap();
        let first = rel
            .components()
            .next()
            .unwrap()
            .as_os_str()
            .to_string_lossy();
        let top = first.trim_end_matches(".rs").to_string();
        if top == "lib" || top == "bin" {
            continue;
        }
        let own = layer_of(&top).unwrap_or_else(|| {
            panic!("src/{top}: not in a layer of tests/layers.rs (and docs/architecture.md)")
        });
        seen.insert(top.clone());
        let text = std::fs::read_to_string(f).unwrap();
        for line in text.lines().filter(|l| !l.trim_start().starts_with("//")) {
            for (i, _) in line.match_indices("crate::") {
                let rest = &line[i + "crate::".len()..];
                let name: String = rest
                    .chars()
                    .take_while(|c| c.is_ascii_alphanumeric() || *c == '_')
                    .collect();
                if name == top || name.is_empty() {
                    continue;
                }
                match layer_of(&name) {
                    Some(l) if l < own => {}
                    _ => {
                        bad.insert(format!("src/{}: uses crate::{name}", rel.display()));
                    }
                }
            }
        }
    }
    assert!(
        bad.is_empty(),
        "imports that point up or sideways:\n{bad:#?}"
    );
    // Every layer's modules exist (the list is not stale).
    for m in LAYERS.iter().flat_map(|l| l.iter()) {
        assert!(
            seen.contains(*m),
            "{m} is listed but is not a module of src/"
        );
    }
}

/// A module per concern, none long (issue 33): no source file under `src/` is over 600 lines.
#[test]
fn no_source_file_is_over_600_lines() {
    let (src, files) = src_files();
    let long: Vec<String> = files
        .iter()
        .filter_map(|f| {
            let n = std::fs::read_to_string(f).unwrap().lines().count();
            (n > 600).then(|| format!("{} ({n} lines)", f.strip_prefix(&src).unwrap().display()))
        })
        .collect();
    assert!(long.is_empty(), "split these: {long:?}");
}

/// One public path per name (issue 33): the simulator's and the thickness-distribution
/// physics' modules are private behind their `pub use` fronts (`src/dem/mod.rs`,
/// `src/itd/mod.rs`), and no module re-exports another top-level module's public items
/// (`pub use crate::…`), which would give them a second path. `scripts/public-items.sh`
/// lists any second path rustdoc sees.
#[test]
fn one_public_path_per_name() {
    let (src, files) = src_files();
    let mut bad = Vec::new();
    for f in &files {
        let rel = f.strip_prefix(&src).unwrap().display().to_string();
        let text = std::fs::read_to_string(f).unwrap();
        for line in text.lines().map(str::trim_start) {
            let front = rel.starts_with("dem/") || rel.starts_with("itd/");
            if line.starts_with("pub use crate::") || (front && line.starts_with("pub mod ")) {
                bad.push(format!("src/{rel}: {line}"));
            }
        }
    }
    assert!(bad.is_empty(), "a second public path: {bad:#?}");
}
