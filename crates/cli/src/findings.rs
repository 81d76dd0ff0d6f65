//! `pressridge findings`: the paper's stated findings tested on the runs of campaign
//! directories (issue 30's statement table, `pressridge_lab::findings`).

use crate::BoxError;
use pressridge::campaign::{read_campaign, read_pooled};
use pressridge::record::RunRecord;
use pressridge::scene::StepScheme;
use pressridge_lab::choices::effects;
use pressridge_lab::findings::{Register, evidence, findings, markdown, records_step};
use std::path::{Path, PathBuf};

#[derive(clap::Args)]
pub struct Args {
    /// A campaign directory, or a directory of campaign directories (each holding a
    /// `campaign.json`); repeatable. Runs are chosen by their scenes, so any campaigns of the
    /// paper's scenes will do; a run two directories share is counted once.
    #[arg(long, default_value = "crates/lab/records/paper4")]
    records: Vec<PathBuf>,
    /// A key of the Figure 5 scene moved for the model whose findings are tested, e.g.
    /// `--set floe.length=20` for the records of the former 20-m floe (repeatable; the
    /// paper's points then move only their friction, modulus or speed from it). The step
    /// (`numerics.time_step_safety` and the `numerics.refine_*` keys) is the one the records
    /// at the Figure 5 point were made with unless set here; records of two steps there are
    /// refused.
    #[arg(long = "set", value_name = "KEY=VALUE", conflicts_with = "choices")]
    set: Vec<String>,
    /// The fewest runs an ensemble may have (the paper's sets have seven).
    #[arg(long, default_value_t = 7)]
    min_seeds: usize,
    /// Instead of the findings, the register of open choices: the effect of each probe
    /// campaign in this directory against its baseline (the campaigns named `baseline*`), at
    /// each friction pair; probe runs of one setting are pooled across campaigns (a probe's
    /// later seeds in a campaign of their own) (docs/choices.md).
    #[arg(long, value_name = "DIR", conflicts_with = "records")]
    choices: Option<PathBuf>,
    /// The register of open choices whose probes are the evidence under the table: for each
    /// statement the model disagrees with, the closest any choice comes (default
    /// `crates/lab/records/choices40` where it exists; left out when the register is not of the model
    /// tested, e.g. with `--set`).
    #[arg(long, value_name = "DIR", conflicts_with = "choices")]
    register: Option<PathBuf>,
    /// Write the table here (Markdown) instead of to standard output.
    #[arg(long)]
    out: Option<PathBuf>,
}

/// The campaign directories at or directly below `dir`.
pub(crate) fn campaigns(dir: &Path) -> Result<Vec<PathBuf>, BoxError> {
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

/// The register of open choices from the probe campaigns under `dir`: the baseline is every
/// campaign whose name starts with `baseline` (e.g. `baseline-more` with later seeds), the
/// probes all others.
fn register(dir: &Path) -> Result<String, BoxError> {
    let (base, probes) = register_records(dir)?;
    Ok(effects(&base, &probes))
}

/// The register's records under `dir`: the baseline's runs and each probe campaign's, by
/// name ([`register`]).
type RegisterRecords = (Vec<RunRecord>, Vec<(String, Vec<RunRecord>)>);

fn register_records(dir: &Path) -> Result<RegisterRecords, BoxError> {
    let (mut base, mut probes) = (Vec::new(), Vec::new());
    for c in campaigns(dir)? {
        let name = c
            .file_name()
            .map_or_else(String::new, |n| n.to_string_lossy().into_owned());
        let records = read_campaign(&c, true)?.records;
        if name.starts_with("baseline") {
            base.extend(records);
        } else {
            probes.push((name, records));
        }
    }
    Ok((base, probes))
}

/// The runs of the campaign directories at or directly below each of `records` (`--records`),
/// a run two directories share counted once ([`read_pooled`]), and the directories read.
pub(crate) fn pooled_records(
    records: &[PathBuf],
) -> Result<(Vec<RunRecord>, Vec<String>), BoxError> {
    let mut dirs = Vec::new();
    for d in records {
        dirs.extend(campaigns(d)?);
    }
    let runs = read_pooled(&dirs)?;
    Ok((runs, dirs.iter().map(|c| c.display().to_string()).collect()))
}

pub(crate) fn write(text: &str, out: Option<PathBuf>) -> Result<(), BoxError> {
    match out {
        // Through a temporary file and a rename: an interrupted write leaves the old file.
        Some(p) => pressridge::io::write_atomic(&p, text.as_bytes())
            .map_err(|e| format!("--out {}: {e}", p.display()))?,
        None => print!("{text}"),
    }
    Ok(())
}

pub fn run(a: Args) -> Result<(), BoxError> {
    if let Some(dir) = &a.choices {
        return write(&register(dir)?, a.out);
    }
    let (records, dirs) = pooled_records(&a.records)?;
    let mut base =
        pressridge::scene::Scene::load(None, &a.set).map_err(|e| format!("--set: {e}"))?;
    // The records' own step, unless --set names one (records_step).
    let mut step = String::new();
    let chosen = a.set.iter().any(|s| {
        pressridge::scene::split_override(s).is_some_and(|(k, _)| {
            StepScheme::KEYS
                .iter()
                .any(|n| k.strip_prefix("numerics.") == Some(n))
        })
    });
    let inferred = if chosen {
        None
    } else {
        records_step(&records, &base).map_err(|e| format!("findings: {e}"))?
    };
    if let Some(v) = inferred
        && v != base.numerics.step_scheme()
    {
        base.numerics.set_step_scheme(v);
        step = format!(
            " Read at the step the records were made with, {v} (`numerics.time_step_safety` \
             and `numerics.refine_*`; the default is now {}).",
            pressridge::scene::NumericsSection::default().step_scheme()
        );
    }
    let rows = findings(&records, a.min_seeds, &base)?;
    let model = if a.set.is_empty() {
        step
    } else {
        format!(
            " The model: the Figure 5 scene with {}.{step}",
            a.set.join(", ")
        )
    };
    let mut text = format!(
        "{}\nFrom {} runs of: {}.{model}\n",
        markdown(&rows),
        records.len(),
        dirs.join(", ")
    );
    let dir = a.register.clone().or_else(|| {
        let d = PathBuf::from("crates/lab/records/choices40");
        d.is_dir().then_some(d)
    });
    if let Some(dir) = dir {
        let (baseline, probes) = register_records(&dir).map_err(|e| format!("--register: {e}"))?;
        let reg = Register {
            baseline: &baseline,
            probes: &probes,
        };
        if let Some(s) = evidence(&rows, &records, &base, &reg, &dir.display().to_string()) {
            text.push_str(&s);
        }
    }
    write(&text, a.out)
}
