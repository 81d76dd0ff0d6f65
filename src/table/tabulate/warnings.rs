//! What is missing or not a number in a ridging table's fits, in words.

use super::{RidgeTable, SetFits};
use ndarray::s;

/// What is missing or not a number in the fits of a table, one sentence each: an empty fit
/// table (no fit at all), a set without a pooled fit, a thickness without its own fit, a fit
/// coefficient or C_f that is NaN. Empty when every fit is there and finite.
pub fn fit_warnings(t: &RidgeTable) -> Vec<String> {
    let mut out = Vec::new();
    let name = |si: usize| {
        if t.sets[si].is_empty() {
            "all runs".to_string()
        } else {
            format!("set `{}`", t.sets[si])
        }
    };
    let finite = |f: &SetFits| {
        [
            f.work.a,
            f.work.b,
            f.potential_energy.a,
            f.potential_energy.b,
        ]
        .iter()
        .all(|v| v.is_finite())
    };
    if t.pooled.iter().all(Option::is_none) && t.fits.iter().all(Option::is_none) {
        out.push(
            "the fit table is empty: no set or thickness had enough samples with V > 0 for \
             eqs (13)-(14) (runs too short for the sample interval?)"
                .to_string(),
        );
        return out;
    }
    for si in 0..t.sets.len() {
        match &t.pooled[si] {
            None => out.push(format!("{}: no pooled fit of eqs (13)-(14)", name(si))),
            Some(f) if !finite(f) => out.push(format!(
                "{}: the pooled fit is not a number (NaN)",
                name(si)
            )),
            _ => {}
        }
        for (hi, h) in t.thickness.iter().enumerate() {
            if t.runs.slice(s![si, hi, ..]).iter().all(|&n| n == 0) {
                continue;
            }
            match &t.fits[[si, hi]] {
                None => out.push(format!("{}, h = {h} m: no fit of eqs (13)-(14)", name(si))),
                Some(f) if !finite(f) => out.push(format!(
                    "{}, h = {h} m: the fit is not a number (NaN)",
                    name(si)
                )),
                _ => {}
            }
            if !t.cf[[si, hi]].is_finite() {
                out.push(format!(
                    "{}, h = {h} m: C_f is not a number (no run with ΔPE > 0 at its end)",
                    name(si)
                ));
            }
        }
    }
    out
}
