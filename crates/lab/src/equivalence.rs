//! The step's equivalence test (docs/speed-vs-error.md, "The equivalence test"): a numerical
//! change that does not keep the bits is equivalent to its reference when, with at least
//! [`SEEDS`] seeds in each arm, every judged quantity's shift of the ensemble mean has a 95 %
//! Welch interval across zero and its centre within [`CENTRE`] of the reference's
//! seed-to-seed σ. Read by the `speed_vs_error` and `equivalence_power` programs.

use pressridge::campaign::read_campaign;
use pressridge::record::RunRecord;
use pressridge::table::ensemble::{Stat, quantity};
use pressridge::table::rafting;
use std::collections::BTreeMap;
use std::path::Path;

/// The quantities compared: key ([`value`]), label, and whether the test judges it (W, ΔPE,
/// W/ΔPE, Φ_i/W, L/h, joints broken, energy per break and the ride-over count).
pub const QUANTITIES: [(&str, &str, bool); 11] = [
    ("work", "W", true),
    ("potential_energy", "ΔPE", true),
    ("ratio_work_to_pe", "W/ΔPE", true),
    ("normal_contact_fraction", "Φ_i/W", true),
    ("friction_fraction", "Φ_f/W", false),
    ("length_to_thickness", "L/h", true),
    ("blocks_broken", "broken", true),
    ("fracture_per_break", "E_f/break", true),
    ("rafted", "rafted", true),
    ("max_sail_height", "sail", false),
    ("max_keel_depth", "keel", false),
];

/// The fewest seeds per arm the test judges on.
pub const SEEDS: usize = 41;

/// The largest centre of a judged shift the test allows, in units of the reference's σ.
pub const CENTRE: f64 = 0.3;

/// One run's value of a quantity of [`QUANTITIES`]: a key of
/// [`pressridge::table::ensemble::quantity`], or `normal_contact_fraction` (Φ_i/W, eq (12)'s
/// net normal contact work over W), `fracture_per_break` (the elastic energy released by
/// cracks over the joints broken, J/m per joint) or `rafted` (1 for a run whose intact sheet
/// rode over the floe by more than the rafting reach, 0 for one that broke at it, so that
/// its mean is the share of runs that rafted). None where the run cannot say.
pub fn value(r: &RunRecord, key: &str) -> Option<f64> {
    match key {
        "normal_contact_fraction" => {
            Some(quantity(r, "normal_contact_work")? / quantity(r, "work")?)
        }
        "fracture_per_break" => {
            let n = quantity(r, "blocks_broken")?;
            (n > 0.0).then_some(quantity(r, "fracture_dissipation")? / n)
        }
        "rafted" => match rafting::outcome(r, rafting::RAFTING_REACH) {
            rafting::Outcome::Rafted(_) => Some(1.0),
            rafting::Outcome::Ridged => Some(0.0),
            rafting::Outcome::Unknown => None,
        },
        _ => quantity(r, key),
    }
}

/// The ensemble statistics of a quantity over runs.
pub fn stat(runs: &[RunRecord], key: &str) -> Stat {
    let xs: Vec<f64> = runs.iter().filter_map(|r| value(r, key)).collect();
    Stat::of(&xs)
}

/// A configuration's shift from the reference in one quantity.
#[derive(Clone, Copy, Debug)]
pub struct Shift {
    /// Difference of the means, configuration − reference (the quantity's unit).
    pub diff: f64,
    /// Half-width of its 95 % Welch interval (the quantity's unit).
    pub half: f64,
    /// The difference in units of the reference's σ (1).
    pub sigmas: f64,
    /// The half-width in units of the reference's σ (1).
    pub sigmas_half: f64,
    /// Whether it passes the test: the interval spans zero, its centre within [`CENTRE`].
    pub passes: bool,
}

/// The shift of `b` from the reference `a` (each with at least two values), judged by the
/// standing rule ([`Rule::Standard`]). σ is the reference's seed-to-seed spread, or both
/// arms' pooled where the reference's values all agree (as every run ridging does).
pub fn shift(a: &Stat, b: &Stat) -> Shift {
    shift_by(a, b, Rule::Standard)
}

/// Rules a shift can be judged by: the standing one and the two alternatives
/// docs/speed-vs-error.md ("What the test can tell") weighs for the owner.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Rule {
    /// The 95 % interval spans zero and its centre lies within [`CENTRE`] σ.
    Standard,
    /// The same with the interval at 1 − 0.05/m for `m` judged shifts (Bonferroni).
    Bonferroni(usize),
    /// Two one-sided tests at 5 %: the 90 % interval lies inside ±[`CENTRE`] σ.
    Tost,
}

/// [`shift`] judged by `rule` (the interval reported is the one the rule reads).
pub fn shift_by(a: &Stat, b: &Stat, rule: Rule) -> Shift {
    let level = match rule {
        Rule::Standard => 0.95,
        Rule::Bonferroni(m) => 1.0 - 0.05 / m.max(1) as f64,
        Rule::Tost => 0.90,
    };
    let (diff, half) = a.welch_difference_at(b, level);
    let sigma = if a.std > 0.0 {
        a.std
    } else {
        (0.5 * (a.std.powi(2) + b.std.powi(2))).sqrt()
    };
    let (sigmas, sigmas_half) = if sigma > 0.0 {
        (diff / sigma, (half / sigma).abs())
    } else {
        (0.0, 0.0)
    };
    let passes = match rule {
        Rule::Standard | Rule::Bonferroni(_) => {
            sigmas - sigmas_half <= 0.0 && sigmas + sigmas_half >= 0.0 && sigmas.abs() <= CENTRE
        }
        Rule::Tost => sigmas - sigmas_half >= -CENTRE && sigmas + sigmas_half <= CENTRE,
    };
    Shift {
        diff,
        half,
        sigmas,
        sigmas_half,
        passes,
    }
}

/// The runs of campaign `dir` by point; with `only`, just the runs whose settings hold it,
/// keyed without it.
pub fn points(
    dir: &Path,
    only: Option<&str>,
) -> Result<BTreeMap<String, Vec<RunRecord>>, Box<dyn std::error::Error>> {
    // A campaign still running is read as far as it got: the table gives n per row.
    let c = read_campaign(dir, true)?;
    if !c.missing.is_empty() {
        eprintln!(
            "{}: {} of {} runs so far",
            dir.display(),
            c.records.len(),
            c.planned
        );
    }
    let records = c.records;
    let mut g: BTreeMap<String, Vec<RunRecord>> = BTreeMap::new();
    for r in records {
        let mut point = r.settings.clone();
        if let Some(only) = only {
            let Some(k) = point.iter().position(|s| s == only) else {
                continue;
            };
            point.remove(k);
        }
        g.entry(point.join(", ")).or_default().push(r);
    }
    if let Some(only) = only
        && g.is_empty()
    {
        return Err(format!("{}: no run has the setting {only}", dir.display()).into());
    }
    Ok(g)
}
