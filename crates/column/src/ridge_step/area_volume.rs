//! One ridging step, as CICE/Icepack `ridge_ice` (with `ridge_prep`, `ridge_itd`,
//! `ridge_shift`, `asum_ridging`); Thorndike et al. (1975), Hibler (1980), Flato and Hibler
//! (1995), Lipscomb et al. (2007).
//!
//! The net closing rate is C_s·shear + convergence (1/s), raised if needed so that the
//! excess area (total area above 1, left by advection) is removed in `dt`; the opening rate
//! then makes the total area 1. Ice area a_Pn·(closing_net/aksum)·dt ridges out of each
//! category and its area/k_n and all its volume go into the categories that the ridged-ice
//! distribution overlaps. The rates are cut if a category would be emptied beyond its area,
//! and the step repeats (at most `nitermax` times) until the total area is 1 within `puny`.
//! Area and volume are conserved to round-off; no category becomes negative.

// Several parallel per-category arrays are indexed by the category number, as in CICE.
#![allow(clippy::needless_range_loop)]

use ndarray::{ArrayView1, ArrayViewMut1, ArrayViewMut2, Axis};

use crate::bounds::validate_bounds;
use crate::params::{ItdParams, Participation, Redistribution};
use crate::redistribution::{RidgeGeometry, category_fractions};
use crate::{ColumnError, ItdError, Workspace, check_column, check_len, check_shape};

/// Options of the ridging step; the default is CICE's (exponential, exponential).
#[derive(Debug, Clone, Copy, Default)]
pub struct RidgeOptions {
    /// Participation function (CICE `krdg_partic`).
    pub participation: Participation,
    /// Ridged-ice redistribution (CICE `krdg_redist`).
    pub redistribution: Redistribution,
    /// Physical constants and tunables.
    pub params: ItdParams,
}

/// Deformation forcing of one column over one step.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RidgeForcing {
    /// Convergence rate (1/s, ≥ 0): CICE `rdg_conv` = −min(div u, 0).
    pub convergence: f64,
    /// Shear term (1/s, ≥ 0): CICE `rdg_shear` = ½(Δ − |div u|); a fraction C_s ridges.
    pub shear: f64,
    /// Time step (s, > 0).
    pub dt: f64,
}

/// Rates and counters of one column's ridging step.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct RidgeDiagnostics {
    /// Net closing rate requested at the start of the step (1/s; `ridge_prep`'s
    /// `closing_net`, including the part that removes excess area).
    pub closing: f64,
    /// Area opened per unit time, summed over iterations (1/s).
    pub opening: f64,
    /// Rate of fractional area loss by ridging ice (1/s; CICE `dardg1dt`).
    pub dardg1dt: f64,
    /// Rate of fractional area gain by new ridges (1/s; CICE `dardg2dt`).
    pub dardg2dt: f64,
    /// Rate of ice volume ridged (m/s; CICE `dvirdgdt`).
    pub dvirdgdt: f64,
    /// Iterations used (1 in the common case).
    pub niter: usize,
    /// A category ridged with μ_rdg from a table queried outside its thickness range (the
    /// end value used; [`Redistribution::Table`]).
    pub mu_rdg_clamped: bool,
}

/// One ridging step of one column, in place.
///
/// `aicen` (dimensionless), `vicen` (m) have length `ncat = ws.ncat()`, `hin_max` (m) length
/// `ncat + 1`. The input total area `aice0 + Σ aicen` may exceed 1 (up to
/// [`ItdParams::max_area_before_ridging`]) or fall below it (divergence: water opens). A
/// column with no area above `puny` becomes open water (CICE divides by zero there).
/// Per-category areas and volumes ridged are left in `ws.ardg1n`, `ws.ardg2n`, `ws.virdgn`.
/// Does not allocate.
///
/// # Panics
/// If the slice lengths do not match `ws.ncat()` (the batched driver checks shapes first).
///
/// # Example
/// ```
/// use pressridge_column::{
///     CategoryBounds, RidgeForcing, RidgeOptions, Workspace, category_bounds, ridge_column,
/// };
///
/// let hin_max = category_bounds(&CategoryBounds::default(), 5)?; // 0, 0.6, 1.4, 2.4, 3.6, 5 m
/// let mut aicen = [0.2, 0.3, 0.2, 0.15, 0.05]; // dimensionless
/// let mut vicen = [0.06, 0.3, 0.38, 0.45, 0.2]; // m
/// let mut aice0 = 0.1; // open water
/// let volume = vicen.iter().sum::<f64>();
/// // One hour of convergence at 1e-6 1/s (about 9 % a day), no shear.
/// let forcing = RidgeForcing { convergence: 1e-6, shear: 0.0, dt: 3600.0 };
/// let mut ws = Workspace::new(5);
/// let opts = RidgeOptions::default(); // CICE's
/// let d = ridge_column(&mut aicen, &mut vicen, &mut aice0, &hin_max, forcing, &opts, &mut ws)?;
/// // The total area stays 1 and the ice volume is conserved, to round-off.
/// assert!((aice0 + aicen.iter().sum::<f64>() - 1.0).abs() < 1e-12);
/// assert!((vicen.iter().sum::<f64>() - volume).abs() < 1e-12);
/// // Rates (1/s) and the areas ridged out of each category (dimensionless).
/// assert!(d.dardg1dt > 0.0 && d.dardg2dt < d.dardg1dt && ws.ardg1n.iter().sum::<f64>() > 0.0);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn ridge_column(
    aicen: &mut [f64],
    vicen: &mut [f64],
    aice0: &mut f64,
    hin_max: &[f64],
    forcing: RidgeForcing,
    opts: &RidgeOptions,
    ws: &mut Workspace,
) -> Result<RidgeDiagnostics, ColumnError> {
    let ncat = ws.ncat;
    assert!(aicen.len() == ncat && vicen.len() == ncat && hin_max.len() == ncat + 1);
    let p = &opts.params;
    check_column(aicen, vicen, Some(*aice0))?;
    check_forcing(&forcing)?;
    let dt = forcing.dt;
    // Icepack's `asum_ridging` order (open water first, then each category): another order
    // changes aice0 and the opening rate in the last bit.
    let mut asum = asum_ridging(aicen, *aice0);
    if asum > p.max_area_before_ridging {
        return Err(ColumnError::AreaTooLarge {
            total: asum,
            max: p.max_area_before_ridging,
        });
    }

    // ridge_prep
    let mut closing_net = p.cs * forcing.shear + forcing.convergence;
    let mut divu_adv = (1.0 - asum) / dt;
    if divu_adv < 0.0 {
        closing_net = f64::max(closing_net, -divu_adv);
    }
    let mut opning = closing_net + divu_adv;

    let mut d = RidgeDiagnostics {
        closing: closing_net,
        ..Default::default()
    };
    let (mut ardg1, mut ardg2, mut virdg, mut aopen) = (0.0, 0.0, 0.0, 0.0);
    ws.ardg1n.fill(0.0);
    ws.ardg2n.fill(0.0);
    ws.virdgn.fill(0.0);

    let mut niter = 0;
    loop {
        niter += 1;
        // ridge_itd
        let aksum = ws.prepare_ridging(
            opts.participation,
            &opts.redistribution,
            p,
            *aice0,
            aicen,
            vicen,
        );

        // ridge_shift
        ws.aicen_init.copy_from_slice(aicen);
        ws.vicen_init.copy_from_slice(vicen);
        let closing_gross = close_and_open(
            &ws.apartic,
            aksum,
            closing_net,
            aicen,
            aice0,
            p.puny,
            dt,
            &mut opning,
        )?;
        aopen += opning * dt;

        for n in 0..ncat {
            let ap = ws.apartic[n + 1];
            let a_init = ws.aicen_init[n];
            if !(a_init > p.puny && ap > 0.0 && closing_gross > 0.0) {
                continue;
            }
            // ap * closing_gross * dt <= a_init up to round-off after the cuts above.
            let ardg1n = f64::min(a_init, ap * closing_gross * dt);
            let ardg2n = ardg1n / ws.krdg[n];
            let afrac = ardg1n / a_init;
            let virdgn = ws.vicen_init[n] * afrac;
            aicen[n] -= ardg1n;
            vicen[n] -= virdgn;
            ardg1 += ardg1n;
            ardg2 += ardg2n;
            virdg += virdgn;
            ws.ardg1n[n] += ardg1n;
            ws.ardg2n[n] += ardg2n;
            ws.virdgn[n] += virdgn;
            let g = RidgeGeometry {
                hi: ws.hi[n],
                hrmin: ws.hrmin[n],
                hrmax: ws.hrmax[n],
                hrexp: ws.hrexp[n],
                krdg: ws.krdg[n],
                mu_clamped: ws.mu_clamped[n],
            };
            d.mu_rdg_clamped |= g.mu_clamped;
            for nr in 0..ncat {
                let last = nr + 1 == ncat;
                let h_hi = if last { p.big } else { hin_max[nr + 1] };
                let (farea, fvol) =
                    category_fractions(&opts.redistribution, p, &g, hin_max[nr], h_hi, last);
                aicen[nr] += farea * ardg2n;
                vicen[nr] += fvol * virdgn;
            }
        }

        // Total area after this pass.
        asum = asum_ridging(aicen, *aice0);
        if (asum - 1.0).abs() < p.puny {
            break;
        }
        if niter >= p.nitermax {
            return Err(ColumnError::NoConvergence { niter, total: asum });
        }
        divu_adv = (1.0 - asum) / dt;
        closing_net = f64::max(0.0, -divu_adv);
        opning = f64::max(0.0, divu_adv);
    }

    let dti = 1.0 / dt;
    d.opening = aopen * dti;
    d.dardg1dt = ardg1 * dti;
    d.dardg2dt = ardg2 * dti;
    d.dvirdgdt = virdg * dti;
    d.niter = niter;
    Ok(d)
}

/// Icepack `ridge_shift`'s rates for one pass: the gross closing rate closing_net/aksum
/// (1/s; zero, with the missing area opened instead, when nothing can ridge), cut together
/// with the opening rate `opning` (1/s) so that neither open water nor any category above
/// `puny` loses more area than it has in `dt` (s), and the open water `aice0` updated.
/// Returns the gross closing rate; an open water that would still become negative beyond
/// `puny` is an error (round-off below it is set to 0). Shared by the area-and-volume step
/// and the complete step ([`super::ridge_step`]).
#[allow(clippy::too_many_arguments)]
pub(crate) fn close_and_open(
    apartic: &[f64],
    aksum: f64,
    closing_net: f64,
    aicen: &[f64],
    aice0: &mut f64,
    puny: f64,
    dt: f64,
    opning: &mut f64,
) -> Result<f64, ColumnError> {
    let mut closing_gross = if aksum > 0.0 {
        closing_net / aksum
    } else {
        // Nothing can ridge (Icepack divides by aksum = 0): only open the missing area.
        *opning = f64::max(0.0, (1.0 - asum_ridging(aicen, *aice0)) / dt);
        0.0
    };
    if apartic[0] > 0.0 {
        let wk1 = apartic[0] * closing_gross * dt;
        if wk1 > *aice0 {
            let tmpfac = *aice0 / wk1;
            closing_gross *= tmpfac;
            *opning *= tmpfac;
        }
    }
    for n in 0..aicen.len() {
        let ap = apartic[n + 1];
        if aicen[n] > puny && ap > 0.0 {
            let wk1 = ap * closing_gross * dt;
            if wk1 > aicen[n] {
                let tmpfac = aicen[n] / wk1;
                closing_gross *= tmpfac;
                *opning *= tmpfac;
            }
        }
    }
    *aice0 = *aice0 - apartic[0] * closing_gross * dt + *opning * dt;
    if *aice0 < -puny {
        return Err(ColumnError::OpenWaterExhausted { aice0: *aice0 });
    } else if *aice0 < 0.0 {
        *aice0 = 0.0; // round-off
    }
    Ok(closing_gross)
}

fn check_forcing(f: &RidgeForcing) -> Result<(), ColumnError> {
    for (var, value) in [
        ("convergence", f.convergence),
        ("shear", f.shear),
        ("dt", f.dt),
    ] {
        if !value.is_finite() {
            return Err(ColumnError::NotFinite {
                var,
                category: None,
                value,
            });
        }
        if value < 0.0 {
            return Err(ColumnError::Negative {
                var,
                category: None,
                value,
            });
        }
    }
    if f.dt == 0.0 {
        return Err(ColumnError::Negative {
            var: "dt",
            category: None,
            value: 0.0,
        });
    }
    Ok(())
}

/// Caller-owned outputs of [`ridge_batch`]: one value per column.
#[derive(Debug)]
pub struct RidgeRatesMut<'a> {
    /// Net closing rate (1/s).
    pub closing: ArrayViewMut1<'a, f64>,
    /// Opening rate (1/s).
    pub opening: ArrayViewMut1<'a, f64>,
    /// Rate of area loss by ridging ice (1/s).
    pub dardg1dt: ArrayViewMut1<'a, f64>,
    /// Rate of area gain by new ridges (1/s).
    pub dardg2dt: ArrayViewMut1<'a, f64>,
    /// Rate of ice volume ridged (m/s).
    pub dvirdgdt: ArrayViewMut1<'a, f64>,
    /// The value of every rate of a column [`RidgeBatchForcing::valid`] leaves out (NaN, a
    /// file's fill value).
    pub fill: f64,
}

/// The forcing of [`ridge_batch`]: per column the deformation (1/s, `ncol` values each, as
/// [`RidgeForcing`]) and which columns to step, one time step for all.
#[derive(Debug, Clone, Copy)]
pub struct RidgeBatchForcing<'a> {
    /// Convergence rate (1/s, ≥ 0), `ncol`.
    pub convergence: ArrayView1<'a, f64>,
    /// Shear term (1/s, ≥ 0), `ncol`.
    pub shear: ArrayView1<'a, f64>,
    /// Time step (s, > 0).
    pub dt: f64,
    /// Columns to step (`ncol`; land and missing data false): the others are left untouched
    /// and unvalidated, their rates set to [`RidgeRatesMut::fill`]. `None`: every column.
    pub valid: Option<ArrayView1<'a, bool>>,
}

/// One ridging step over `ncol` columns, in place.
///
/// `aicen`, `vicen`: shape `(ncat, ncol)`, any strides; `aice0`: length `ncol`; `hin_max`:
/// `ncat + 1` bounds (m) shared by all columns. Writes the rates into `rates`. Stops at the
/// first bad column with [`ItdError::Column`]; columns before it have been updated, the bad
/// one and those after are unchanged.
pub fn ridge_batch(
    mut aicen: ArrayViewMut2<f64>,
    mut vicen: ArrayViewMut2<f64>,
    mut aice0: ArrayViewMut1<f64>,
    hin_max: &[f64],
    forcing: RidgeBatchForcing<'_>,
    opts: &RidgeOptions,
    rates: RidgeRatesMut<'_>,
) -> Result<(), ItdError> {
    let RidgeBatchForcing {
        convergence,
        shear,
        dt,
        valid,
    } = forcing;
    let (ncat, ncol) = aicen.dim();
    check_shape("vicen", vicen.shape(), &[ncat, ncol])?;
    validate_bounds(hin_max)?;
    check_len("hin_max", hin_max.len(), ncat + 1)?;
    check_len("aice0", aice0.len(), ncol)?;
    check_len("convergence", convergence.len(), ncol)?;
    check_len("shear", shear.len(), ncol)?;
    let RidgeRatesMut {
        mut closing,
        mut opening,
        mut dardg1dt,
        mut dardg2dt,
        mut dvirdgdt,
        fill,
    } = rates;
    for (var, l) in [
        ("closing", closing.len()),
        ("opening", opening.len()),
        ("dardg1dt", dardg1dt.len()),
        ("dardg2dt", dardg2dt.len()),
        ("dvirdgdt", dvirdgdt.len()),
    ] {
        check_len(var, l, ncol)?;
    }
    if let Some(m) = &valid {
        check_len("valid", m.len(), ncol)?;
    }
    let mut ws = Workspace::new(ncat);
    let mut abuf = vec![0.0; ncat];
    let mut vbuf = vec![0.0; ncat];
    for c in 0..ncol {
        if let Some(m) = &valid
            && !m[c]
        {
            closing[c] = fill;
            opening[c] = fill;
            dardg1dt[c] = fill;
            dardg2dt[c] = fill;
            dvirdgdt[c] = fill;
            continue;
        }
        let mut acol = aicen.index_axis_mut(Axis(1), c);
        let mut vcol = vicen.index_axis_mut(Axis(1), c);
        abuf.iter_mut().zip(acol.iter()).for_each(|(d, s)| *d = *s);
        vbuf.iter_mut().zip(vcol.iter()).for_each(|(d, s)| *d = *s);
        let mut a0 = aice0[c];
        let forcing = RidgeForcing {
            convergence: convergence[c],
            shear: shear[c],
            dt,
        };
        let d = ridge_column(
            &mut abuf, &mut vbuf, &mut a0, hin_max, forcing, opts, &mut ws,
        )
        .map_err(|source| ItdError::Column { column: c, source })?;
        acol.iter_mut().zip(&abuf).for_each(|(d, s)| *d = *s);
        vcol.iter_mut().zip(&vbuf).for_each(|(d, s)| *d = *s);
        aice0[c] = a0;
        closing[c] = d.closing;
        opening[c] = d.opening;
        dardg1dt[c] = d.dardg1dt;
        dardg2dt[c] = d.dardg2dt;
        dvirdgdt[c] = d.dvirdgdt;
    }
    Ok(())
}

/// Icepack `asum_ridging`: open water plus the category areas, in that order.
#[inline]
pub(crate) fn asum_ridging(aicen: &[f64], aice0: f64) -> f64 {
    let mut asum = aice0;
    for &a in aicen {
        asum += a;
    }
    asum
}
