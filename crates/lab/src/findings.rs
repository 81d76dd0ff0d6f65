//! The paper's stated findings, tested on ensembles (issue 30): each statement Hopkins (1994)
//! makes in words about the model's behaviour away from and at the Figure 5 point, our
//! ensemble's answer with its 95 % interval, and a verdict.
//!
//! The runs are chosen by their scenes, not by the directory that holds them: the Figure 5
//! point is every run whose scene is the built-in default (the Figure 5 scene) but for its
//! name, seed and output; the friction set is the same scene at other (μ, μ_w); the modulus
//! and speed sets move E and U alone (with the duration that pushes 100 m of sheet). So the same table reads the paper campaign's records
//! (`crates/lab/records/paper/`) or any other set of campaigns of the same scenes.
//!
//! Verdicts: **agree** when the 95 % interval lies on the paper's side of the statement's
//! bound, **disagree** when it lies on the other side, **unresolved** when it straddles it
//! (more seeds would decide). Where the paper says "small", "nearly identical" or "nearly
//! constant" without a number, the bound is ours and is written in the row
//! ([`SMALL_SPREAD`], [`NEARLY_IDENTICAL`], [`NEARLY_CONSTANT`], [`OTHER_SINKS_BOUND`]).
//! Intervals: Student's t for one ensemble's mean, Welch's t for a difference of two
//! ensembles' means, the ordinary least-squares slope's t interval for a trend.

use crate::choices::{other_sinks_fraction, phi_i};
use pressridge::energy::EnergyBudget;
use pressridge::record::RunRecord;
use pressridge::scene::{Scene, StepScheme};
use pressridge::table::ensemble::Stat;
use pressridge::table::fit::student_t_quantile;
use pressridge::table::rafting::{Outcome, RAFTING_REACH, outcome};
use std::fmt::Write as _;

mod energy;
mod evidence;
mod friction;
mod modulus_speed;

pub use evidence::{NOT_CHOICES, Register, evidence};

/// The paper's bound on the sinks other than Φ_f, Φ_i, ΔPE and kinetic energy, as a fraction
/// of the work: "in total, typically amount to less than 5% of the energy consumed".
pub const OTHER_SINKS_BOUND: f64 = 0.05;
/// Our bound for "small" (the spread of W over μ at one μ_w): the difference of the mean W at
/// μ = 0.4 and μ = 1.0, as a fraction of the mean at μ = 1.0. The paper's number is
/// withheld; its words set the spread against the "strong" dependence on thickness (W more
/// than doubles from 0.20 to 0.45 m), so a quarter is taken as the largest "small" spread.
pub const SMALL_SPREAD: f64 = 0.25;
/// Our bound for "nearly identical" (6.25 against 25 cm/s): a difference of means within this
/// fraction of the 25 cm/s mean.
pub const NEARLY_IDENTICAL: f64 = 0.15;
/// Our bound for "nearly constant" (W/ΔPE over primary ridge growth): the ratio at the end of
/// a run over the ratio at a quarter of its duration within 1 ± this fraction.
pub const NEARLY_CONSTANT: f64 = 0.25;
/// The share of the work breakage may take to count as "little energy" ("a few per cent").
pub const BREAKAGE_BOUND: f64 = 0.05;

/// A statement's verdict.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Verdict {
    /// The 95 % interval lies on the paper's side.
    Agree,
    /// The 95 % interval lies on the other side.
    Disagree,
    /// The interval straddles the bound.
    Unresolved,
}

impl Verdict {
    /// As the table writes it.
    pub fn as_str(&self) -> &'static str {
        match self {
            Verdict::Agree => "agree",
            Verdict::Disagree => "disagree",
            Verdict::Unresolved => "unresolved",
        }
    }
    /// The verdict of an interval `[lo, hi]` against the statement "the value is above
    /// `bound`" (`above = true`) or "below `bound`".
    fn of(lo: f64, hi: f64, bound: f64, above: bool) -> Verdict {
        let (lo, hi) = if above { (lo, hi) } else { (-hi, -lo) };
        let bound = if above { bound } else { -bound };
        if !(lo.is_finite() && hi.is_finite()) {
            Verdict::Unresolved
        } else if lo > bound {
            Verdict::Agree
        } else if hi < bound {
            Verdict::Disagree
        } else {
            Verdict::Unresolved
        }
    }
    /// The verdict of an interval `[lo, hi]` against "the value lies within ±`bound`".
    fn within(lo: f64, hi: f64, bound: f64) -> Verdict {
        if !(lo.is_finite() && hi.is_finite()) {
            Verdict::Unresolved
        } else if lo > -bound && hi < bound {
            Verdict::Agree
        } else if lo > bound || hi < -bound {
            Verdict::Disagree
        } else {
            Verdict::Unresolved
        }
    }
}

/// One row of the statement table.
#[derive(Clone, Debug, PartialEq)]
pub struct Finding {
    /// The item of issue 30 it tests (`a`, `c1`, …).
    pub item: &'static str,
    /// The paper's words (section in brackets).
    pub paper: &'static str,
    /// Our answer: the measured quantity with its 95 % interval and the runs behind it.
    pub ours: String,
    /// The verdict.
    pub verdict: Verdict,
}

/// A set of runs the table needs and did not find.
#[derive(Debug, thiserror::Error)]
#[error("findings: {what}: {have} runs, {need} needed")]
pub struct MissingRuns {
    /// Which runs (the scene that selects them).
    pub what: String,
    /// How many were found.
    pub have: usize,
    /// How many are needed.
    pub need: usize,
}

/// A scene of the paper's experiments: the Figure 5 scene (the built-in default) with its
/// friction, lead-ice modulus or speed moved, 100 m of sheet pushed.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Point {
    mu: f64,
    mu_w: f64,
    e_top: f64,
    e_bottom: f64,
    speed: f64,
}

const FIGURE5: Point = Point {
    mu: 1.0,
    mu_w: 0.6,
    e_top: 1.0e8,
    e_bottom: 6.7e7,
    speed: 0.25,
};

/// A scene as JSON without what does not change the physics of a run: its name, seed,
/// output and sampling.
fn physics(s: &Scene) -> serde_json::Value {
    let mut v = serde_json::to_value(s).expect("a scene serialises");
    if let Some(o) = v.as_object_mut() {
        for k in ["name", "seed", "output"] {
            o.remove(k);
        }
        if let Some(n) = o.get_mut("numerics").and_then(|n| n.as_object_mut()) {
            n.remove("sample_interval");
        }
    }
    v
}

impl Point {
    fn friction(mu: f64, mu_w: f64) -> Point {
        Point {
            mu,
            mu_w,
            ..FIGURE5
        }
    }
    /// The point's scene, `base` with the point's friction, modulus and speed, as JSON
    /// ([`physics`]).
    fn scene(&self, base: &Scene) -> serde_json::Value {
        physics(&self.with(base))
    }
    /// `base` with the point's friction, modulus and speed.
    fn with(&self, base: &Scene) -> Scene {
        let sets = [
            format!("contact.mu={}", self.mu),
            format!("contact.mu_water={}", self.mu_w),
            format!("sheet.e_top={:e}", self.e_top),
            format!("sheet.e_bottom={:e}", self.e_bottom),
            format!("sheet.speed={}", self.speed),
            format!("duration={}", 100.0 / self.speed),
        ];
        base.clone()
            .with_overrides(&sets)
            .expect("the paper's points are valid scenes")
    }
    fn describe(&self) -> String {
        format!(
            "the Figure 5 scene at μ = {}, μ_w = {}, E_top = {} GPa, U = {} m/s",
            self.mu,
            self.mu_w,
            self.e_top / 1e9,
            self.speed
        )
    }
}

/// The step scheme of `records` at the Figure 5 point of `base` (`numerics.time_step_safety`
/// and the refinements, [`StepScheme`]): the table tests the model at the step its records
/// were made with, and every point is then read at that step. `Ok(None)` when no run is at
/// the point (the table then names the missing runs); an error naming the schemes when the
/// runs there were made at more than one, since an ensemble must not mix steps
/// (docs/speed-vs-error.md).
pub fn records_step(records: &[RunRecord], base: &Scene) -> Result<Option<StepScheme>, String> {
    let without_step = |s: &Scene| {
        let mut v = physics(s);
        if let Some(n) = v.get_mut("numerics").and_then(|n| n.as_object_mut()) {
            for k in StepScheme::KEYS {
                n.remove(k);
            }
        }
        v
    };
    let want = without_step(&FIGURE5.with(base));
    let mut steps: Vec<StepScheme> = Vec::new();
    for r in records.iter().filter(|r| without_step(&r.scene) == want) {
        let s = r.scene.numerics.step_scheme();
        if !steps.contains(&s) {
            steps.push(s);
        }
    }
    steps.sort_by(|a, b| a.time_step_safety.total_cmp(&b.time_step_safety));
    match steps.as_slice() {
        [] => Ok(None),
        [one] => Ok(Some(*one)),
        many => Err(format!(
            "the runs at the Figure 5 point were made at {} steps ({}); choose one with \
             --set numerics.time_step_safety=VALUE (and the numerics.refine_* keys)",
            many.len(),
            many.iter()
                .map(|v| v.to_string())
                .collect::<Vec<_>>()
                .join("; ")
        )),
    }
}

/// The runs of `records` at `p` of scene `base`; an error when fewer than `need`.
fn select<'a>(
    records: &'a [RunRecord],
    base: &Scene,
    p: Point,
    need: usize,
) -> Result<Vec<&'a RunRecord>, MissingRuns> {
    let want = p.scene(base);
    let v: Vec<&RunRecord> = records
        .iter()
        .filter(|r| physics(&r.scene) == want)
        .collect();
    if v.len() < need {
        return Err(MissingRuns {
            what: p.describe(),
            have: v.len(),
            need,
        });
    }
    Ok(v)
}

/// W (J/m) of a run.
fn work(r: &RunRecord) -> Option<f64> {
    Some(r.summary.energy().work)
}

/// ΔPE (J/m) of a run.
fn pe(r: &RunRecord) -> Option<f64> {
    Some(r.summary.energy().potential_energy)
}

/// W/ΔPE of a run; none where ΔPE is not positive.
fn ratio(r: &RunRecord) -> Option<f64> {
    let e = r.summary.energy();
    (e.potential_energy > 0.0).then(|| e.work / e.potential_energy)
}

fn sail_to_keel(r: &RunRecord) -> f64 {
    r.metrics.sail_ice_area / r.metrics.keel_ice_area
}

/// W/ΔPE of run `r` at its sample nearest to `t` (s).
fn ratio_at(r: &RunRecord, t: f64) -> Option<f64> {
    let s = r
        .samples
        .iter()
        .min_by(|a, b| (a.time - t).abs().total_cmp(&(b.time - t).abs()))?;
    let e = s.energy();
    (e.potential_energy > 0.0).then(|| e.work / e.potential_energy)
}

fn stat(runs: &[&RunRecord], f: impl Fn(&RunRecord) -> Option<f64>) -> Stat {
    let xs: Vec<f64> = runs.iter().filter_map(|r| f(r)).collect();
    Stat::of(&xs)
}

/// `mean unit [lo, hi] (n = …)` with `digits` decimals, values scaled by `scale`.
fn interval(s: &Stat, scale: f64, digits: usize, unit: &str) -> String {
    let h = s.half_width_95();
    format!(
        "{:.d$}{unit} [{:.d$}, {:.d$}] (n = {})",
        s.mean * scale,
        (s.mean - h) * scale,
        (s.mean + h) * scale,
        s.n,
        d = digits
    )
}

/// The Welch difference `b − a` as `(diff, lo, hi)`.
fn difference(a: &Stat, b: &Stat) -> (f64, f64, f64) {
    let (d, h) = a.welch_difference(b);
    (d, d - h, d + h)
}

/// Least-squares slope of `y` on `x` with its 95 % interval `(slope, lo, hi)`.
fn slope(x: &[f64], y: &[f64]) -> (f64, f64, f64) {
    let n = x.len() as f64;
    let (mx, my) = (x.iter().sum::<f64>() / n, y.iter().sum::<f64>() / n);
    let sxx: f64 = x.iter().map(|a| (a - mx).powi(2)).sum();
    let sxy: f64 = x.iter().zip(y).map(|(a, b)| (a - mx) * (b - my)).sum();
    let b = sxy / sxx;
    let a = my - b * mx;
    let sse: f64 = x.iter().zip(y).map(|(u, v)| (v - a - b * u).powi(2)).sum();
    let se = (sse / (n - 2.0) / sxx).sqrt();
    let h = student_t_quantile(0.975, n - 2.0) * se;
    (b, b - h, b + h)
}

/// The statement table of `records` (every run of the paper's scenes among them), needing at
/// least `min_seeds` runs of each ensemble it reads. `base` is the model whose findings are
/// tested: the Figure 5 scene (the default scene, `data/scenes/figure5.toml`) or a variant of
/// it, e.g. with the former 20-m floe; each of the paper's points moves only its friction,
/// modulus or speed from it.
pub fn findings(
    records: &[RunRecord],
    min_seeds: usize,
    base: &Scene,
) -> Result<Vec<Finding>, MissingRuns> {
    let need = min_seeds.max(2);
    let sel = |p: Point| select(records, base, p, need);
    let mut out = Vec::new();
    let fig5 = sel(FIGURE5)?;

    // (a), (b): where the energy goes at the Figure 5 point.
    energy::findings(&fig5, &mut out);

    // (c) and (d): low friction, and the trends with μ.
    friction::findings(&sel, &fig5, &mut out)?;

    // (e) The modulus ×10.
    modulus_speed::modulus(&sel, &fig5, &mut out)?;

    // (f) The speed.
    modulus_speed::speed(&sel, &fig5, &mut out)?;

    // (g) W/ΔPE over primary ridge growth, at the Figure 5 point.
    energy::growth(&fig5, &mut out);
    Ok(out)
}

/// The statement table as Markdown: one row per finding and a count of the verdicts.
pub fn markdown(rows: &[Finding]) -> String {
    let mut s = String::from(
        "| item | the paper | ours (mean [95 % interval]) | verdict |\n|---|---|---|---|\n",
    );
    for r in rows {
        let _ = writeln!(
            s,
            "| {} | {} | {} | {} |",
            r.item,
            r.paper,
            r.ours,
            r.verdict.as_str()
        );
    }
    let count = |v: Verdict| rows.iter().filter(|r| r.verdict == v).count();
    let _ = writeln!(
        s,
        "\n{} agree, {} disagree, {} unresolved.",
        count(Verdict::Agree),
        count(Verdict::Disagree),
        count(Verdict::Unresolved)
    );
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The verdicts of an interval against a one-sided and a two-sided bound.
    #[test]
    fn verdicts_follow_the_interval() {
        assert_eq!(Verdict::of(0.1, 0.2, 0.0, true), Verdict::Agree);
        assert_eq!(Verdict::of(-0.2, -0.1, 0.0, true), Verdict::Disagree);
        assert_eq!(Verdict::of(-0.1, 0.1, 0.0, true), Verdict::Unresolved);
        assert_eq!(Verdict::of(0.01, 0.04, 0.05, false), Verdict::Agree);
        assert_eq!(Verdict::of(0.06, 0.09, 0.05, false), Verdict::Disagree);
        assert_eq!(Verdict::within(-0.1, 0.2, 0.25), Verdict::Agree);
        assert_eq!(Verdict::within(0.3, 0.5, 0.25), Verdict::Disagree);
        assert_eq!(Verdict::within(0.1, 0.3, 0.25), Verdict::Unresolved);
        assert_eq!(Verdict::of(f64::NAN, 1.0, 0.0, true), Verdict::Unresolved);
    }

    /// The slope interval of exact data is the slope itself; of y = 2x + noise it covers 2.
    #[test]
    fn slope_and_its_interval() {
        let x = [0.4, 0.6, 0.8, 1.0, 0.4, 0.6, 0.8, 1.0];
        let y: Vec<f64> = x.iter().map(|v| 3.0 - 2.0 * v).collect();
        let (b, lo, hi) = slope(&x, &y);
        assert!((b + 2.0).abs() < 1e-12 && (hi - lo).abs() < 1e-9);
        let noise = [0.1, -0.1, 0.05, -0.05, -0.1, 0.1, -0.05, 0.05];
        let y: Vec<f64> = x.iter().zip(noise).map(|(v, e)| 2.0 * v + e).collect();
        let (b, lo, hi) = slope(&x, &y);
        assert!(lo < 2.0 && 2.0 < hi && lo < b && b < hi, "{lo} {b} {hi}");
    }
}
