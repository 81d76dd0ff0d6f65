//! The library's layers (`docs/architecture.md`): every `crate::` path in a top-level module
//! names a module of a lower layer, so that no import points up and no two modules import
//! each other. The column physics is a crate of its own (`crates/column`, re-exported as
//! `crate::itd`), below every module, and the C ABI is one above it all (`crates/capi`): the
//! manifests keep the first from importing anything of `pressridge` and the second from being
//! imported by it. Read from the sources as text (comments left out), so a new upward import
//! fails here, naming the file.

use std::collections::BTreeSet;
use std::path::Path;

/// Bottom to top; a module may use only modules of the layers before its own.
const LAYERS: &[&[&str]] = &[
    &["itd"],
    &["limits", "eta", "energy"],
    &["dem"],
    &["scene", "observe"],
    &["simulation"],
    &["record"],
    &["table"],
    &["io"],
    &["plot", "campaign"],
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

/// The workspace's crates apart from the root one: `crates/<name>/src` and its files.
fn crate_files() -> Vec<(std::path::PathBuf, Vec<std::path::PathBuf>)> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("crates");
    let mut out = Vec::new();
    for e in std::fs::read_dir(&root).unwrap() {
        let src = e.unwrap().path().join("src");
        let mut files = Vec::new();
        sources(&src, &mut files);
        out.push((src, files));
    }
    out
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
        assert!(top != "itd", "src/itd: the column physics is crates/column");
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
    // Every layer's modules exist (the list is not stale); `itd` is the column crate.
    seen.insert("itd".to_string());
    for m in LAYERS.iter().flat_map(|l| l.iter()) {
        assert!(
            seen.contains(*m),
            "{m} is listed but is not a module of src/"
        );
    }
}

/// A module per concern, none long: no source file under `src/` or `crates/*/src/` is over
/// 600 lines.
#[test]
fn no_source_file_is_over_600_lines() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut all = crate_files();
    all.push(src_files());
    let long: Vec<String> = all
        .iter()
        .flat_map(|(_, files)| files)
        .filter_map(|f| {
            let n = std::fs::read_to_string(f).unwrap().lines().count();
            (n > 600).then(|| format!("{} ({n} lines)", f.strip_prefix(root).unwrap().display()))
        })
        .collect();
    assert!(long.is_empty(), "split these: {long:?}");
}

/// One public path per name: the simulator's modules are private behind their `pub use` front
/// (`src/dem/mod.rs`), the column crate's behind its `lib.rs` (only its `limits` and `interp`
/// are modules of their own), the C ABI's functions each in the one module of its topic (C
/// sees them flat), and no module re-exports another top-level module's public items
/// (`pub use crate::…`), which would give them a second path.
/// `scripts/public-items.sh` lists any second path rustdoc sees.
#[test]
fn one_public_path_per_name() {
    let (src, files) = src_files();
    let mut bad = Vec::new();
    for f in &files {
        let rel = f.strip_prefix(&src).unwrap().display().to_string();
        let text = std::fs::read_to_string(f).unwrap();
        for line in text.lines().map(str::trim_start) {
            let front = rel.starts_with("dem/");
            if line.starts_with("pub use crate::") || (front && line.starts_with("pub mod ")) {
                bad.push(format!("src/{rel}: {line}"));
            }
        }
    }
    for (src, files) in crate_files() {
        for f in &files {
            let rel = f.strip_prefix(&src).unwrap().display().to_string();
            let text = std::fs::read_to_string(f).unwrap();
            for line in text.lines().map(str::trim_start) {
                let modules: &[&str] = match src.parent().and_then(|c| c.file_name()) {
                    Some(c) if c == "column" => &["interp", "limits"],
                    Some(c) if c == "capi" => {
                        &["itd", "mu_rdg_table", "ridge_step", "scene", "tables"]
                    }
                    _ => &[],
                };
                let allowed = rel == "lib.rs"
                    && modules
                        .iter()
                        .any(|m| line.starts_with(&format!("pub mod {m};")));
                if line.starts_with("pub mod ") && !allowed {
                    bad.push(format!("{}: {line}", f.display()));
                }
            }
        }
    }
    assert!(bad.is_empty(), "a second public path: {bad:#?}");
}
