//! Rafting instead of ridging: a per-run detector (issue 14).
//!
//! Hopkins (1994) pushes a lead sheet against a thick floe to grow a ridge. A sheet can
//! instead *raft*: slide intact over (or under) the floe instead of breaking against it. One
//! run of our first table did (h = 0.40 m: its sheet lay on the whole 20-m floe, and its
//! W/ΔPE came out a third above its siblings'), so a table mixes two processes unless the
//! rafted runs are found and counted.
//!
//! The diagnostic is [`crate::simulation::Summary::sheet_overrun_max`]: the largest
//! distance, over every step, by which the leading edge of the *intact* sheet passed the
//! floe's nose ([`crate::dem::World::sheet_overrun`]). A sheet that breaks against the floe
//! keeps it within a block or so of zero: the tip block may ride onto the nose before it
//! breaks off. A rafting sheet drives it up by the length it overrides. A run **rafted**
//! when that distance exceeds [`RAFTING_REACH`]; runs recorded before the diagnostic existed
//! are **unknown**, never counted as ridged.

use crate::record::RunRecord;
use crate::table::ensemble::{Stat, group_by_point};

/// The overrun beyond which a run counts as rafted (m). 2 m is several block widths
/// (0.20–0.30 m in the paper's sets) past the nose: more than a tip block riding up before
/// it breaks, and a tenth of the paper's 20-m floe. The paper gives no criterion; this one
/// is a definition, reported with every count and adjustable (`tabulate --rafting-reach`).
pub const RAFTING_REACH: f64 = 2.0;

/// What a run did at the floe.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Outcome {
    /// The intact sheet never passed the nose by more than the reach.
    Ridged,
    /// It did, by this much (m).
    Rafted(f64),
    /// The record predates the diagnostic, or the scene has no sheet or no floe.
    Unknown,
}

/// Classifies one run with rafting reach `reach` (m).
pub fn outcome(r: &RunRecord, reach: f64) -> Outcome {
    match r.summary.sheet_overrun_max {
        Some(x) if x > reach => Outcome::Rafted(x),
        Some(_) => Outcome::Ridged,
        None => Outcome::Unknown,
    }
}

/// Rafting at one grid point of a campaign.
#[derive(Clone, Debug, PartialEq)]
pub struct PointRafting {
    /// The grid point's label ([`group_by_point`]).
    pub label: String,
    /// Runs with a known outcome.
    pub known: usize,
    /// Rafted runs: (run id, overrun (m), final W/ΔPE).
    pub rafted: Vec<(String, f64, f64)>,
    /// Largest overrun of the runs that ridged, over the runs (m).
    pub ridged_overrun: Stat,
    /// Final W/ΔPE of the runs that ridged (dimensionless).
    pub ridged_ratio: Stat,
}

/// Rafting per grid point of `records` with reach `reach` (m).
pub fn by_point(records: &[RunRecord], reach: f64) -> Vec<PointRafting> {
    group_by_point(records)
        .into_iter()
        .map(|(label, rs)| {
            let mut p = PointRafting {
                label,
                known: 0,
                rafted: Vec::new(),
                ridged_overrun: Stat::of(&[]),
                ridged_ratio: Stat::of(&[]),
            };
            let (mut over, mut ratio) = (Vec::new(), Vec::new());
            for r in rs {
                match outcome(r, reach) {
                    Outcome::Rafted(x) => {
                        p.known += 1;
                        p.rafted.push((r.id.clone(), x, r.summary.ratio_work_to_pe));
                    }
                    Outcome::Ridged => {
                        p.known += 1;
                        over.extend(r.summary.sheet_overrun_max);
                        ratio.push(r.summary.ratio_work_to_pe);
                    }
                    Outcome::Unknown => {}
                }
            }
            p.ridged_overrun = Stat::of(&over);
            p.ridged_ratio = Stat::of(&ratio);
            p
        })
        .collect()
}
