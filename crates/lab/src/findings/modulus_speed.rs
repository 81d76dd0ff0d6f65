//! Findings e and f of the statement table: the modulus ×10 and the speed ÷4 against the
//! Figure 5 point (Hopkins 1994, "Effects of Elastic Modulus" and "Effects of Velocity").

use super::*;

/// Appends findings e (E = 1 GPa against the Figure 5 point's 0.1 GPa) to `out`; `sel` gives
/// the runs of a point, and `fig5` those of the Figure 5 point.
pub(super) fn modulus<'a>(
    sel: &dyn Fn(Point) -> Result<Vec<&'a RunRecord>, MissingRuns>,
    fig5: &[&'a RunRecord],
    out: &mut Vec<Finding>,
) -> Result<(), MissingRuns> {
    let stiff = sel(Point {
        e_top: 1.0e9,
        e_bottom: 6.7e8,
        ..FIGURE5
    })?;
    for (name, paper, f, lower) in [
        (
            "L/h",
            "with the higher modulus \"the blocks were somewhat smaller\" (Effects of modulus)",
            (|r: &RunRecord| Some(r.metrics.length_to_thickness)) as fn(&RunRecord) -> Option<f64>,
            Some(true),
        ),
        (
            "W (kJ/m)",
            "\"the average energy consumed using the highest modulus was lower\"",
            |r: &RunRecord| Some(r.summary.energy().work / 1e3),
            Some(true),
        ),
        (
            evidence::SAIL_AT_MODULUS,
            "\"there were no significant differences between the final profiles\"",
            |r: &RunRecord| Some(r.metrics.max_sail_height),
            None,
        ),
        (
            "max keel depth (m)",
            "\"there were no significant differences between the final profiles\"",
            |r: &RunRecord| Some(r.metrics.max_keel_depth),
            None,
        ),
    ] {
        let (a, b) = (stat(fig5, f), stat(&stiff, f));
        let (d, lo, hi) = difference(&a, &b);
        out.push(Finding {
            item: "e",
            paper,
            ours: format!(
                "{name} at E = 1 GPa minus 0.1 GPa: {d:+.2} [{lo:+.2}, {hi:+.2}] ({:.2} against \
                 {:.2}; n = {}, {})",
                b.mean, a.mean, b.n, a.n
            ),
            verdict: match lower {
                Some(_) => Verdict::of(lo, hi, 0.0, false),
                None if lo > 0.0 || hi < 0.0 => Verdict::Disagree,
                None => Verdict::Agree,
            },
        });
    }
    let s = stat(&stiff, |r| {
        let e = r.summary.energy();
        Some(e.fracture_dissipation / e.work)
    });
    let h = s.half_width_95();
    out.push(Finding {
        item: "e",
        paper: "\"breakage, per se, consumed little energy\" (ours: below 5 % of W at 1 GPa)",
        ours: format!("fracture/W at E = 1 GPa: {}", interval(&s, 100.0, 2, " %")),
        verdict: Verdict::of(s.mean - h, s.mean + h, BREAKAGE_BOUND, false),
    });
    Ok(())
}

/// Appends findings f (6.25 cm/s against the Figure 5 point's 25 cm/s) to `out`; `sel` gives
/// the runs of a point, and `fig5` those of the Figure 5 point.
pub(super) fn speed<'a>(
    sel: &dyn Fn(Point) -> Result<Vec<&'a RunRecord>, MissingRuns>,
    fig5: &[&'a RunRecord],
    out: &mut Vec<Finding>,
) -> Result<(), MissingRuns> {
    let slow = sel(Point {
        speed: 0.0625,
        ..FIGURE5
    })?;
    for (name, f) in [
        (
            "W",
            (|r: &RunRecord| Some(r.summary.energy().work)) as fn(&RunRecord) -> Option<f64>,
        ),
        ("ΔPE", |r: &RunRecord| {
            Some(r.summary.energy().potential_energy)
        }),
        ("max keel depth", |r: &RunRecord| {
            Some(r.metrics.max_keel_depth)
        }),
        ("max sail height", |r: &RunRecord| {
            Some(r.metrics.max_sail_height)
        }),
    ] {
        let (a, b) = (stat(fig5, f), stat(&slow, f));
        let (d, lo, hi) = difference(&a, &b);
        out.push(Finding {
            item: "f",
            paper: "at 6.25 and 25 cm/s \"the average final ridge profiles and energetics in the \
                    two sets of experiments were nearly identical\" (ours: within ±15 %)",
            ours: format!(
                "{name} at 6.25 cm/s minus 25 cm/s: {:+.0} % [{:+.0}, {:+.0}] (n = {}, {})",
                100.0 * d / a.mean,
                100.0 * lo / a.mean,
                100.0 * hi / a.mean,
                b.n,
                a.n
            ),
            verdict: Verdict::within(lo / a.mean, hi / a.mean, NEARLY_IDENTICAL),
        });
    }
    let fi = |r: &RunRecord| Some(phi_i(r) / r.summary.energy().work);
    let (a, b) = (stat(&slow, fi), stat(fig5, fi));
    let (d, lo, hi) = difference(&a, &b);
    out.push(Finding {
        item: "f",
        paper: "\"the inelastic dissipation increased slightly at 25 cm/s\"",
        ours: format!(
            "Φ_i/W at 25 cm/s minus 6.25 cm/s: {:+.2} [{:+.2}, {:+.2}] points of % (n = {}, {})",
            100.0 * d,
            100.0 * lo,
            100.0 * hi,
            b.n,
            a.n
        ),
        verdict: Verdict::of(lo, hi, 0.0, true),
    });
    Ok(())
}
