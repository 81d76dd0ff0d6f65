//! Campaign directories to a lookup table: the pipeline of `pressridge tabulate` and
//! Python's `pressridge.tabulate`, written once. It reads each campaign's records
//! ([`read_campaign`], refusing an incomplete one unless partial campaigns are allowed),
//! pools them (a run two campaigns share is counted once, by
//! [`crate::table::tabulate::tabulate`]), leaves rafted runs out on request
//! ([`crate::table::rafting`]), tabulates them (the dissipation gate leaves numerically
//! unstable runs out) and gathers the table's provenance. Writing the table,
//! figures and the report, and telling the user, are the faces' business. It sits in the
//! campaign layer, above `table` and `io`, whose pieces it joins.

use crate::campaign::{CampaignError, CampaignSpec, read_campaign};
use crate::io::table_netcdf::Provenance;
use crate::record::RunRecord;
use crate::table::tabulate::{RidgeTable, TabulateError, tabulate_scaled};
use std::path::PathBuf;

/// The choices of a tabulation; `Default` is the command line's.
#[derive(Clone, Debug, PartialEq)]
pub struct TabulateOptions {
    /// Points of the ridged-volume grid. Default 41.
    pub points: usize,
    /// Tabulate the complete runs of an incomplete campaign instead of refusing it.
    /// Default false.
    pub allow_partial: bool,
    /// A run counts as rafted when its intact lead sheet passed the floe's nose by more than
    /// this (m) in a scene of the paper's size, scaled with a scene scaled with the sheet
    /// ([`crate::table::rafting::reach_of`]). Default
    /// [`crate::table::rafting::RAFTING_REACH`].
    pub rafting_reach: f64,
    /// Leave rafted runs out of the table. Default false.
    pub exclude_rafted: bool,
    /// Scene keys scaled with the sheet thickness within a set
    /// ([`crate::table::tabulate::tabulate_scaled`]), e.g. `floe.thickness`. Default none.
    pub scaled_keys: Vec<String>,
}

impl Default for TabulateOptions {
    fn default() -> Self {
        TabulateOptions {
            points: 41,
            allow_partial: false,
            rafting_reach: crate::table::rafting::RAFTING_REACH,
            exclude_rafted: false,
            scaled_keys: Vec::new(),
        }
    }
}

/// An error of [`tabulate_campaigns`].
#[derive(Debug, thiserror::Error)]
pub enum TabulateCampaignsError {
    /// No campaign directory was given.
    #[error("no campaign given")]
    NoCampaign,
    /// The rafting reach is not a length.
    #[error("the rafting reach must be a finite length >= 0 m, not {0}")]
    RaftingReach(f64),
    /// A campaign could not be read, or is incomplete and partial campaigns are not allowed.
    #[error(transparent)]
    Campaign(#[from] CampaignError),
    /// The records could not be tabulated.
    #[error(transparent)]
    Tabulate(#[from] TabulateError),
    /// A campaign spec could not be written as TOML for the provenance.
    #[error("campaign spec: {0}")]
    Spec(String),
}

/// A tabulation and what went into it.
#[derive(Clone, Debug)]
pub struct Tabulated {
    /// The table; its `excluded` lists the runs the dissipation gate left out, then the
    /// rafted runs left out.
    pub table: RidgeTable,
    /// The table's provenance attributes, with the `command` and `date` given.
    pub provenance: Provenance,
    /// The spec of each campaign, in the order given.
    pub specs: Vec<CampaignSpec>,
    /// The records tabulated: every record read, less the rafted ones left out.
    pub records: Vec<RunRecord>,
    /// Every record read, rafted ones included (the rafting statistics count them all).
    pub all_records: Vec<RunRecord>,
    /// The runs the dissipation gate left out: (id, why).
    pub gate_excluded: Vec<(String, String)>,
    /// The rafted runs left out (only with `exclude_rafted`): (id, why).
    pub rafted_out: Vec<(String, String)>,
    /// The incomplete campaigns (only with `allow_partial`): (directory, its gaps).
    pub partial: Vec<(PathBuf, String)>,
}

/// Reads, pools and tabulates the campaign directories `dirs` (see the module
/// documentation); `command` and `date` go into the provenance.
pub fn tabulate_campaigns(
    dirs: &[PathBuf],
    opts: &TabulateOptions,
    command: &str,
    date: &str,
) -> Result<Tabulated, TabulateCampaignsError> {
    if dirs.is_empty() {
        return Err(TabulateCampaignsError::NoCampaign);
    }
    if !(opts.rafting_reach.is_finite() && opts.rafting_reach >= 0.0) {
        return Err(TabulateCampaignsError::RaftingReach(opts.rafting_reach));
    }
    let (mut planned, mut specs, mut records, mut partial) =
        (0, Vec::new(), Vec::new(), Vec::new());
    for dir in dirs {
        let campaign = read_campaign(dir, opts.allow_partial)?;
        if !campaign.is_complete() {
            partial.push((dir.clone(), campaign.describe_gaps()));
        }
        planned += campaign.planned;
        specs.push(campaign.spec);
        records.extend(campaign.records);
    }
    let all_records = records.clone();
    let mut rafted_out: Vec<(String, String)> = Vec::new();
    if opts.exclude_rafted {
        use crate::table::rafting::{Outcome, outcome, reach_of};
        records.retain(|r| match outcome(r, opts.rafting_reach) {
            Outcome::Rafted(over) => {
                rafted_out.push((
                    r.id.clone(),
                    format!(
                        "sheet rafted {over:.1} m past the floe's nose (--exclude-rafted, reach {} m)",
                        reach_of(r, opts.rafting_reach)
                    ),
                ));
                false
            }
            Outcome::Ridged | Outcome::Unknown => true,
        });
    }
    let mut table = tabulate_scaled(&records, opts.points, &opts.scaled_keys)?;
    let gate_excluded = table.excluded.clone();
    table.excluded.extend(rafted_out.iter().cloned());
    let mut spec_text = String::new();
    for s in &specs {
        if !spec_text.is_empty() {
            spec_text.push_str("\n# --- next campaign ---\n");
        }
        spec_text.push_str(
            &toml::to_string(s).map_err(|e| TabulateCampaignsError::Spec(e.to_string()))?,
        );
    }
    let provenance = Provenance {
        campaign_spec: spec_text,
        scene: records
            .first()
            .map(|r| r.scene.to_toml())
            .unwrap_or_default(),
        command: command.into(),
        date: date.into(),
        runs_planned: planned,
        runs_tabulated: records.len() - table.duplicates.len(),
        gaps: partial
            .iter()
            .map(|(d, g)| format!("{}: {g}", d.display()))
            .collect::<Vec<_>>()
            .join("; "),
    };
    Ok(Tabulated {
        table,
        provenance,
        specs,
        records,
        all_records,
        gate_excluded,
        rafted_out,
        partial,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn no_campaign_is_an_error_and_defaults_are_the_command_lines() {
        let o = TabulateOptions::default();
        assert_eq!(
            (o.points, o.allow_partial, o.exclude_rafted),
            (41, false, false)
        );
        assert_eq!(o.rafting_reach, crate::table::rafting::RAFTING_REACH);
        assert!(matches!(
            tabulate_campaigns(&[], &o, "", ""),
            Err(TabulateCampaignsError::NoCampaign)
        ));
    }
}
