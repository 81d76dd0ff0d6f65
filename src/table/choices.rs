//! The measured effect of each open modelling choice (issue 30's register, docs/choices.md):
//! for every probe — a campaign that moves one choice from its default — the difference of
//! its ensemble means from the baseline's at the same friction, with the 95 % Welch interval.
//!
//! A probe's runs are matched to the baseline's by their friction pair (μ, μ_w); the probe's
//! own axis setting (e.g. `floe.nose_bevel=0.25`) names its row.

use crate::record::RunRecord;
use crate::table::ensemble::Stat;
use crate::table::rafting::{Outcome, RAFTING_REACH, outcome};
use std::fmt::Write as _;

/// One quantity of a run the register reports: (column label, value of a run, scale for
/// printing, decimals).
type Quantity = (&'static str, fn(&RunRecord) -> Option<f64>, f64, usize);

/// Φ_i as eq (12) defines it (J/m): `normal_contact_work`, or in records without it the
/// viscous part plus the contact hysteresis.
pub(crate) fn phi_i(r: &RunRecord) -> f64 {
    let e = r.summary.energy();
    if e.normal_contact_work != 0.0 {
        e.normal_contact_work
    } else {
        e.viscous_dissipation + e.contact_hysteresis
    }
}

/// The sinks other than Φ_f, Φ_i (eq 12), ΔPE and the change of kinetic energy, as a
/// fraction of the work.
pub(crate) fn other_sinks_fraction(r: &RunRecord) -> f64 {
    let e = r.summary.energy();
    (e.work - e.friction_dissipation - phi_i(r) - e.potential_energy - e.kinetic_energy) / e.work
}

/// The register's quantities.
pub const QUANTITIES: [Quantity; 10] = [
    ("W (kJ/m)", |r| Some(r.summary.energy().work), 1e-3, 0),
    (
        "ΔPE (kJ/m)",
        |r| Some(r.summary.energy().potential_energy),
        1e-3,
        1,
    ),
    (
        "W/ΔPE",
        |r| {
            let e = r.summary.energy();
            (e.potential_energy > 0.0).then(|| e.work / e.potential_energy)
        },
        1.0,
        1,
    ),
    (
        "Φ_f/W (%)",
        |r| {
            let e = r.summary.energy();
            Some(e.friction_dissipation / e.work)
        },
        100.0,
        1,
    ),
    (
        "Φ_i/W (%)",
        |r| Some(phi_i(r) / r.summary.energy().work),
        100.0,
        1,
    ),
    ("other/W (%)", |r| Some(other_sinks_fraction(r)), 100.0, 1),
    ("L/h", |r| Some(r.metrics.length_to_thickness), 1.0, 2),
    (
        "sail/keel",
        |r| Some(r.metrics.sail_ice_area / r.metrics.keel_ice_area),
        1.0,
        2,
    ),
    ("max sail (m)", |r| Some(r.metrics.max_sail_height), 1.0, 2),
    ("overrun (m)", |r| r.summary.sheet_overrun_max, 1.0, 1),
];

/// The friction pair of a run.
fn friction(r: &RunRecord) -> (f64, f64) {
    (r.scene.contact.mu, r.scene.contact.mu_water)
}

/// A probe run's own axis settings, without its friction (e.g. `floe.nose_bevel=0.25`).
fn probe_setting(r: &RunRecord) -> String {
    r.settings
        .iter()
        .filter(|x| !x.starts_with("contact.mu"))
        .cloned()
        .collect::<Vec<_>>()
        .join(", ")
}

/// The runs of `records` at friction `f`.
fn at(records: &[RunRecord], f: (f64, f64)) -> Vec<&RunRecord> {
    records.iter().filter(|r| friction(r) == f).collect()
}

fn stat(runs: &[&RunRecord], q: fn(&RunRecord) -> Option<f64>) -> Stat {
    let xs: Vec<f64> = runs.iter().filter_map(|r| q(r)).collect();
    Stat::of(&xs)
}

/// `rafted/n`: the runs whose intact sheet passed the floe's nose by more than
/// [`RAFTING_REACH`].
fn rafted(runs: &[&RunRecord]) -> String {
    let n = runs
        .iter()
        .filter(|r| matches!(outcome(r, RAFTING_REACH), Outcome::Rafted(_)))
        .count();
    format!("{n}/{}", runs.len())
}

/// The register's effect table as Markdown: per friction pair, the baseline's means (with
/// their 95 % half-widths) and, for every probe setting, its difference from them with the
/// 95 % Welch interval; `rafted` counts the runs that rode over the floe.
///
/// `baseline` is the baseline campaign's runs; `probes` the probe campaigns' runs, each as
/// (probe name, runs).
pub fn effects(baseline: &[RunRecord], probes: &[(String, Vec<RunRecord>)]) -> String {
    let mut pairs: Vec<(f64, f64)> = baseline.iter().map(friction).collect();
    pairs.sort_by(|a, b| a.partial_cmp(b).expect("finite friction"));
    pairs.dedup();
    let mut s = String::new();
    for f in pairs {
        let base = at(baseline, f);
        let _ = writeln!(s, "\n**μ = {}, μ_w = {}**\n", f.0, f.1);
        let mut head = String::from("| choice | rafted |");
        let mut rule = String::from("|---|---|");
        for (label, ..) in QUANTITIES {
            let _ = write!(head, " {label} |");
            rule.push_str("---|");
        }
        let _ = writeln!(s, "{head}\n{rule}");
        let mut row = format!("| baseline (n = {}) | {} |", base.len(), rafted(&base));
        for (_, q, scale, d) in QUANTITIES {
            let st = stat(&base, q);
            let _ = write!(
                row,
                " {:.d$} ± {:.d$} |",
                st.mean * scale,
                st.half_width_95() * scale,
                d = d
            );
        }
        let _ = writeln!(s, "{row}");
        // Each probe setting, its runs pooled over the probe campaigns that hold it.
        let mut by_setting: std::collections::BTreeMap<String, Vec<&RunRecord>> =
            std::collections::BTreeMap::new();
        for (name, runs) in probes {
            for r in at(runs, f) {
                let setting = probe_setting(r);
                let label = if setting.is_empty() {
                    name.clone()
                } else {
                    setting
                };
                by_setting.entry(label).or_default().push(r);
            }
        }
        for (label, these) in by_setting {
            let mut row = format!("| {label} (n = {}) | {} |", these.len(), rafted(&these));
            for (_, q, scale, d) in QUANTITIES {
                let (a, b) = (stat(&base, q), stat(&these, q));
                let (diff, h) = a.welch_difference(&b);
                let mark = if (diff - h) * (diff + h) > 0.0 {
                    "**"
                } else {
                    ""
                };
                let _ = write!(
                    row,
                    " {mark}{:+.d$} [{:+.d$}, {:+.d$}]{mark} |",
                    diff * scale,
                    (diff - h) * scale,
                    (diff + h) * scale,
                    d = d
                );
            }
            let _ = writeln!(s, "{row}");
        }
    }
    s.push_str(
        "\nBaseline: mean ± 95 % half-width (Student's t). Probes: difference of means from the \
         baseline with its 95 % Welch interval; in bold where the interval excludes zero. \
         Φ_i is eq (12)'s net normal contact work; other = W − Φ_f − Φ_i − ΔPE − ΔKE; \
         sail/keel is the rubble ice area above over below the water line; overrun is the \
         farthest the intact sheet passed the floe's nose; rafted counts the runs whose overrun \
         passed 2 m.\n",
    );
    s
}
