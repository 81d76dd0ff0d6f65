//! Findings a, b and g of the statement table: where the energy goes at the Figure 5 point
//! (the other sinks, Φ_i as eq (12) defines it) and W/ΔPE over primary ridge growth
//! (Hopkins 1994, "Energetics" and Conclusions).

use super::*;

/// Appends findings a and b to `out` from `fig5`, the runs of the Figure 5 point.
pub(super) fn findings(fig5: &[&RunRecord], out: &mut Vec<Finding>) {
    // (a) Sinks other than Φ_f, Φ_i, ΔPE and kinetic energy.
    let share = |term: fn(&EnergyBudget) -> f64| {
        let s = stat(fig5, |r| {
            let e = r.summary.energy();
            Some(term(&e) / e.work)
        });
        100.0 * s.mean
    };
    let s = stat(fig5, |r| Some(other_sinks_fraction(r)));
    let h = s.half_width_95();
    out.push(Finding {
        item: "a",
        paper: "water drag, kinetic energy and viscous boundary forces \"in total, typically \
                amount to less than 5% of the energy consumed\" (Energetics; Figure 5 point)",
        ours: format!(
            "(W − Φ_f − Φ_i − ΔPE − ΔKE)/W = {}; drag {:.1} %, boundary {:.1} %, joints \
             {:.1} %, fracture {:.1} %",
            interval(&s, 100.0, 1, " %"),
            share(|e| e.drag_dissipation),
            share(|e| e.boundary_dissipation),
            share(|e| e.joint_dissipation),
            share(|e| e.fracture_dissipation),
        ),
        verdict: Verdict::of(s.mean - h, s.mean + h, OTHER_SINKS_BOUND, false),
    });

    // (b) Φ_i as eq (12) defines it, with its parts.
    let recorded = fig5
        .iter()
        .all(|r| r.summary.energy().normal_contact_work != 0.0);
    let total = stat(fig5, |r| Some(phi_i(r) / r.summary.energy().work));
    let visc = stat(fig5, |r| {
        let e = r.summary.energy();
        Some(e.viscous_dissipation / e.work)
    });
    out.push(Finding {
        item: "b",
        paper: "Φ_i \"is the net work performed by the normal contact forces at each point of \
                contact\" (eq 12)",
        ours: format!(
            "Φ_i/W = {}: viscous {:.2} %, elastic {:.2} %{}",
            interval(&total, 100.0, 2, " %"),
            100.0 * visc.mean,
            100.0 * (total.mean - visc.mean),
            if recorded {
                ""
            } else {
                " (records without `normal_contact_work`: elastic part read as the contact hysteresis)"
            }
        ),
        verdict: if recorded {
            Verdict::Agree
        } else {
            Verdict::Unresolved
        },
    });
}

/// Appends finding g to `out` from `fig5`, the runs of the Figure 5 point.
pub(super) fn growth(fig5: &[&RunRecord], out: &mut Vec<Finding>) {
    // (g) W/ΔPE over primary ridge growth, at the Figure 5 point.
    let s = stat(fig5, |r| {
        let t = r.scene.duration;
        Some(ratio_at(r, t)? / ratio_at(r, 0.25 * t)? - 1.0)
    });
    let h = s.half_width_95();
    out.push(Finding {
        item: "g",
        paper: "\"for a given ice thickness and set of friction coefficients the ratio remains \
                nearly constant over the period of primary ridge growth\" (Conclusions; ours: \
                within ±25 % from a quarter of the run to its end)",
        ours: format!(
            "W/ΔPE at the end over W/ΔPE at a quarter of the run, less 1: {}",
            interval(&s, 100.0, 0, " %")
        ),
        verdict: Verdict::within(s.mean - h, s.mean + h, NEARLY_CONSTANT),
    });
}
