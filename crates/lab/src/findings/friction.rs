//! Findings c and d of the statement table: low friction (the sheet fails at the floe, sail
//! against keel, ΔPE) and the trends with μ at each μ_w (Hopkins 1994, "Effects of
//! Friction").

use super::*;

/// Appends findings c1–c3 and d (each μ_w) to `out`; `sel` gives the runs of a point, and
/// `fig5` those of the Figure 5 point.
pub(super) fn findings<'a>(
    sel: &dyn Fn(Point) -> Result<Vec<&'a RunRecord>, MissingRuns>,
    fig5: &[&'a RunRecord],
    out: &mut Vec<Finding>,
) -> Result<(), MissingRuns> {
    low_friction(sel, fig5, out)?;
    trends(sel, out)
}

/// Finding c1–c3: at μ = 0.4 the sheet fails at the floe, the sail against the keel, ΔPE.
fn low_friction<'a>(
    sel: &dyn Fn(Point) -> Result<Vec<&'a RunRecord>, MissingRuns>,
    fig5: &[&'a RunRecord],
    out: &mut Vec<Finding>,
) -> Result<(), MissingRuns> {
    // (c) Low friction ridges; sail relative to keel; ΔPE.
    let mut low = Vec::new();
    for mu_w in [0.6, 0.3] {
        low.extend(sel(Point::friction(0.4, mu_w))?);
    }
    // The measure's threshold, RAFTING_REACH, against the runs at the Figure 5 point, which
    // ridge against the floe as the paper's Figure 5 shows.
    let reach_high = fig5
        .iter()
        .filter_map(|r| r.summary.sheet_overrun_max)
        .fold(f64::NEG_INFINITY, f64::max);
    let rafted: Vec<f64> = low
        .iter()
        .filter_map(|r| match outcome(r, RAFTING_REACH) {
            Outcome::Rafted(x) => Some(x),
            _ => None,
        })
        .collect();
    let unknown = low
        .iter()
        .filter(|r| outcome(r, RAFTING_REACH) == Outcome::Unknown)
        .count();
    out.push(Finding {
        item: "c1",
        paper: "at μ = 0.4 the sheet fails against the floe and builds a ridge (Figure 6a: \
                keel building, then sail building; \"experiments with μ less than 0.4 resulted \
                in sails of enormous widths\")",
        ours: format!(
            "{} of {} runs at μ = 0.4 (μ_w = 0.6 and 0.3) rode over the floe: the intact sheet \
             passed its nose by more than {RAFTING_REACH} m{} (at most {reach_high:.2} m in the {} \
             runs at the Figure 5 point){}",
            rafted.len(),
            low.len(),
            if rafted.is_empty() {
                String::new()
            } else {
                format!(
                    ", by {:.1}–{:.1} m",
                    rafted.iter().copied().fold(f64::INFINITY, f64::min),
                    rafted.iter().copied().fold(f64::NEG_INFINITY, f64::max)
                )
            },
            fig5.len(),
            if unknown > 0 {
                format!("; {unknown} without the diagnostic")
            } else {
                String::new()
            }
        ),
        verdict: if !rafted.is_empty() {
            Verdict::Disagree
        } else if unknown > 0 {
            Verdict::Unresolved
        } else {
            Verdict::Agree
        },
    });
    for (item, paper, f, unit, scale) in [
        (
            "c2",
            "\"increasing the above-water coefficient of friction μ results in a smaller, more \
             compact sail and a larger keel\" (Effects of Friction)",
            &sail_to_keel as &dyn Fn(&RunRecord) -> f64,
            "sail/keel ice area",
            1.0,
        ),
        (
            "c3",
            "the results show a decrease in potential energy as μ is increased (Effects of \
             Friction)",
            &|r: &RunRecord| r.summary.energy().potential_energy,
            "ΔPE (kJ/m)",
            1e-3,
        ),
    ] {
        for mu_w in [0.6, 0.3] {
            let a = stat(&sel(Point::friction(1.0, mu_w))?, |r| Some(f(r)));
            let b = stat(&sel(Point::friction(0.4, mu_w))?, |r| Some(f(r)));
            let (d, lo, hi) = difference(&a, &b);
            out.push(Finding {
                item,
                paper,
                ours: format!(
                    "μ_w = {mu_w}: {unit} at μ = 0.4 minus at μ = 1.0: {:.3} [{:.3}, {:.3}] \
                     ({:.3} against {:.3}; n = {}, {})",
                    d * scale,
                    lo * scale,
                    hi * scale,
                    b.mean * scale,
                    a.mean * scale,
                    b.n,
                    a.n
                ),
                verdict: Verdict::of(lo, hi, 0.0, true),
            });
        }
    }
    Ok(())
}

/// Finding d at each μ_w: the trends with μ, the spread of W, μ_w and the keel slope.
fn trends<'a>(
    sel: &dyn Fn(Point) -> Result<Vec<&'a RunRecord>, MissingRuns>,
    out: &mut Vec<Finding>,
) -> Result<(), MissingRuns> {
    // (d) Trends with μ at each μ_w; the spread of W; μ_w and the keel slope.
    for mu_w in [0.6, 0.3] {
        let mut runs = Vec::new();
        for mu in [0.4, 0.6, 0.8, 1.0] {
            runs.extend(sel(Point::friction(mu, mu_w))?);
        }
        let x: Vec<f64> = runs.iter().map(|r| r.scene.contact.mu).collect();
        for (name, paper, f, rising, scale, unit) in [
            (
                "W",
                "\"a decrease in work ... as μ is increased\"; \"energy consumption is inversely \
                 related to μ\" (Effects of Friction, Figure 9)",
                &work as &dyn Fn(&RunRecord) -> Option<f64>,
                false,
                1e-3,
                "kJ/m per unit μ",
            ),
            (
                "ΔPE",
                "\"a decrease in ... potential energy as μ is increased\" (Effects of Friction)",
                &pe,
                false,
                1e-3,
                "kJ/m per unit μ",
            ),
            (
                "W/ΔPE",
                "increasing friction \"increases the ratio of work to potential energy\" \
                 (Effects of Friction)",
                &ratio,
                true,
                1.0,
                "per unit μ",
            ),
        ] {
            let (xs, ys): (Vec<f64>, Vec<f64>) = x
                .iter()
                .zip(&runs)
                .filter_map(|(&a, r)| f(r).map(|y| (a, y)))
                .unzip();
            let (b, lo, hi) = slope(&xs, &ys);
            out.push(Finding {
                item: "d1",
                paper,
                ours: format!(
                    "μ_w = {mu_w}: slope of {name} over μ = 0.4–1.0: {:.1} [{:.1}, {:.1}] {unit} \
                     (n = {})",
                    b * scale,
                    lo * scale,
                    hi * scale,
                    xs.len()
                ),
                verdict: Verdict::of(lo, hi, 0.0, rising),
            });
        }
        let a = stat(&sel(Point::friction(1.0, mu_w))?, work);
        let b = stat(&sel(Point::friction(0.4, mu_w))?, work);
        let (d, lo, hi) = difference(&a, &b);
        out.push(Finding {
            item: "d2",
            paper: "\"the difference in energy consumption between the high- and low-friction \
                    experiments for a given value of μ_w was small\" (Effects of Friction; ours: \
                    within ±25 % of W at μ = 1.0)",
            ours: format!(
                "μ_w = {mu_w}: W(μ = 0.4) − W(μ = 1.0) = {:+.0} % [{:+.0}, {:+.0}] of W(μ = 1.0)",
                100.0 * d / a.mean,
                100.0 * lo / a.mean,
                100.0 * hi / a.mean
            ),
            verdict: Verdict::within(lo / a.mean, hi / a.mean, SMALL_SPREAD),
        });
    }
    for (side, f) in [
        (
            "lead-side φ₁",
            (|r: &RunRecord| r.metrics.keel_slope_lead) as fn(&RunRecord) -> Option<f64>,
        ),
        ("floe-side φ₂", |r: &RunRecord| r.metrics.keel_slope_floe),
    ] {
        let (mut a, mut b) = (Vec::new(), Vec::new());
        for mu in [0.4, 0.6, 0.8, 1.0] {
            a.extend(sel(Point::friction(mu, 0.6))?);
            b.extend(sel(Point::friction(mu, 0.3))?);
        }
        let (sa, sb) = (stat(&a, f), stat(&b, f));
        let (d, lo, hi) = difference(&sa, &sb);
        out.push(Finding {
            item: "d3",
            paper: "\"the underwater coefficient affected the slope of the keel\" (Conclusions)",
            ours: format!(
                "keel slope {side} at μ_w = 0.3 minus at 0.6, all μ pooled: {d:+.1}° [{lo:+.1}, \
                 {hi:+.1}] (n = {}, {})",
                sb.n, sa.n
            ),
            verdict: if lo > 0.0 || hi < 0.0 {
                Verdict::Agree
            } else {
                Verdict::Unresolved
            },
        });
    }
    Ok(())
}
