//! The measured effect of each open modelling choice (issue 30's register, docs/choices.md):
//! for every probe — a campaign that moves one choice from its default — the difference of
//! its ensemble means from the baseline's at the same friction, with the 95 % Welch interval.
//!
//! A probe's runs are matched to the baseline's by their friction pair (μ, μ_w); the probe's
//! own axis setting (e.g. `floe.nose_bevel=0.25`) names its row.

use pressridge::record::RunRecord;
use pressridge::table::ensemble::Stat;
use pressridge::table::rafting::{Outcome, RAFTING_REACH, outcome};
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
    (
        "L/h",
        // 0 when no block broke off: undefined, not a length.
        |r| (r.metrics.length_to_thickness > 0.0).then_some(r.metrics.length_to_thickness),
        1.0,
        2,
    ),
    (
        "sail/keel",
        |r| {
            (r.metrics.keel_ice_area > 0.0)
                .then(|| r.metrics.sail_ice_area / r.metrics.keel_ice_area)
        },
        1.0,
        2,
    ),
    ("max sail (m)", |r| Some(r.metrics.max_sail_height), 1.0, 2),
    ("overrun (m)", |r| r.summary.sheet_overrun_max, 1.0, 1),
];

/// A share of the work (dimensionless): `part` over W.
fn share(r: &RunRecord, part: fn(&pressridge::energy::EnergyBudget) -> f64) -> Option<f64> {
    let e = r.summary.energy();
    (e.work != 0.0).then(|| part(&e) / e.work)
}

/// The register's second table: where the work went besides friction, and the contacts
/// (the parts of Φ_i, each other sink, the joints broken, the keel, the contacts' median
/// damping ratio ζ and impact restitution e). Records made before the contacts were tallied
/// (model revision 1) have no ζ or e.
pub const SINKS: [Quantity; 10] = [
    (
        "Φ_i viscous/W (%)",
        |r| share(r, |e| e.viscous_dissipation),
        100.0,
        2,
    ),
    (
        "Φ_i elastic/W (%)",
        |r| share(r, |e| e.normal_elastic_work - e.plastic_dissipation),
        100.0,
        2,
    ),
    (
        "Φ_i plastic/W (%)",
        |r| share(r, |e| e.plastic_dissipation),
        100.0,
        2,
    ),
    ("drag/W (%)", |r| share(r, |e| e.drag_dissipation), 100.0, 1),
    (
        "dashpots/W (%)",
        |r| share(r, |e| e.boundary_dissipation),
        100.0,
        1,
    ),
    (
        "joints/W (%)",
        |r| share(r, |e| e.joint_dissipation + e.fracture_dissipation),
        100.0,
        2,
    ),
    (
        "joints broken",
        |r| Some(r.summary.blocks_broken as f64),
        1.0,
        0,
    ),
    ("max keel (m)", |r| Some(r.metrics.max_keel_depth), 1.0, 2),
    (
        "ζ median",
        |r| {
            r.summary
                .contacts
                .and_then(|c| c.damping_ratio)
                .map(|q| q[1])
        },
        1.0,
        2,
    ),
    (
        "e median",
        |r| r.summary.contacts.and_then(|c| c.restitution).map(|q| q[1]),
        1.0,
        2,
    ),
];

/// The table of the paper's friction statements for the baseline and each probe setting: the
/// difference of the means at μ = 1.0 and μ = 0.4 (same μ_w) with its 95 % Welch interval, in
/// bold where the interval excludes zero; `agrees` counts the resolved differences of the
/// paper's sign.
fn friction_contrast(s: &mut String, baseline: &[RunRecord], probes: &[(String, Vec<RunRecord>)]) {
    let mut waters: Vec<f64> = baseline.iter().map(|r| friction(r).1).collect();
    waters.sort_by(f64::total_cmp);
    waters.dedup();
    for mu_w in waters {
        let (lo, hi) = ((0.4, mu_w), (1.0, mu_w));
        let _ = writeln!(
            s,
            "\n**The paper's friction statements at μ_w = {mu_w}: μ = 1.0 minus μ = 0.4**\n"
        );
        let mut head = String::from("| choice |");
        for (label, ..) in FRICTION_STATEMENTS {
            let _ = write!(head, " {label} |");
        }
        let _ = writeln!(
            s,
            "{head} resolved with the paper's sign |\n|---|---|---|---|---|---|"
        );
        let mut rows: Vec<(String, Vec<&RunRecord>, Vec<&RunRecord>)> =
            vec![("baseline".into(), at(baseline, lo), at(baseline, hi))];
        let (pl, ph) = (by_setting(probes, lo), by_setting(probes, hi));
        for (label, runs) in pl {
            if let Some(h) = ph.get(&label) {
                rows.push((label, runs, h.clone()));
            }
        }
        for (label, a, b) in rows {
            let mut row = format!("| {label} (n = {}, {}) |", a.len(), b.len());
            let mut agree = 0;
            for (_, k, sign) in FRICTION_STATEMENTS {
                let (_, q, scale, d) = QUANTITIES[k];
                let (cell, diff, resolved) = difference_cell(&stat(&a, q), &stat(&b, q), scale, d);
                if resolved && diff * sign > 0.0 {
                    agree += 1;
                }
                let _ = write!(row, " {cell} |");
            }
            let _ = writeln!(s, "{row} {agree} of {} |", FRICTION_STATEMENTS.len());
        }
    }
}

/// The difference of means `b − a` as a table cell, `diff [lo, hi]` with its 95 % Welch
/// interval (scaled by `scale`, `d` decimals), in bold where the interval excludes zero;
/// with the difference (unscaled) and whether it is resolved.
///
/// A quantity defined in fewer than two runs of either side (W/ΔPE of runs that built no
/// ridge, ΔPE = 0) has no interval: the cell says `n/a` and how many runs define it, or `—`
/// when no run of either side does (ζ and e in records made before they were kept). Two
/// sides without spread (a term that is zero in every run) get the difference alone.
fn difference_cell(a: &Stat, b: &Stat, scale: f64, d: usize) -> (String, f64, bool) {
    if a.n == 0 && b.n == 0 {
        return ("—".into(), f64::NAN, false);
    }
    if a.n < 2 || b.n < 2 {
        return (
            format!("n/a (defined in {} and {} runs)", a.n, b.n),
            f64::NAN,
            false,
        );
    }
    let (diff, h) = a.welch_difference(b);
    if h.is_nan() {
        // Neither side varies (a term that is zero in every run, say): no interval.
        let mark = if diff != 0.0 { "**" } else { "" };
        return (
            format!("{mark}{:+.d$} (no spread){mark}", diff * scale),
            diff,
            diff != 0.0,
        );
    }
    let resolved = (diff - h) * (diff + h) > 0.0;
    let mark = if resolved { "**" } else { "" };
    let cell = format!(
        "{mark}{:+.d$} [{:+.d$}, {:+.d$}]{mark}",
        diff * scale,
        (diff - h) * scale,
        (diff + h) * scale,
    );
    (cell, diff, resolved)
}

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

/// Each probe setting's runs at friction `f`, pooled over the probe campaigns that hold it
/// (a probe's later seeds in a campaign of their own), by the setting's label.
pub(crate) fn by_setting(
    probes: &[(String, Vec<RunRecord>)],
    f: (f64, f64),
) -> std::collections::BTreeMap<String, Vec<&RunRecord>> {
    let mut m: std::collections::BTreeMap<String, Vec<&RunRecord>> = Default::default();
    for (name, runs) in probes {
        for r in at(runs, f) {
            let setting = probe_setting(r);
            let label = if setting.is_empty() {
                name.clone()
            } else {
                setting
            };
            m.entry(label).or_default().push(r);
        }
    }
    m
}

/// The paper's friction statements, as signs of the change from μ = 0.4 to μ = 1.0 at one
/// μ_w: W falls, ΔPE falls, W/ΔPE rises, the sail shrinks against the keel (Hopkins 1994,
/// "Effects of Friction"). (column label, quantity index in [`QUANTITIES`], sign.)
const FRICTION_STATEMENTS: [(&str, usize, f64); 4] = [
    ("W (kJ/m), falls", 0, -1.0),
    ("ΔPE (kJ/m), falls", 1, -1.0),
    ("W/ΔPE, rises", 2, 1.0),
    ("sail/keel, falls", 7, -1.0),
];

/// The runs of `records` at friction `f`.
pub(crate) fn at(records: &[RunRecord], f: (f64, f64)) -> Vec<&RunRecord> {
    records.iter().filter(|r| friction(r) == f).collect()
}

fn stat(runs: &[&RunRecord], q: fn(&RunRecord) -> Option<f64>) -> Stat {
    let xs: Vec<f64> = runs.iter().filter_map(|r| q(r)).collect();
    Stat::of(&xs)
}

/// `rafted/n`: the runs whose intact sheet passed the floe's nose by more than
/// [`RAFTING_REACH`].
fn rafted(runs: &[&RunRecord]) -> String {
    format!("{}/{}", rafted_count(runs), runs.len())
}

/// The number of `runs` whose intact sheet passed the floe's nose by more than
/// [`RAFTING_REACH`].
pub(crate) fn rafted_count(runs: &[&RunRecord]) -> usize {
    runs.iter()
        .filter(|r| matches!(outcome(r, RAFTING_REACH), Outcome::Rafted(_)))
        .count()
}

/// One table of the register at friction `f`: the baseline's means of `quantities` (with
/// their 95 % half-widths), and every probe setting's difference from them.
fn effect_table(
    s: &mut String,
    base: &[&RunRecord],
    probes: &[(String, Vec<RunRecord>)],
    f: (f64, f64),
    quantities: &[Quantity],
) {
    let mut head = String::from("| choice | rafted |");
    let mut rule = String::from("|---|---|");
    for (label, ..) in quantities {
        let _ = write!(head, " {label} |");
        rule.push_str("---|");
    }
    let _ = writeln!(s, "{head}\n{rule}");
    let mut row = format!("| baseline (n = {}) | {} |", base.len(), rafted(base));
    for &(_, q, scale, d) in quantities {
        let st = stat(base, q);
        if st.n == 0 {
            row.push_str(" — |");
            continue;
        }
        let _ = write!(
            row,
            " {:.d$} ± {:.d$} |",
            st.mean * scale,
            st.half_width_95() * scale,
            d = d
        );
    }
    let _ = writeln!(s, "{row}");
    for (label, these) in by_setting(probes, f) {
        let mut row = format!("| {label} (n = {}) | {} |", these.len(), rafted(&these));
        for &(_, q, scale, d) in quantities {
            let (cell, ..) = difference_cell(&stat(base, q), &stat(&these, q), scale, d);
            let _ = write!(row, " {cell} |");
        }
        let _ = writeln!(s, "{row}");
    }
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
        for (k, quantities) in [&QUANTITIES, &SINKS].into_iter().enumerate() {
            let what = if k == 0 { "" } else { ": sinks and contacts" };
            let _ = writeln!(s, "\n**μ = {}, μ_w = {}{what}**\n", f.0, f.1);
            effect_table(&mut s, &base, probes, f, quantities);
        }
    }
    friction_contrast(&mut s, baseline, probes);
    s.push_str(
        "\nBaseline: mean ± 95 % half-width (Student's t). Probes: difference of means from the \
         baseline with its 95 % Welch interval; in bold where the interval excludes zero. \
         Φ_i is eq (12)'s net normal contact work (viscous, elastic and plastic parts in the \
         second table); other = W − Φ_f − Φ_i − ΔPE − ΔKE (drag, the eq (7)–(8) and floe \
         dashpots, the joints' viscosity and fracture); ζ and e are each run's median damping \
         ratio of its contacts and restitution of its impacts; \
         sail/keel is the rubble ice area above over below the water line; overrun is the \
         farthest the intact sheet passed the floe's nose; rafted counts the runs whose overrun \
         passed the rafting reach, 2 m past the top of the nose ramp (a 45° ramp's 0.5 m; a \
         20° ramp adds its longer run, 2.87 m). The friction tables test the paper's statements within each setting: the \
         change of each mean from μ = 0.4 to μ = 1.0 at one μ_w, with the paper's sign in the \
         column's name.\n",
    );
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A quantity no run defines (W/ΔPE where no ridge was built) is `n/a`, never a NaN
    /// interval and never resolved; a defined one gets the Welch interval.
    #[test]
    fn undefined_quantities_are_not_given_an_interval() {
        let none = Stat::of(&[]);
        let some = Stat::of(&[14.0, 16.0, 15.0]);
        let (cell, diff, resolved) = difference_cell(&some, &none, 1.0, 1);
        assert_eq!(cell, "n/a (defined in 3 and 0 runs)");
        assert!(diff.is_nan() && !resolved);
        let (cell, diff, resolved) = difference_cell(&some, &Stat::of(&[24.0, 26.0, 25.0]), 1.0, 1);
        assert_eq!(diff, 10.0);
        assert!(resolved, "{cell}");
        assert!(cell.starts_with("**+10.0 ["), "{cell}");
    }
}
