//! Thickness distribution of newly ridged ice from ice of thickness h (Hibler 1980;
//! Lipscomb et al. 2007; CICE/Icepack `ridge_itd`, `ridge_shift`, `icepack_ice_strength`).
//!
//! Both forms start at h_min = min(2h, h + maxraft) (thin ice rafts, thick ice is not forced
//! to). Uniform (Hibler 1980): between h_min and h_max = 2√(H*·h), mean (h_min + h_max)/2,
//! ⟨h_r²⟩ = (h_max³ − h_min³)/(3(h_max − h_min)). Exponential (Lipscomb et al. 2007):
//! ∝ exp(−(h_r − h_min)/λ), λ = μ√h, mean h_min + λ, ⟨h_r²⟩ = h_min² + 2h_minλ + 2λ².
//! The ratio k = ⟨h_r⟩/h is the area lost per unit ridged area (area factor 1/k, volume
//! factor 1), and 1 − 1/k is the net-to-gross closing contribution of that category.

// Several parallel per-category arrays are indexed by the category number, as in CICE.
#![allow(clippy::needless_range_loop)]

use super::params::{ItdParams, Redistribution};

/// Ridged-ice distribution from one category.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RidgeGeometry {
    /// Thickness of the ridging ice h = vicen/aicen (m), before any clamping.
    pub hi: f64,
    /// Minimum ridge thickness h_min (m).
    pub hrmin: f64,
    /// Maximum ridge thickness h_max (m), uniform form only (0 otherwise).
    pub hrmax: f64,
    /// E-folding thickness λ (m), exponential form only (0 otherwise).
    pub hrexp: f64,
    /// Mean ridge thickness over ridging-ice thickness k (dimensionless, > 1).
    pub krdg: f64,
    /// μ_rdg came from a table queried outside its thickness range (the end value used).
    pub mu_clamped: bool,
}

impl RidgeGeometry {
    /// Geometry of a category with no (or ≤ `puny`) area: k = 1, thicknesses 0 (as CICE).
    pub const EMPTY: RidgeGeometry = RidgeGeometry {
        hi: 0.0,
        hrmin: 0.0,
        hrmax: 0.0,
        hrexp: 0.0,
        krdg: 1.0,
        mu_clamped: false,
    };
}

/// Ridge geometry for a category of area `ain` (dimensionless) and volume `vin` (m).
/// Returns [`RidgeGeometry::EMPTY`] when `ain ≤ puny`.
#[inline]
pub fn ridge_geometry(
    kind: &Redistribution,
    params: &ItdParams,
    ain: f64,
    vin: f64,
) -> RidgeGeometry {
    if ain <= params.puny {
        return RidgeGeometry::EMPTY;
    }
    let hi = vin / ain;
    match kind {
        Redistribution::Uniform => {
            let hrmin = f64::min(2.0 * hi, hi + params.maxraft);
            let hrmax = f64::max(2.0 * (params.hstar * hi).sqrt(), hrmin + params.puny);
            let hrmean = 0.5 * (hrmin + hrmax);
            RidgeGeometry {
                hi,
                hrmin,
                hrmax,
                hrexp: 0.0,
                krdg: hrmean / hi,
                mu_clamped: false,
            }
        }
        Redistribution::Exponential | Redistribution::Table(_) => {
            let raw = hi;
            let hi = f64::max(hi, params.puny);
            let hrmin = f64::min(2.0 * hi, hi + params.maxraft);
            // μ_rdg at the ridging ice's own thickness (as the table's lead ice).
            let (mu, mu_clamped) = match kind {
                Redistribution::Table(t) => {
                    let l = t.lookup(raw);
                    (l.value, l.clamped)
                }
                _ => (params.mu_rdg, false),
            };
            let hrexp = mu * hi.sqrt();
            RidgeGeometry {
                hi: raw,
                hrmin,
                hrmax: 0.0,
                hrexp,
                krdg: (hrmin + hrexp) / hi,
                mu_clamped,
            }
        }
    }
}

/// Mean square thickness ⟨h_r²⟩ (m²) of the ridged ice of geometry `g`.
#[inline]
pub fn mean_square_ridge_thickness(kind: &Redistribution, g: &RidgeGeometry) -> f64 {
    match kind {
        Redistribution::Uniform => {
            // x**3 as gfortran evaluates it: (x*x)*x.
            let cube = |x: f64| x * x * x;
            (1.0 / 3.0) * (cube(g.hrmax) - cube(g.hrmin)) / (g.hrmax - g.hrmin)
        }
        Redistribution::Exponential | Redistribution::Table(_) => {
            g.hrmin * g.hrmin + 2.0 * g.hrmin * g.hrexp + 2.0 * g.hrexp * g.hrexp
        }
    }
}

/// Fractions (f_area, f_volume) (dimensionless) of the new ridges of geometry `g` that fall
/// between the bounds `h_lo` and `h_hi` (m) of a receiving category. For the thickest
/// category pass `last = true`: the exponential form then integrates to infinity, and the
/// caller passes `params.big` as `h_hi` for the uniform form (as CICE's `ridge_prep`).
#[inline]
pub fn category_fractions(
    kind: &Redistribution,
    params: &ItdParams,
    g: &RidgeGeometry,
    h_lo: f64,
    h_hi: f64,
    last: bool,
) -> (f64, f64) {
    match kind {
        Redistribution::Uniform => {
            let (hl, hr) = if g.hrmin >= h_hi || g.hrmax <= h_lo {
                (0.0, 0.0)
            } else {
                (f64::max(g.hrmin, h_lo), f64::min(g.hrmax, h_hi))
            };
            let dhr = g.hrmax - g.hrmin;
            let dhr2 = g.hrmax * g.hrmax - g.hrmin * g.hrmin;
            ((hr - hl) / dhr, (hr * hr - hl * hl) / dhr2)
        }
        Redistribution::Exponential | Redistribution::Table(_) => {
            let hi1 = g.hrmin;
            let hexp = g.hrexp;
            if !last {
                if hi1 >= h_hi {
                    (0.0, 0.0)
                } else {
                    let hl = f64::max(hi1, h_lo);
                    let hr = h_hi;
                    let argl = f64::min((hl - hi1) / hexp, params.exp_argmax);
                    let argr = f64::min((hr - hi1) / hexp, params.exp_argmax);
                    let expl = (-argl).exp();
                    let expr = (-argr).exp();
                    let farea = expl - expr;
                    let fvol = ((hl + hexp) * expl - (hr + hexp) * expr) / (hi1 + hexp);
                    // pressridge: beyond the exp_argmax cut-off both exponentials are e^-100
                    // and Icepack's volume fraction becomes a negative e^-100 residue, which
                    // makes empty categories' volume negative. Nothing lands there.
                    if argl >= params.exp_argmax {
                        (farea, 0.0)
                    } else if argr >= params.exp_argmax {
                        (farea, f64::max(fvol, 0.0))
                    } else {
                        (farea, fvol)
                    }
                }
            } else {
                let hl = f64::max(hi1, h_lo);
                let expl = (-f64::min((hl - hi1) / hexp, params.exp_argmax)).exp();
                (expl, (hl + hexp) * expl / (hi1 + hexp))
            }
        }
    }
}

/// Ratio of net area removed to gross area participating, a_P0 + Σ a_Pn(1 − 1/k_n)
/// (dimensionless; CICE `aksum`).
#[inline]
pub fn net_to_gross(apartic: &[f64], krdg: &[f64]) -> f64 {
    let mut aksum = apartic[0];
    for (a, k) in apartic[1..].iter().zip(krdg) {
        aksum += a * (1.0 - 1.0 / k);
    }
    aksum
}

/// [`category_fractions`] for every receiving category at once: `farea[nr]`, `fvol[nr]`
/// (dimensionless) for the bounds `hin_max[0..=ncat]` (m), the top one replaced by `top`.
/// Same numbers to the bit; the exponential form evaluates one exponential per bound instead
/// of two per category (the right end of one category is the left end of the next).
pub fn category_fractions_all(
    kind: &Redistribution,
    params: &ItdParams,
    g: &RidgeGeometry,
    hin_max: &[f64],
    top: f64,
    farea: &mut [f64],
    fvol: &mut [f64],
) {
    let ncat = farea.len();
    match kind {
        Redistribution::Uniform => {
            for nr in 0..ncat {
                let h_hi = if nr + 1 == ncat { top } else { hin_max[nr + 1] };
                (farea[nr], fvol[nr]) =
                    category_fractions(kind, params, g, hin_max[nr], h_hi, nr + 1 == ncat);
            }
        }
        Redistribution::Exponential | Redistribution::Table(_) => {
            let hi1 = g.hrmin;
            let hexp = g.hrexp;
            let cap = params.exp_argmax;
            // Left end of category nr: argument and exponential at max(hi1, hin_max[nr]).
            let left = |b: usize| -> (f64, f64, f64) {
                let hl = f64::max(hi1, hin_max[b]);
                let arg = f64::min((hl - hi1) / hexp, cap);
                // exp(-0) = 1 exactly: skip the call for bounds below the ridges.
                (hl, arg, if arg == 0.0 { 1.0 } else { (-arg).exp() })
            };
            let (mut hl, mut argl, mut expl) = left(0);
            for nr in 0..ncat {
                if nr + 1 == ncat {
                    farea[nr] = expl;
                    fvol[nr] = (hl + hexp) * expl / (hi1 + hexp);
                    break;
                }
                let hr = hin_max[nr + 1];
                let next = left(nr + 1);
                if hi1 >= hr {
                    farea[nr] = 0.0;
                    fvol[nr] = 0.0;
                } else {
                    // hr > hi1, so the next left end is hr itself: its exponential is this
                    // category's right one.
                    let (argr, expr) = (next.1, next.2);
                    let fa = expl - expr;
                    let fv = ((hl + hexp) * expl - (hr + hexp) * expr) / (hi1 + hexp);
                    farea[nr] = fa;
                    fvol[nr] = if argl >= cap {
                        0.0
                    } else if argr >= cap {
                        f64::max(fv, 0.0)
                    } else {
                        fv
                    };
                }
                (hl, argl, expl) = next;
            }
        }
    }
}
