//! Ensemble statistics of a campaign per grid point: the final energy budget, W/ΔPE and the
//! ridge metrics over the seeds of each setting (Hopkins 1994, "Numerical Ridge Growth
//! Experiments", Tables 2–5 report such means per set).
//!
//! Means and sample standard deviations (n − 1) over the runs; a metric that is undefined for
//! a run (a flank slope with fewer than two strips in the 20–80 % band) is left out of that
//! metric's statistics only, and its count says how many runs were behind it.

use crate::energy::{LEDGER_TERMS, N_TERMS};
use crate::record::RunRecord;

/// Mean, sample standard deviation and count of one quantity over runs.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Stat {
    /// Mean over the runs (units of the quantity).
    pub mean: f64,
    /// Sample standard deviation (n − 1; 0 for one run) (units of the quantity).
    pub std: f64,
    /// Number of runs behind the value.
    pub n: usize,
}

impl Stat {
    /// Statistics of `xs` (NaN mean for an empty slice).
    pub fn of(xs: &[f64]) -> Stat {
        let n = xs.len();
        if n == 0 {
            return Stat {
                mean: f64::NAN,
                std: f64::NAN,
                n,
            };
        }
        let mean = xs.iter().sum::<f64>() / n as f64;
        let std = if n > 1 {
            (xs.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (n - 1) as f64).sqrt()
        } else {
            0.0
        };
        Stat { mean, std, n }
    }

    /// Half-width of the 95 % Student-t interval of the mean (units of the quantity; NaN
    /// for fewer than two runs).
    pub fn half_width_95(&self) -> f64 {
        if self.n < 2 {
            return f64::NAN;
        }
        crate::table::fit::student_t_quantile(0.975, (self.n - 1) as f64) * self.std
            / (self.n as f64).sqrt()
    }

    /// `mean ± half-width of the 95 % interval` with `prec` decimals, or the mean alone when
    /// there is no interval (fewer than two runs): how the tables of ensembles write a value.
    pub fn mean_ci95(&self, prec: usize) -> String {
        let h = self.half_width_95();
        if h.is_finite() {
            format!("{:.prec$} ± {:.prec$}", self.mean, h)
        } else {
            format!("{:.prec$}", self.mean)
        }
    }

    /// The difference of means `other − self` and the half-width of its 95 % Welch interval
    /// (unequal variances, Welch–Satterthwaite degrees of freedom), in units of the quantity:
    /// how ensembles of two configurations are compared (docs/speed-vs-error.md).
    pub fn welch_difference(&self, other: &Stat) -> (f64, f64) {
        self.welch_difference_at(other, 0.95)
    }

    /// [`Stat::welch_difference`] with a two-sided interval of confidence `level` in (0, 1)
    /// (dimensionless; 0.95 gives the 95 % interval, its t quantile at 0.5 + 0.5·0.95, which
    /// is 0.975 to the bit).
    pub fn welch_difference_at(&self, other: &Stat, level: f64) -> (f64, f64) {
        let (va, vb) = (
            self.std.powi(2) / self.n as f64,
            other.std.powi(2) / other.n as f64,
        );
        let se = (va + vb).sqrt();
        let dof = (va + vb).powi(2)
            / (va.powi(2) / (self.n as f64 - 1.0) + vb.powi(2) / (other.n as f64 - 1.0))
                .max(1e-300);
        (
            other.mean - self.mean,
            crate::table::fit::student_t_quantile(0.5 + 0.5 * level, dof) * se,
        )
    }
}

/// The quantities summarised, (key, unit, description): every term of the energy ledger at
/// the end of the run, from its table ([`LEDGER_TERMS`], in its order), then the
/// [`OTHER_QUANTITIES`].
pub const QUANTITIES: [(&str, &str, &str); N_QUANTITIES] = quantities();

/// Number of [`QUANTITIES`].
pub const N_QUANTITIES: usize = N_TERMS + OTHER_QUANTITIES.len();

/// The quantities summarised besides the ledger terms: (key, unit, description).
pub const OTHER_QUANTITIES: [(&str, &str, &str); 18] = [
    ("residual_fraction", "1", "|W − sinks| / W at the end"),
    ("pe_fraction", "1", "ΔPE / W"),
    ("friction_fraction", "1", "Φ_f / W"),
    ("viscous_fraction", "1", "Φ_i / W"),
    ("drag_fraction", "1", "drag / W"),
    ("ratio_work_to_pe", "1", "W / ΔPE at the end"),
    ("mean_force", "N/m", "mean ridging force W / (U t)"),
    ("blocks_broken", "1", "joints severed"),
    (
        "handover_contacts",
        "1",
        "contacts born overlapping, their overlap forgiven",
    ),
    (
        "max_sail_height",
        "m",
        "largest strip-mean rubble sail height",
    ),
    (
        "max_keel_depth",
        "m",
        "largest strip-mean rubble keel depth",
    ),
    ("sail_area", "m²/m", "sail cross-section (envelope)"),
    ("keel_area", "m²/m", "keel cross-section (envelope)"),
    ("sail_slope_lead", "°", "lead-side sail slope θ₁"),
    ("sail_slope_floe", "°", "floe-side sail slope θ₂"),
    ("keel_slope_lead", "°", "lead-side keel slope φ₁"),
    ("keel_slope_floe", "°", "floe-side keel slope φ₂"),
    (
        "length_to_thickness",
        "1",
        "rubble piece length over sheet thickness L/h",
    ),
];

/// [`QUANTITIES`]: the ledger's table, then the others.
const fn quantities() -> [(&'static str, &'static str, &'static str); N_QUANTITIES] {
    let mut out = [("", "", ""); N_QUANTITIES];
    let mut k = 0;
    while k < N_TERMS {
        let t = &LEDGER_TERMS[k];
        out[k] = (t.name, t.unit, t.description);
        k += 1;
    }
    while k < out.len() {
        out[k] = OTHER_QUANTITIES[k - N_TERMS];
        k += 1;
    }
    out
}

/// The value of quantity `key` (see [`QUANTITIES`]) for one run, `None` where undefined.
pub fn quantity(r: &RunRecord, key: &str) -> Option<f64> {
    let s = &r.summary;
    let e = s.energy();
    let m = &r.metrics;
    if let Some(k) = LEDGER_TERMS.iter().position(|t| t.name == key) {
        return Some(e.values()[k]);
    }
    let frac = |x: f64| (e.work != 0.0).then(|| x / e.work);
    match key {
        "residual_fraction" => frac(e.residual.abs()),
        "pe_fraction" => frac(e.potential_energy),
        "friction_fraction" => frac(e.friction_dissipation),
        "viscous_fraction" => frac(e.viscous_dissipation),
        "drag_fraction" => frac(e.drag_dissipation),
        "ratio_work_to_pe" => (e.potential_energy > 0.0).then_some(s.ratio_work_to_pe),
        "mean_force" => {
            let u = r.scene.sheet.as_ref().map_or(0.0, |sh| sh.speed);
            (u * s.time > 0.0).then(|| e.work / (u * s.time))
        }
        "blocks_broken" => Some(s.blocks_broken as f64),
        "handover_contacts" => Some(s.handover_contacts as f64),
        "max_sail_height" => Some(m.max_sail_height),
        "max_keel_depth" => Some(m.max_keel_depth),
        "sail_area" => Some(m.sail_area),
        "keel_area" => Some(m.keel_area),
        "sail_slope_lead" => m.sail_slope_lead,
        "sail_slope_floe" => m.sail_slope_floe,
        "keel_slope_lead" => m.keel_slope_lead,
        "keel_slope_floe" => m.keel_slope_floe,
        "length_to_thickness" => Some(m.length_to_thickness),
        _ => None,
    }
}

/// Relative tolerance of [`dissipation_violation`]: a dissipation may be negative by this
/// fraction of the work (round-off of sums over millions of steps), no more.
pub const DISSIPATION_TOLERANCE: f64 = 1e-6;

/// Why run `r` cannot be physical, or `None`: every dissipation (friction Φ_f, eq 11;
/// viscous contact Φ_i, eq 12; drag; joint viscosity; boundary dashpots; crack release) is
/// work turned into heat and can only grow from zero. A ledger that closes while one of them
/// is negative (below −[`DISSIPATION_TOLERANCE`]·|W|, at the end or at any sample) books a
/// numerical energy source: the run went unstable, and its energetics are not ridging.
pub fn dissipation_violation(r: &RunRecord) -> Option<String> {
    let e = r.summary.energy();
    let tol = DISSIPATION_TOLERANCE * e.work.abs().max(1.0);
    let bad = |v: f64| v < -tol || !v.is_finite();
    if let Some((name, v)) = e.dissipations().find(|&(_, v)| bad(v)) {
        return Some(format!(
            "{name} = {v:.4e} J/m at the end (work {:.4e} J/m)",
            e.work
        ));
    }
    r.samples.iter().find_map(|x| {
        let (name, v) = x.energy().dissipations().find(|&(_, v)| bad(v))?;
        Some(format!("{name} = {v:.4e} J/m at t = {} s", x.time))
    })
}

/// Statistics of one grid point (all seeds of one setting).
#[derive(Clone, Debug, PartialEq)]
pub struct PointStats {
    /// The point's settings, `key=value` joined by `, ` (`all` for a grid of one point).
    pub label: String,
    /// Seeds of its runs.
    pub seeds: Vec<u64>,
    /// One [`Stat`] per entry of [`QUANTITIES`], in that order.
    pub stats: Vec<Stat>,
}

impl PointStats {
    /// The statistics of quantity `key`.
    pub fn get(&self, key: &str) -> Option<Stat> {
        QUANTITIES
            .iter()
            .position(|(k, _, _)| *k == key)
            .map(|i| self.stats[i])
    }
}

/// Groups `records` by their settings, in first-seen order: the grid points of a campaign,
/// labelled `key=value, …` (`all` for a grid of one point).
pub fn group_by_point(records: &[RunRecord]) -> Vec<(String, Vec<&RunRecord>)> {
    let mut groups: Vec<(String, Vec<&RunRecord>)> = Vec::new();
    for r in records {
        let label = if r.settings.is_empty() {
            "all".to_string()
        } else {
            r.settings.join(", ")
        };
        match groups.iter_mut().find(|(l, _)| *l == label) {
            Some((_, v)) => v.push(r),
            None => groups.push((label, vec![r])),
        }
    }
    groups
}

/// Groups `records` by their settings ([`group_by_point`]) and summarises each group.
pub fn summarise(records: &[RunRecord]) -> Vec<PointStats> {
    group_by_point(records)
        .into_iter()
        .map(|(label, rs)| PointStats {
            label,
            seeds: rs.iter().map(|r| r.seed).collect(),
            stats: QUANTITIES
                .iter()
                .map(|(k, _, _)| {
                    let xs: Vec<f64> = rs.iter().filter_map(|r| quantity(r, k)).collect();
                    Stat::of(&xs)
                })
                .collect(),
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Two ensembles of six runs with standard deviation 1: Welch's degrees of freedom are
    /// (2/6)²/(2·(1/6)²/5) = 10, so the half-width is t₀.₉₇₅,₁₀·sqrt(2/6) = 2.228139·0.577350;
    /// the mean's own interval is t₀.₉₇₅,₅/sqrt(6) = 2.570582/2.449490.
    #[test]
    fn welch_and_student_intervals_match_the_textbook_values() {
        let a = Stat {
            mean: 10.0,
            std: 1.0,
            n: 6,
        };
        let b = Stat {
            mean: 12.5,
            std: 1.0,
            n: 6,
        };
        let (d, h) = a.welch_difference(&b);
        assert_eq!(d, 2.5);
        assert!((h - 2.228139 * (2.0f64 / 6.0).sqrt()).abs() < 1e-5, "{h}");
        // At 90 %: t₀.₉₅,₁₀ = 1.812461; the 95 % call is the general one at 0.95, bit for bit.
        let (_, h90) = a.welch_difference_at(&b, 0.90);
        assert!(
            (h90 - 1.812461 * (2.0f64 / 6.0).sqrt()).abs() < 1e-5,
            "{h90}"
        );
        let (_, h95) = a.welch_difference_at(&b, 0.95);
        assert_eq!(h95.to_bits(), h.to_bits());
        assert_eq!(
            h.to_bits(),
            (crate::table::fit::student_t_quantile(0.975, 10.0) * (2.0f64 / 6.0).sqrt()).to_bits()
        );
        assert!((a.half_width_95() - 2.570582 / 6f64.sqrt()).abs() < 1e-5);
        assert!(
            Stat {
                mean: 1.0,
                std: 0.0,
                n: 1
            }
            .half_width_95()
            .is_nan()
        );
    }

    /// The ensemble summarises every ledger term under the table's name, unit and
    /// description, with the run summary's value; no key is there twice.
    #[test]
    fn the_ledger_quantities_come_from_the_table() {
        let mut json = crate::table::summary_without_ledger();
        for (k, t) in LEDGER_TERMS.iter().enumerate() {
            json[t.name] = (k as f64 + 1.0).into();
        }
        let r = RunRecord {
            id: "x".into(),
            settings: vec![],
            seed: 1,
            scene: crate::scene::Scene::default(),
            summary: serde_json::from_value(json).unwrap(),
            samples: vec![],
            profile: Default::default(),
            metrics: Default::default(),
            digest: None,
        };
        for (k, t) in LEDGER_TERMS.iter().enumerate() {
            assert_eq!(QUANTITIES[k], (t.name, t.unit, t.description));
            assert_eq!(quantity(&r, t.name), Some(k as f64 + 1.0));
        }
        let mut keys: Vec<&str> = QUANTITIES.iter().map(|q| q.0).collect();
        keys.sort_unstable();
        keys.dedup();
        assert_eq!(keys.len(), QUANTITIES.len());
    }

    #[test]
    fn stat_is_the_sample_mean_and_deviation() {
        let s = Stat::of(&[1.0, 2.0, 3.0, 4.0]);
        assert_eq!(s.mean, 2.5);
        assert!((s.std - (5.0f64 / 3.0).sqrt()).abs() < 1e-15);
        assert_eq!(s.n, 4);
        assert_eq!(Stat::of(&[7.0]).std, 0.0);
        assert!(Stat::of(&[]).mean.is_nan());
    }
}
