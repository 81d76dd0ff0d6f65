//! Reading a campaign's run records back: one directory checked against its plan, or several
//! pooled.

use super::{CampaignError, CampaignSpec, RunRecord, record_path, scene_digest};
use crate::io::state::read_json;
use std::path::{Path, PathBuf};

/// The run records of a campaign directory, checked against its plan ([`read_campaign`]).
#[derive(Clone, Debug)]
pub struct CampaignRecords {
    /// The spec the directory was made with.
    pub spec: CampaignSpec,
    /// The complete, consistent records, in plan order.
    pub records: Vec<RunRecord>,
    /// Number of planned runs.
    pub planned: usize,
    /// Planned runs without a record.
    pub missing: Vec<String>,
    /// Planned runs whose record does not match its run (id, scene, seed or files), with
    /// what is wrong; also a second record of a run already counted.
    pub inconsistent: Vec<(String, String)>,
}

impl CampaignRecords {
    /// Whether every planned run has a consistent record.
    pub(crate) fn is_complete(&self) -> bool {
        self.missing.is_empty() && self.inconsistent.is_empty()
    }

    /// One line naming the missing and inconsistent runs (at most ten of each).
    pub(crate) fn describe_gaps(&self) -> String {
        let list = |v: Vec<String>| {
            let n = v.len();
            let mut s = v.into_iter().take(10).collect::<Vec<_>>().join(", ");
            if n > 10 {
                s.push_str(&format!(", and {} more", n - 10));
            }
            s
        };
        let mut parts = Vec::new();
        if !self.missing.is_empty() {
            parts.push(format!(
                "{} missing ({})",
                self.missing.len(),
                list(self.missing.clone())
            ));
        }
        if !self.inconsistent.is_empty() {
            parts.push(format!(
                "{} inconsistent ({})",
                self.inconsistent.len(),
                list(
                    self.inconsistent
                        .iter()
                        .map(|(id, why)| format!("{id}: {why}"))
                        .collect()
                )
            ));
        }
        format!(
            "{} of {} planned runs complete; {}",
            self.records.len(),
            self.planned,
            parts.join("; ")
        )
    }
}

/// Reads every run record of a campaign directory, in plan order, and checks each against
/// its run (its id, its scene and seed against its digest ([`scene_digest`]), and the files
/// the digest lists, unless the directory is a [`super::RECORDS_ONLY`] archive); a record whose
/// scene and seed another record already has counts once. Missing or inconsistent runs are
/// an error naming them unless `allow_partial`, which returns the complete ones with the
/// gaps listed.
pub fn read_campaign(out: &Path, allow_partial: bool) -> Result<CampaignRecords, CampaignError> {
    let spec: CampaignSpec = read_json(&out.join("campaign.json"))?;
    let ids: Vec<String> = read_json(&out.join("plan.json"))?;
    let mut c = CampaignRecords {
        spec,
        records: Vec::new(),
        planned: ids.len(),
        missing: Vec::new(),
        inconsistent: Vec::new(),
    };
    let mut seen: Vec<String> = Vec::new();
    for id in ids {
        let p = record_path(out, &id);
        if !p.is_file() {
            c.missing.push(id);
            continue;
        }
        let r: RunRecord = match read_json(&p) {
            Ok(r) => r,
            Err(e) => {
                c.inconsistent.push((id, format!("unreadable record: {e}")));
                continue;
            }
        };
        if let Err(why) = super::verify_record(&r, out, &id) {
            c.inconsistent.push((id, why));
            continue;
        }
        // The same scene and seed under another id (e.g. a value given twice on an axis
        // before such specs were refused) is the same run: counted once.
        let key = scene_digest("", r.seed, &r.scene);
        if seen.contains(&key) {
            c.inconsistent.push((
                id,
                "the same scene and seed as a run already counted (counted once)".into(),
            ));
            continue;
        }
        seen.push(key);
        c.records.push(r);
    }
    if c.records.is_empty() || (!allow_partial && !c.is_complete()) {
        let hint = if c.records.is_empty() {
            "nothing to tabulate; run (or resume) the campaign"
        } else {
            "resume the campaign to complete it, or pass --allow-partial (allow_partial) to use the complete runs only"
        };
        return Err(CampaignError::Incomplete(format!(
            "{}: {}: {hint}",
            out.display(),
            c.describe_gaps()
        )));
    }
    Ok(c)
}

/// Reads every run record of a complete campaign directory, in plan order
/// ([`read_campaign`] without `allow_partial`).
pub fn read_records(out: &Path) -> Result<(CampaignSpec, Vec<RunRecord>), CampaignError> {
    let c = read_campaign(out, false)?;
    Ok((c.spec, c.records))
}

/// The runs of the campaign directories `dirs` together, each campaign read with its
/// complete runs ([`read_campaign`] with partial campaigns allowed): a run whose scene and
/// seed an earlier record already has (the same run in two archives) is counted once. What
/// `pressridge findings`, `pressridge redistribution` and their Python faces read.
pub fn read_pooled(dirs: &[PathBuf]) -> Result<Vec<RunRecord>, CampaignError> {
    let mut records: Vec<RunRecord> = Vec::new();
    for d in dirs {
        for r in read_campaign(d, true)?.records {
            if !records
                .iter()
                .any(|o| o.scene == r.scene && o.seed == r.seed)
            {
                records.push(r);
            }
        }
    }
    Ok(records)
}
