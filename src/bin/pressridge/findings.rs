//! `pressridge findings`: the paper's stated findings tested on the runs of campaign
//! directories (issue 30's statement table, `pressridge::table::findings`).

use crate::BoxError;
use pressridge::campaign::{RunRecord, read_campaign};
use pressridge::table::choices::effects;
use pressridge::table::findings::{findings, markdown};
use std::path::{Path, PathBuf};

#[derive(clap::Args)]
pub struct Args {
    /// A campaign directory, or a directory of campaign directories (each holding a
    /// `campaign.json`); repeatable. Runs are chosen by their scenes, so any campaigns of the
    /// paper's scenes will do; a run two directories share is counted once.
    #[arg(long, default_value = "data/paper")]
    records: Vec<PathBuf>,
    /// The fewest runs an ensemble may have (the paper's sets have seven).
    #[arg(long, default_value_t = 7)]
    min_seeds: usize,
    /// Instead of the findings, the register of open choices: the effect of each probe
    /// campaign in this directory (every campaign directory in it but `baseline`) against
    /// its `baseline` campaign, at each friction pair (docs/choices.md).
    #[arg(long, value_name = "DIR", conflicts_with = "records")]
    choices: Option<PathBuf>,
    /// Write the table here (Markdown) instead of to standard output.
    #[arg(long)]
    out: Option<PathBuf>,
}

/// The campaign directories at or directly below `dir`.
fn campaigns(dir: &Path) -> Result<Vec<PathBuf>, BoxError> {
    if dir.join("campaign.json").is_file() {
        return Ok(vec![dir.to_path_buf()]);
    }
    let mut v: Vec<PathBuf> = std::fs::read_dir(dir)
        .map_err(|e| format!("--records {}: {e}", dir.display()))?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.join("campaign.json").is_file())
        .collect();
    if v.is_empty() {
        return Err(format!("--records {}: no campaign directory there", dir.display()).into());
    }
    v.sort();
    Ok(v)
}

/// The register of open choices from the probe campaigns under `dir`.
fn register(dir: &Path) -> Result<String, BoxError> {
    let base = read_campaign(&dir.join("baseline"), true)?.records;
    let mut probes = Vec::new();
    for c in campaigns(dir)? {
        let name = c.file_name().map(|n| n.to_string_lossy().into_owned());
        if let Some(name) = name.filter(|n| n != "baseline") {
            probes.push((name, read_campaign(&c, true)?.records));
        }
    }
    Ok(effects(&base, &probes))
}

fn write(text: &str, out: Option<PathBuf>) -> Result<(), BoxError> {
    match out {
        Some(p) => std::fs::write(&p, text).map_err(|e| format!("--out {}: {e}", p.display()))?,
        None => print!("{text}"),
    }
    Ok(())
}

pub fn run(a: Args) -> Result<(), BoxError> {
    if let Some(dir) = &a.choices {
        return write(&register(dir)?, a.out);
    }
    let mut records: Vec<RunRecord> = Vec::new();
    let mut dirs = Vec::new();
    for d in &a.records {
        for c in campaigns(d)? {
            let got = read_campaign(&c, true)?;
            for r in got.records {
                let dup = records
                    .iter()
                    .any(|o| o.scene == r.scene && o.seed == r.seed);
                if !dup {
                    records.push(r);
                }
            }
            dirs.push(c.display().to_string());
        }
    }
    let rows = findings(&records, a.min_seeds)?;
    let text = format!(
        "{}\nFrom {} runs of: {}.\n",
        markdown(&rows),
        records.len(),
        dirs.join(", ")
    );
    write(&text, a.out)
}
