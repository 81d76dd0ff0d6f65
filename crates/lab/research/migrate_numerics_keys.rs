//! One-off migration of committed run records: the numerics options that a scene's
//! `[experimental]` section held from 2026-11-28 move to `[numerics]` (the incubation time
//! to `[joint]`), as the scene format now reads them.
//!
//! For every `run.json` under the directories given: the lines of the scene's
//! `experimental` object move, as text, to the end of `numerics` (or, for
//! `incubation_time`, of `joint`); the record so moved is read as today's [`RunRecord`] and
//! its scene digest is replaced by today's digest of its scene. Every other byte is as the
//! run wrote it. Of the records without the section it counts those whose stored digest
//! today's code reproduces, which says what a recomputed digest is worth. `campaign.json`'s
//! `set` strings move the same keys.
//!
//! ```sh
//! cargo run --release --example migrate_numerics_keys -- crates/lab/records
//! ```
use pressridge::campaign::scene_digest;
use pressridge::record::RunRecord;
use std::path::{Path, PathBuf};

fn files(dir: &Path, name: &str, out: &mut Vec<PathBuf>) {
    let mut entries: Vec<_> = std::fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|e| e.unwrap().path())
        .collect();
    entries.sort();
    for p in entries {
        if p.is_dir() {
            files(&p, name, out);
        } else if p.file_name().is_some_and(|f| f == name) {
            out.push(p);
        }
    }
}

/// Where a former `experimental.<key>` lives now.
fn section_of(key: &str) -> &'static str {
    if key == "incubation_time" {
        "joint"
    } else {
        "numerics"
    }
}

/// What became of one record.
#[derive(PartialEq)]
enum Outcome {
    Migrated,
    /// Without the section: its stored scene digest is today's digest of its scene.
    Same,
    /// Without the section: its stored digest is not today's (a former scene format).
    Former,
}

/// The line range `[start, end)` of the object `"name": {` at `indent` spaces in `lines`,
/// its closing line `end - 1`.
fn object(lines: &[String], name: &str, indent: usize) -> Option<(usize, usize)> {
    let pad = " ".repeat(indent);
    let open = format!("{pad}\"{name}\": {{");
    let start = lines.iter().position(|l| *l == open)?;
    let end = start
        + lines[start..]
            .iter()
            .position(|l| l.starts_with(&format!("{pad}}}")))?;
    Some((start, end + 1))
}

/// Moves the scene's `experimental` entries, as text, to the end of `numerics` (or
/// `joint`), dropping the empty section and the comma before it; every other line is kept
/// byte for byte.
fn move_entries(text: &str) -> Option<String> {
    let mut lines: Vec<String> = text.split('\n').map(String::from).collect();
    let (s, e) = object(&lines, "experimental", 4)?;
    let entries: Vec<String> = lines[s + 1..e - 1]
        .iter()
        .map(|l| l.trim_end_matches(',').to_string())
        .collect();
    // The section was the scene's last: the line before it loses its comma.
    assert!(
        lines[e - 1] == "    }",
        "experimental is the scene's last object"
    );
    lines.drain(s..e);
    let before = lines[s - 1].strip_suffix(',').expect("a comma").to_string();
    lines[s - 1] = before;
    for entry in entries {
        let key = entry.trim().split('"').nth(1).unwrap().to_string();
        let (_, close) = object(&lines, section_of(&key), 4).expect("the section");
        let last = close - 2;
        lines[last].push(',');
        lines.insert(close - 1, entry);
    }
    Some(lines.join("\n"))
}

fn migrate_record(path: &Path) -> Outcome {
    let text = std::fs::read_to_string(path).unwrap();
    let Some(moved) = move_entries(&text) else {
        let r: Result<RunRecord, _> = serde_json::from_str(&text);
        return match r
            .ok()
            .and_then(|r| Some(r.digest.clone()?.scene == scene_digest(&r.id, r.seed, &r.scene)))
        {
            Some(true) => Outcome::Same,
            _ => Outcome::Former,
        };
    };
    let r: RunRecord = serde_json::from_str(&moved).unwrap();
    let old = r.digest.clone().expect("a digest").scene;
    let new = scene_digest(&r.id, r.seed, &r.scene);
    assert_eq!(moved.matches(&old).count(), 1);
    std::fs::write(path, moved.replace(&old, &new)).unwrap();
    Outcome::Migrated
}

fn migrate_spec(path: &Path) -> bool {
    let text = std::fs::read_to_string(path).unwrap();
    let new = text
        .replace(
            "\"experimental.incubation_time=",
            "\"joint.incubation_time=",
        )
        .replace("\"experimental.", "\"numerics.");
    if new != text {
        std::fs::write(path, &new).unwrap();
    }
    new != text
}

fn main() {
    let (mut records, mut specs) = (vec![], vec![]);
    for dir in std::env::args().skip(1) {
        files(Path::new(&dir), "run.json", &mut records);
        files(Path::new(&dir), "campaign.json", &mut specs);
    }
    let outcomes: Vec<Outcome> = records.iter().map(|p| migrate_record(p)).collect();
    let count = |o: Outcome| outcomes.iter().filter(|x| **x == o).count();
    let specs_moved = specs.iter().filter(|p| migrate_spec(p)).count();
    println!(
        "{} of {} run records migrated; of the others {} have the digest today's code gives their scene, {} a former one; {specs_moved} of {} campaign.json",
        count(Outcome::Migrated),
        records.len(),
        count(Outcome::Same),
        count(Outcome::Former),
        specs.len()
    );
}
