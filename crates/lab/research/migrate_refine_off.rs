//! One-off migration of committed run records for the default step of 2026-12-07: the full
//! stable limit refined around fracture and impacts (`numerics.refine_window`, `refine_load`,
//! `refine_impact` on by default, `DEFAULT_TIME_STEP_SAFETY` = 1). A record made before
//! wrote no key for a refinement it did not use; read today, a missing key is the new
//! default, so each record's scene gets the keys it lacks as `"off"`, which is what it ran.
//!
//! For every `run.json` under the directories given: `"refine_window": "off"` (and
//! `refine_load`, `refine_impact`) for each key its scene's `numerics` lacks, inserted as
//! text at the end of that object; every other byte as the run wrote it. Its scene digest is
//! replaced by today's digest of its scene where the stored one was the digest of the same
//! scene in the former form (the TOML without those keys); a record whose stored digest was
//! already of a former scene format keeps it, and one that today's code cannot read is left
//! as it is (both are counted). `campaign.json`'s `set` gets
//! `numerics.KEY=off` for each key its `set` does not name, so that the spec recorded in an
//! archive makes the scenes of its records.
//!
//! ```sh
//! cargo run --release --example migrate_refine_off -- crates/lab/records
//! ```
use pressridge::campaign::scene_digest;
use pressridge::record::RunRecord;
use std::path::{Path, PathBuf};

/// The keys that a record without them ran switched off.
const KEYS: [&str; 3] = ["refine_window", "refine_load", "refine_impact"];

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

#[derive(PartialEq)]
enum Outcome {
    /// Keys added, the digest renewed.
    Migrated,
    /// Keys added, the stored digest of a former scene format kept.
    Former,
    /// The record names every key already.
    Untouched,
    /// Today's code cannot read the record (a former scene format): left as it is.
    Unreadable,
}

/// Inserts the lacking keys at the end of the scene's `numerics` object (4 spaces in);
/// `None` when it lacks none.
fn insert_keys(text: &str) -> Option<String> {
    let mut lines: Vec<String> = text.split('\n').map(String::from).collect();
    let open = lines
        .iter()
        .position(|l| l == "    \"numerics\": {")
        .expect("a scene's numerics");
    let close = open
        + lines[open..]
            .iter()
            .position(|l| l.starts_with("    }"))
            .expect("its end");
    let present = |k: &str| {
        lines[open..close]
            .iter()
            .any(|l| l.trim_start().starts_with(&format!("\"{k}\":")))
    };
    let missing: Vec<&str> = KEYS.into_iter().filter(|k| !present(k)).collect();
    if missing.is_empty() {
        return None;
    }
    lines[close - 1].push(',');
    let new: Vec<String> = missing
        .iter()
        .map(|k| format!("      \"{k}\": \"off\""))
        .collect();
    let n = new.len();
    for (i, l) in new.into_iter().enumerate() {
        lines.insert(close + i, if i + 1 < n { l + "," } else { l });
    }
    Some(lines.join("\n"))
}

/// The TOML of `scene` as the code before this migration wrote it: without the keys set
/// "off" (it skipped a refinement it did not use).
fn former_toml(toml: &str) -> String {
    toml.lines()
        .filter(|l| !KEYS.iter().any(|k| *l == format!("{k} = \"off\"")))
        .map(|l| format!("{l}\n"))
        .collect()
}

/// SHA-256 of `text` as hex, by the system's `sha256sum` (a one-off program: the crate's
/// own digest is private to it).
fn sha256_hex(text: &str) -> String {
    use std::io::Write;
    let mut child = std::process::Command::new("sha256sum")
        .stdin(std::process::Stdio::piped())
        .stdout(std::process::Stdio::piped())
        .spawn()
        .expect("sha256sum");
    child
        .stdin
        .take()
        .unwrap()
        .write_all(text.as_bytes())
        .unwrap();
    let out = child.wait_with_output().unwrap();
    String::from_utf8(out.stdout).unwrap()[..64].to_string()
}

fn migrate_record(path: &Path) -> Outcome {
    let text = std::fs::read_to_string(path).unwrap();
    let Some(moved) = insert_keys(&text) else {
        return Outcome::Untouched;
    };
    let Ok(r) = serde_json::from_str::<RunRecord>(&moved) else {
        return Outcome::Unreadable;
    };
    let Some(d) = r.digest.clone() else {
        std::fs::write(path, moved).unwrap();
        return Outcome::Former;
    };
    let toml = r.scene.to_toml();
    let former = sha256_hex(&format!("{}\n{}\n{}", r.id, r.seed, former_toml(&toml)));
    if former != d.scene {
        std::fs::write(path, moved).unwrap();
        return Outcome::Former;
    }
    let new = scene_digest(&r.id, r.seed, &r.scene);
    assert_eq!(moved.matches(&d.scene).count(), 1);
    std::fs::write(path, moved.replace(&d.scene, &new)).unwrap();
    Outcome::Migrated
}

fn migrate_spec(path: &Path) -> bool {
    let text = std::fs::read_to_string(path).unwrap();
    let v: serde_json::Value = serde_json::from_str(&text).unwrap();
    let set: Vec<&str> = v["set"]
        .as_array()
        .expect("a spec's set")
        .iter()
        .filter_map(|s| s.as_str())
        .collect();
    let lacking: Vec<String> = KEYS
        .into_iter()
        .filter(|k| !set.iter().any(|s| s.starts_with(&format!("numerics.{k}="))))
        .map(|k| format!("    \"numerics.{k}=off\""))
        .collect();
    if lacking.is_empty() {
        return false;
    }
    // As text, so that every other byte stays: `"set": [],` or a list closed by `  ],`.
    let mut lines: Vec<String> = text.split('\n').map(String::from).collect();
    let open = lines
        .iter()
        .position(|l| l.starts_with("  \"set\": ["))
        .expect("the set's line");
    if lines[open].trim_end_matches(',').ends_with("[]") {
        let comma = if lines[open].ends_with(',') { "," } else { "" };
        lines[open] = "  \"set\": [".into();
        let n = lacking.len();
        for (i, l) in lacking.into_iter().enumerate() {
            lines.insert(open + 1 + i, if i + 1 < n { l + "," } else { l });
        }
        lines.insert(open + 1 + n, format!("  ]{comma}"));
    } else {
        let close = open
            + lines[open..]
                .iter()
                .position(|l| l.starts_with("  ]"))
                .expect("the set's end");
        lines[close - 1].push(',');
        let n = lacking.len();
        for (i, l) in lacking.into_iter().enumerate() {
            lines.insert(close + i, if i + 1 < n { l + "," } else { l });
        }
    }
    let new = lines.join("\n");
    // The same spec with the keys added.
    let back: serde_json::Value = serde_json::from_str(&new).expect("still JSON");
    assert_eq!(back["name"], v["name"]);
    std::fs::write(path, new).unwrap();
    true
}

fn main() {
    let (mut records, mut specs) = (vec![], vec![]);
    for dir in std::env::args().skip(1) {
        files(Path::new(&dir), "run.json", &mut records);
        files(Path::new(&dir), "campaign.json", &mut specs);
    }
    let outcomes: Vec<Outcome> = records.iter().map(|p| migrate_record(p)).collect();
    let count = |o: Outcome| outcomes.iter().filter(|x| **x == o).count();
    let specs_changed = specs.iter().filter(|p| migrate_spec(p)).count();
    println!(
        "{} run records: {} migrated with a renewed digest, {} with their former-format digest kept, {} untouched, {} unreadable today (left); {specs_changed} of {} campaign.json",
        records.len(),
        count(Outcome::Migrated),
        count(Outcome::Former),
        count(Outcome::Untouched),
        count(Outcome::Unreadable),
        specs.len()
    );
}
