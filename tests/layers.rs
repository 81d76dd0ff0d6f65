//! The workspace's layers (`docs/architecture.md`): every `crate::` path in a top-level module
//! names a module of a lower layer, so that no import points up and no two modules import
//! each other. The layers run across the crates: the column physics (`crates/column`,
//! re-exported as `crate::itd`) at the bottom, then the simulator's modules (`crates/sim`,
//! `pressridge-sim`, re-exported by `pressridge` under their own names), then the root
//! crate's (`src/`: tables, files, figures, campaigns), and the faces above it all: the C ABI
//! (`crates/capi`) and the command line (`crates/cli`, `pressridge-cli`, the binary
//! `pressridge`). Within a crate the layers are checked from the sources as text (comments
//! left out), so a new upward import fails here, naming the file; between crates the
//! manifests hold them: the column crate names no crate of the workspace, the simulator's
//! only the column crate (checked here too), so neither can import anything above it; the
//! command line names only the library's crates and the lab, no manifest names it, and the
//! lab (`crates/lab`, `pressridge-lab`: findings, the choices register, the investigation
//! programs) is named by the command line alone.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

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

/// The modules of `LAYERS` that are the simulator's crate (`crates/sim/src`); the rest but
/// `itd` are the root crate's (`src/`).
const SIM: &[&str] = &[
    "limits",
    "eta",
    "energy",
    "dem",
    "scene",
    "observe",
    "simulation",
    "record",
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

/// The root of the repository (this file's package).
fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// `dir` and every `.rs` file under it.
fn files_of(dir: PathBuf) -> (PathBuf, Vec<PathBuf>) {
    let mut files = Vec::new();
    sources(&dir, &mut files);
    (dir, files)
}

/// `src/` and every `.rs` file under it.
fn src_files() -> (PathBuf, Vec<PathBuf>) {
    files_of(root().join("src"))
}

/// The workspace's crates apart from the root one: `crates/<name>/src` and its files.
fn crate_files() -> Vec<(PathBuf, Vec<PathBuf>)> {
    let mut out = Vec::new();
    for e in std::fs::read_dir(root().join("crates")).unwrap() {
        out.push(files_of(e.unwrap().path().join("src")));
    }
    out
}

/// The `crate::` paths of `files` (under `src`, shown as `shown/...`) that name no module of a
/// lower layer; the top-level modules seen, each checked to live in the crate `in_sim` says.
fn upward_imports(
    shown: &str,
    (src, files): &(PathBuf, Vec<PathBuf>),
    in_sim: bool,
    bad: &mut BTreeSet<String>,
    seen: &mut BTreeSet<String>,
) {
    for f in files {
        let rel = f.strip_prefix(src).unwrap();
        let first = rel
            .components()
            .next()
            .unwrap()
            .as_os_str()
            .to_string_lossy();
        let top = first.trim_end_matches(".rs").to_string();
        if top == "lib" {
            continue;
        }
        assert!(
            top != "itd",
            "{shown}/itd: the column physics is crates/column"
        );
        let own = layer_of(&top).unwrap_or_else(|| {
            panic!("{shown}/{top}: not in a layer of tests/layers.rs (and docs/architecture.md)")
        });
        assert_eq!(
            SIM.contains(&top.as_str()),
            in_sim,
            "{shown}/{top}: in the wrong crate (tests/layers.rs's SIM lists the simulator's)"
        );
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
                        bad.insert(format!("{shown}/{}: uses crate::{name}", rel.display()));
                    }
                }
            }
        }
    }
}

#[test]
fn no_import_points_up() {
    let mut bad = BTreeSet::new();
    let mut seen = BTreeSet::new();
    let sim = files_of(root().join("crates/sim/src"));
    upward_imports("crates/sim/src", &sim, true, &mut bad, &mut seen);
    upward_imports("src", &src_files(), false, &mut bad, &mut seen);
    assert!(
        bad.is_empty(),
        "imports that point up or sideways:\n{bad:#?}"
    );
    // Every layer's modules exist (the list is not stale); `itd` is the column crate.
    seen.insert("itd".to_string());
    for m in LAYERS.iter().flat_map(|l| l.iter()) {
        assert!(
            seen.contains(*m),
            "{m} is listed but is not a module of src/ or crates/sim/src/"
        );
    }
}

/// The dependencies by name in the sections `sections` (e.g. `[dependencies]`) of the
/// manifest `path` (relative to the repository's root).
fn manifest_dependencies(path: &str, sections: &[&str]) -> Vec<String> {
    let text = std::fs::read_to_string(root().join(path)).unwrap();
    let mut out = Vec::new();
    let mut within = false;
    for line in text.lines().map(str::trim) {
        if line.starts_with('[') {
            within = sections.contains(&line);
        } else if within && !line.is_empty() && !line.starts_with('#') {
            out.push(line.split(['=', ' ', '.']).next().unwrap().to_string());
        }
    }
    out
}

/// The `[dependencies]` of the manifest `crates/<name>/Cargo.toml`, by name.
fn dependencies(name: &str) -> Vec<String> {
    manifest_dependencies(&format!("crates/{name}/Cargo.toml"), &["[dependencies]"])
}

/// The manifests hold the layers between crates: the column crate names no crate of the
/// workspace, the simulator only the column crate, and neither the file formats (NetCDF),
/// arrays (ndarray, which the column crate's batched views alone use), figures or the
/// command line that belong to the crates above.
#[test]
fn the_lower_crates_cannot_import_upwards() {
    let column = dependencies("column");
    assert!(
        column.iter().all(|d| !d.starts_with("pressridge")),
        "crates/column depends on {column:?}"
    );
    let sim = dependencies("sim");
    let above = [
        "pressridge",
        "pressridge-capi",
        "netcdf",
        "ndarray",
        "plotters",
        "clap",
        "indicatif",
        "pressridge-cli",
    ];
    assert!(
        sim.iter().any(|d| d == "pressridge-column")
            && sim.iter().all(|d| !above.contains(&d.as_str())),
        "crates/sim depends on {sim:?}"
    );
}

/// The command line (`crates/cli`) is the top of the workspace: its manifest names, of the
/// workspace's crates, only the library `pressridge`, the simulator, the column crate, the
/// lab (for `pressridge findings`) and the builds' feature pins (`crates/pins`, no code), and
/// no manifest names it (as a dependency of any kind). The argument parser and the progress
/// bars are its own: the library's manifest does not name them, so no crate that depends on
/// the library builds them.
#[test]
fn the_command_line_is_the_top_and_its_dependencies_are_its_own() {
    let all = [
        "[dependencies]",
        "[dev-dependencies]",
        "[build-dependencies]",
    ];
    let cli = manifest_dependencies("crates/cli/Cargo.toml", &all);
    let library = [
        "pressridge",
        "pressridge-sim",
        "pressridge-column",
        "pressridge-lab",
        "pressridge-pins",
    ];
    assert!(
        cli.iter()
            .filter(|d| d.starts_with("pressridge"))
            .all(|d| library.contains(&d.as_str())),
        "crates/cli depends on {cli:?}"
    );
    let mut manifests = vec!["Cargo.toml".to_string(), "python/Cargo.toml".to_string()];
    for e in std::fs::read_dir(root().join("crates")).unwrap() {
        let name = e.unwrap().file_name().to_string_lossy().into_owned();
        manifests.push(format!("crates/{name}/Cargo.toml"));
    }
    for m in &manifests {
        let deps = manifest_dependencies(m, &all);
        assert!(
            !deps.iter().any(|d| d == "pressridge-cli"),
            "{m} depends on the command line"
        );
        // The lab reads the products; of the products only the command line reads it.
        if m != "crates/cli/Cargo.toml" {
            assert!(
                !deps.iter().any(|d| d == "pressridge-lab"),
                "{m} depends on the lab"
            );
        }
    }
    let root_deps = manifest_dependencies("Cargo.toml", &["[dependencies]"]);
    // The libraries a host depends on carry none of the workspace builds' feature pins.
    for m in [
        "Cargo.toml",
        "crates/sim/Cargo.toml",
        "crates/column/Cargo.toml",
    ] {
        let deps = manifest_dependencies(m, &all);
        assert!(
            !deps.iter().any(|d| d == "pressridge-pins"),
            "{m} names the build pins"
        );
    }
    assert!(
        root_deps
            .iter()
            .all(|d| !["clap", "indicatif"].contains(&d.as_str())),
        "the library depends on the command line's {root_deps:?}"
    );
}

/// A module per concern, none long: no source file under `src/` or `crates/*/src/` (the
/// command line's `crates/cli/src/` too) is over 600 lines.
#[test]
fn no_source_file_is_over_600_lines() {
    let root = root();
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

/// One public path per name within a crate: the simulator's modules are private behind their
/// `pub use` front (`crates/sim/src/dem/mod.rs`), the column crate's behind its `lib.rs` (its
/// entry points at the root, the rest in its `details`; only its `limits` and `interp` are
/// modules of their own), the lab's three modules (`findings`, `choices`, `equivalence`), the C ABI's functions each in the one module of its topic (C
/// sees them flat), and no module re-exports another top-level module's public items
/// (`pub use crate::…`), which would give them a second path. (The root crate's re-exports of
/// the simulator's and the column crate's modules are the one path of each there.)
/// `scripts/public-items.sh` lists any second path rustdoc sees.
#[test]
fn one_public_path_per_name() {
    let (src, files) = src_files();
    let mut bad = Vec::new();
    for f in &files {
        let rel = f.strip_prefix(&src).unwrap().display().to_string();
        let text = std::fs::read_to_string(f).unwrap();
        for line in text.lines().map(str::trim_start) {
            if line.starts_with("pub use crate::") {
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
                    Some(c) if c == "sim" => SIM,
                    Some(c) if c == "capi" => {
                        &["itd", "mu_rdg_table", "ridge_step", "scene", "tables"]
                    }
                    Some(c) if c == "lab" => &["choices", "equivalence", "findings"],
                    _ => &[],
                };
                let is_column = src.parent().and_then(|c| c.file_name()) == Some("column".as_ref());
                // The column crate's second tier: `details` re-exports names of its private
                // modules (their one public path), never of `interp` or `limits`.
                let second_tier = is_column
                    && rel == "lib.rs"
                    && (line.starts_with("pub mod details {")
                        || line.strip_prefix("pub use crate::").is_some_and(|rest| {
                            !modules.iter().any(|m| rest.starts_with(&format!("{m}::")))
                        }));
                let allowed = second_tier
                    || rel == "lib.rs"
                        && modules
                            .iter()
                            .any(|m| line.starts_with(&format!("pub mod {m};")));
                if !allowed && (line.starts_with("pub mod ") || line.starts_with("pub use crate::"))
                {
                    bad.push(format!("{}: {line}", f.display()));
                }
            }
        }
    }
    assert!(bad.is_empty(), "a second public path: {bad:#?}");
}
