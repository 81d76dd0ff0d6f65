//! The checks around one column's ridging step: its inputs (finite, non-negative, a valid
//! forcing and bounds) before, its state and ocean fluxes (finite, physical) after.

use super::{Closing, ColumnMut, OceanFluxes, StepForcing};
use crate::ColumnError;

fn not_finite(var: &'static str, category: Option<usize>, value: f64) -> ColumnError {
    ColumnError::NotFinite {
        var,
        category,
        value,
    }
}

pub(super) fn check_inputs(
    col: &ColumnMut<'_>,
    hin_max: &[f64],
    forcing: &StepForcing,
) -> Result<(), ColumnError> {
    for (var, xs) in [
        ("aicen", &*col.aicen),
        ("vicen", &*col.vicen),
        ("vsnon", &*col.vsnon),
    ] {
        for (n, &x) in xs.iter().enumerate() {
            if !x.is_finite() {
                return Err(not_finite(var, Some(n), x));
            }
            if x < 0.0 {
                return Err(ColumnError::Negative {
                    var,
                    category: Some(n),
                    value: x,
                });
            }
        }
    }
    let nt = if col.aicen.is_empty() {
        0
    } else {
        col.trcrn.len() / col.aicen.len()
    };
    for (i, &x) in col.trcrn.iter().enumerate() {
        if !x.is_finite() {
            return Err(ColumnError::TracerNotFinite {
                tracer: i % nt.max(1),
                category: i / nt.max(1),
                value: x,
            });
        }
    }
    let (a, b, na, nb) = match forcing.closing {
        Closing::Deformation { convergence, shear } => (convergence, shear, "convergence", "shear"),
        Closing::Rates { closing, opening } => (closing, opening, "closing", "opening"),
    };
    for (var, x, nonneg) in [
        ("aice0", *col.aice0, true),
        ("aice", *col.aice, false),
        (na, a, true),
        (nb, b, true),
        ("dt", forcing.dt, true),
        ("tf", forcing.tf, false),
    ] {
        if !x.is_finite() {
            return Err(not_finite(var, None, x));
        }
        if nonneg && x < 0.0 {
            return Err(ColumnError::Negative {
                var,
                category: None,
                value: x,
            });
        }
    }
    if forcing.dt <= 0.0 {
        return Err(ColumnError::Negative {
            var: "dt",
            category: None,
            value: forcing.dt,
        });
    }
    if forcing.ndtd == 0 {
        return Err(ColumnError::Negative {
            var: "ndtd",
            category: None,
            value: 0.0,
        });
    }
    for (n, &h) in hin_max.iter().enumerate() {
        if !h.is_finite() {
            return Err(not_finite("hin_max", Some(n), h));
        }
    }
    if hin_max[0] < 0.0 {
        return Err(ColumnError::Negative {
            var: "hin_max",
            category: Some(0),
            value: hin_max[0],
        });
    }
    Ok(())
}

pub(super) fn check_outputs(
    col: &ColumnMut<'_>,
    f: &OceanFluxes,
    n_bio: usize,
) -> Result<(), ColumnError> {
    for (var, xs) in [
        ("aicen", &*col.aicen),
        ("vicen", &*col.vicen),
        ("vsnon", &*col.vsnon),
    ] {
        for (n, &x) in xs.iter().enumerate() {
            if !x.is_finite() || x < 0.0 {
                return Err(ColumnError::Unphysical {
                    var,
                    category: Some(n),
                    value: x,
                });
            }
        }
    }
    let aero = f.faero_ocn.iter().map(|&x| ("faero_ocn", x));
    let iso = f.fiso_ocn.iter().map(|&x| ("fiso_ocn", x));
    let bio = f.flux_bio[..n_bio].iter().map(|&x| ("flux_bio", x));
    for (var, x) in [
        ("aice0", *col.aice0),
        ("fresh", f.fresh),
        ("fsalt", f.fsalt),
        ("fhocn", f.fhocn),
        ("fpond", f.fpond),
    ]
    .into_iter()
    .chain(aero)
    .chain(iso)
    .chain(bio)
    {
        if !x.is_finite() || (var == "aice0" && x < 0.0) {
            return Err(ColumnError::Unphysical {
                var,
                category: None,
                value: x,
            });
        }
    }
    for (i, &x) in col.trcrn.iter().enumerate() {
        if !x.is_finite() {
            let nt = col.trcrn.len() / col.aicen.len();
            return Err(ColumnError::TracerNotFinite {
                tracer: i % nt,
                category: i / nt,
                value: x,
            });
        }
    }
    Ok(())
}
