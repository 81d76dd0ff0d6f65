//! The ITD clean-up after ridging, as Icepack's `cleanup_itd` (`icepack_itd.F90`):
//! `aggregate_area`, `rebin` with `shift_ice`, `zap_small_areas` with `zap_snow`, and
//! `zap_snow_temperature`. Categories whose ice has left their thickness range move whole to
//! the neighbour; categories with area ≤ `puny` (or a cell with almost no ice) are emptied
//! into the ocean fluxes; a total area slightly above 1 is scaled back, the excess going to
//! the ocean; snow with an unphysical temperature melts into the ocean.
//!
//! Each routine performs Icepack's operations in Icepack's order (so the reference columns
//! match to the bit where the compiler does too); the arithmetic is written anew.

// Several parallel per-category arrays are indexed by the category number, as in Icepack.
#![allow(clippy::needless_range_loop)]

use super::{ColumnMut, OceanFluxes, RidgeStepParams, SaltFlux, StepContext, StepWorkspace};
use crate::ColumnError;
use crate::tracers::{BgcKind, MAX_AERO, MAX_ISO, MAX_NBTRCR, TracerLayout};

/// Zapped-ice fluxes accumulated during the clean-up (Icepack's `dfresh`, `dfsalt`,
/// `dfhocn`, `dfpond`, `dfaero_ocn`, `dfiso_ocn`), kg m⁻² s⁻¹, kg m⁻² s⁻¹, W m⁻², m,
/// kg m⁻² s⁻¹, kg m⁻² s⁻¹.
#[derive(Debug, Default, Clone, Copy)]
struct Zapped {
    fresh: f64,
    fsalt: f64,
    fhocn: f64,
    fpond: f64,
    aero: [f64; MAX_AERO],
    iso: [f64; MAX_ISO],
    /// Bio tracers (Icepack's `dflux_bio`; tracer unit × m s⁻¹).
    bio: [f64; MAX_NBTRCR],
    /// Ice and snow volume put into the ocean (m).
    vice: f64,
    vsno: f64,
}

/// Icepack `cleanup_itd` for one column with the context's time step (s; the caller passes
/// `ndtd · dt`). Adds the zapped fluxes to `fluxes`; returns the ice and snow volumes (m)
/// put into the ocean.
pub(crate) fn cleanup_itd(
    col: &mut ColumnMut<'_>,
    ctx: &StepContext<'_>,
    fluxes: &mut OceanFluxes,
    ws: &mut StepWorkspace,
) -> Result<(f64, f64), ColumnError> {
    let (opts, layout) = (ctx.opts, ctx.layout);
    let (puny, c) = (opts.params.puny, &opts.step);
    let mut z = Zapped::default();
    // aggregate_area
    let mut aice = 0.0;
    for &a in col.aicen.iter() {
        aice += a;
    }
    *col.aice = aice;
    *col.aice0 = f64::max(1.0 - aice, 0.0);
    if aice > 1.0 + puny || aice < -puny {
        return Err(ColumnError::StepFailed {
            routine: "cleanup_itd",
            what: "aggregate ice area out of bounds",
            category: None,
            value: aice,
        });
    }
    if opts.rebin && aice > puny {
        rebin(col, ctx.hin_max, ctx.tf, puny, layout, ws)?;
    }
    zap_small_areas(col, ctx, &mut z, ws)?;
    zap_snow_temperature(col, ctx.dt, puny, c, layout, &mut z);
    fluxes.fpond += z.fpond;
    fluxes.fresh += z.fresh;
    fluxes.fsalt += z.fsalt;
    fluxes.fhocn += z.fhocn;
    for (f, d) in fluxes.faero_ocn.iter_mut().zip(&z.aero) {
        *f += d;
    }
    for (f, d) in fluxes.fiso_ocn.iter_mut().zip(&z.iso) {
        *f += d;
    }
    for (f, d) in fluxes.flux_bio.iter_mut().zip(&z.bio).take(layout.n_bio()) {
        *f += d;
    }
    Ok((z.vice, z.vsno))
}

/// Icepack `rebin`: moves whole categories whose mean thickness has left their bounds into
/// the neighbour, first upwards then downwards.
fn rebin(
    col: &mut ColumnMut<'_>,
    hin_max: &[f64],
    tf: f64,
    puny: f64,
    layout: &TracerLayout,
    ws: &mut StepWorkspace,
) -> Result<(), ColumnError> {
    let ncat = col.aicen.len();
    mean_thickness(col, puny, &mut ws.hicen);
    if col.aicen[0] > puny && ws.hicen[0] <= hin_max[0] && hin_max[0] > 0.0 {
        col.aicen[0] = col.vicen[0] / hin_max[0];
        ws.hicen[0] = hin_max[0];
    }
    // Boundary n (between categories n and n+1, 0-based), hin_max[n + 1].
    for n in 0..ncat.saturating_sub(1) {
        if col.aicen[n] > puny && ws.hicen[n] > hin_max[n + 1] {
            shift_ice(col, n, n, tf, puny, layout, ws)?;
        }
    }
    for n in (0..ncat.saturating_sub(1)).rev() {
        if col.aicen[n + 1] > puny && ws.hicen[n + 1] <= hin_max[n + 1] {
            shift_ice(col, n, n + 1, tf, puny, layout, ws)?;
        }
    }
    Ok(())
}

/// Icepack `shift_ice` with one active boundary `b` (between categories `b` and `b + 1`)
/// and donor `nd`: moves the donor's whole area and volume (and its snow and tracers) across,
/// then recomputes every category's tracers and thickness.
fn shift_ice(
    col: &mut ColumnMut<'_>,
    b: usize,
    nd: usize,
    tf: f64,
    puny: f64,
    layout: &TracerLayout,
    ws: &mut StepWorkspace,
) -> Result<(), ColumnError> {
    let nt = layout.ntrcr();
    let aicen_init_nd = col.aicen[nd];
    let vsnon_init_nd = col.vsnon[nd];
    col.tracer_amounts(layout, &mut ws.atrcrn);
    let mut daice = col.aicen[nd];
    let mut dvice = col.vicen[nd];
    let fail = |what: &'static str, value: f64| ColumnError::StepFailed {
        routine: "shift_ice",
        what,
        category: Some(nd),
        value,
    };
    // The checks of shift_ice, in its order.
    let (mut daice_neg, mut dvice_neg, mut daice_big, mut dvice_big) = (false, false, false, false);
    if daice < 0.0 {
        if daice > -puny * col.aicen[nd] {
            daice = 0.0;
            dvice = 0.0;
        } else {
            daice_neg = true;
        }
    }
    if dvice < 0.0 {
        if dvice > -puny * col.vicen[nd] {
            daice = 0.0;
            dvice = 0.0;
        } else {
            dvice_neg = true;
        }
    }
    if daice > col.aicen[nd] * (1.0 - puny) {
        if daice < col.aicen[nd] * (1.0 + puny) {
            daice = col.aicen[nd];
            dvice = col.vicen[nd];
        } else {
            daice_big = true;
        }
    }
    if dvice > col.vicen[nd] * (1.0 - puny) {
        if dvice < col.vicen[nd] * (1.0 + puny) {
            daice = col.aicen[nd];
            dvice = col.vicen[nd];
        } else {
            dvice_big = true;
        }
    }
    if daice_neg && daice <= -puny * col.aicen[nd] {
        return Err(fail("negative area to shift", daice));
    }
    if dvice_neg && dvice <= -puny * col.vicen[nd] {
        return Err(fail("negative volume to shift", dvice));
    }
    if daice_big && daice >= col.aicen[nd] * (1.0 + puny) {
        return Err(fail("area to shift exceeds the category's", daice));
    }
    if dvice_big && dvice >= col.vicen[nd] * (1.0 + puny) {
        return Err(fail("volume to shift exceeds the category's", dvice));
    }
    if daice > 0.0 {
        let nr = if nd == b { nd + 1 } else { b };
        col.aicen[nd] -= daice;
        col.aicen[nr] += daice;
        col.vicen[nd] -= dvice;
        col.vicen[nr] += dvice;
        let worka = daice / aicen_init_nd;
        let dvsnow = vsnon_init_nd * worka;
        col.vsnon[nd] -= dvsnow;
        col.vsnon[nr] += dvsnow;
        let trd = &col.trcrn[nd * nt..(nd + 1) * nt];
        for it in 0..nt {
            let d = layout.amount(it, trd, daice, dvice, dvsnow);
            ws.atrcrn[nd * nt + it] -= d;
            ws.atrcrn[nr * nt + it] += d;
        }
    }
    mean_thickness(col, puny, &mut ws.hicen);
    col.tracers_from_amounts(layout, &ws.atrcrn, puny, tf);
    Ok(())
}

/// Each category's mean ice thickness (m) into `hicen`: volume over area where the area is
/// above `puny`, else 0.
fn mean_thickness(col: &ColumnMut<'_>, puny: f64, hicen: &mut [f64]) {
    for n in 0..col.aicen.len() {
        hicen[n] = if col.aicen[n] > puny {
            col.vicen[n] / col.aicen[n]
        } else {
            0.0
        };
    }
}

/// Icepack `zap_small_areas`: empties categories with 0 < |area| ≤ `puny` (or any leftover
/// volume or snow without area), or every category when the cell holds almost no ice, into
/// the ocean; scales a total area in (1, 1 + puny) back to 1.
fn zap_small_areas(
    col: &mut ColumnMut<'_>,
    ctx: &StepContext<'_>,
    z: &mut Zapped,
    ws: &mut StepWorkspace,
) -> Result<(), ColumnError> {
    let StepContext {
        dt,
        tf,
        opts,
        layout,
        ..
    } = *ctx;
    let (puny, rhoi, c) = (opts.params.puny, opts.params.rhoi, &opts.step);
    let ncat = col.aicen.len();
    let nt = layout.ntrcr();
    let nilyr = layout.nilyr as f64;
    let nslyr = layout.nslyr as f64;
    let aice = *col.aice;
    let zap_residual =
        aice < f64::max(c.itd_area_min, puny) || aice * rhoi < f64::max(c.itd_mass_min, puny);
    for n in 0..ncat {
        let a = col.aicen[n];
        let zap_category =
            a.abs() <= puny && (a != 0.0 || col.vicen[n] != 0.0 || col.vsnon[n] != 0.0);
        if a < -puny {
            return Err(ColumnError::StepFailed {
                routine: "zap_small_areas",
                what: "negative ice area",
                category: Some(n),
                value: a,
            });
        }
        if !(zap_category || zap_residual) {
            continue;
        }
        let v = col.vicen[n];
        let trc = &mut col.trcrn[n * nt..(n + 1) * nt];
        if layout.zap_pond_water
            && let (Some(ip), Some(ih)) = (layout.nt_apnd, layout.nt_hpnd)
        {
            z.fpond -= a * trc[ip] * trc[ih];
        }
        for (d, a) in z.aero.iter_mut().zip(&layout.aero) {
            *d += v * (trc[a[2]] + trc[a[3]]) / dt;
        }
        if let Some((_, iice, niso)) = layout.iso {
            for k in 0..niso {
                z.iso[k] += v * trc[iice + k] / dt;
            }
        }
        zap_bio_ice(trc, BioZap::Category { area: a }, v, dt, layout, z);
        for k in 0..layout.nilyr {
            let q = &mut trc[layout.nt_qice + k];
            z.fhocn += *q / dt * v / nilyr;
            *q = 0.0;
        }
        z.fresh += rhoi * v / dt;
        z.fsalt += rhoi * v * ice_salinity(trc, c, layout) * 0.001 / dt;
        z.vice += v;
        *col.aice0 += a;
        col.aicen[n] = 0.0;
        col.vicen[n] = 0.0;
        if let Some(i) = layout.nt_tsfc {
            trc[i] = tf;
        }
        zap_snow(trc, &mut col.vsnon[n], dt, c, layout, z);
        for (it, t) in trc.iter_mut().enumerate() {
            if Some(it) != layout.nt_tsfc {
                *t = 0.0;
            }
        }
        // Icepack's refills of an emptied category (fbri = 1; the snow tracers).
        for &it in &layout.refilled {
            trc[it] = layout.empty[it];
        }
        ws.zapped[n] = true;
    }
    if aice > 1.0 + puny {
        return Err(ColumnError::StepFailed {
            routine: "zap_small_areas",
            what: "excess ice area",
            category: None,
            value: aice,
        });
    } else if aice > 1.0 && aice < 1.0 + puny {
        for n in 0..ncat {
            let (v, s) = (col.vicen[n], col.vsnon[n]);
            let trc = &col.trcrn[n * nt..(n + 1) * nt];
            if layout.zap_pond_water
                && let (Some(ip), Some(ih)) = (layout.nt_apnd, layout.nt_hpnd)
            {
                z.fpond -= col.aicen[n] * trc[ip] * trc[ih] * (aice - 1.0) / aice;
            }
            for (d, a) in z.aero.iter_mut().zip(&layout.aero) {
                *d += (s * (trc[a[0]] + trc[a[1]]) + v * (trc[a[2]] + trc[a[3]])) * (aice - 1.0)
                    / aice
                    / dt;
            }
            if let Some((isno, iice, niso)) = layout.iso {
                for k in 0..niso {
                    z.iso[k] += (s * trc[isno + k] + v * trc[iice + k]) * (aice - 1.0) / aice / dt;
                }
            }
            zap_bio_ice(
                trc,
                BioZap::Excess {
                    frac: (aice - 1.0) / aice,
                },
                v,
                dt,
                layout,
                z,
            );
            if let Some(b) = &layout.bgc {
                // The snow's bio tracers go with the excess ice (its surface layer and
                // interior).
                let dvssl = 0.5 * s / layout.nslyr as f64;
                let dvint = s - dvssl;
                for (d, snow) in z.bio.iter_mut().zip(b.snow_content(trc, dvssl, dvint)) {
                    *d += snow * (aice - 1.0) / aice / dt;
                }
            }
            for k in 0..layout.nilyr {
                z.fhocn += trc[layout.nt_qice + k] * v / nilyr * (aice - 1.0) / aice / dt;
            }
            for k in 0..layout.nslyr {
                z.fhocn += trc[layout.nt_qsno + k] * s / nslyr * (aice - 1.0) / aice / dt;
            }
            z.fresh += (rhoi * v + c.rhos * s) * (aice - 1.0) / aice / dt;
            let sal = ice_salinity(trc, c, layout);
            z.fsalt += rhoi * v * sal * 0.001 * (aice - 1.0) / aice / dt;
            col.aicen[n] *= 1.0 / aice;
            col.vicen[n] *= 1.0 / aice;
            col.vsnon[n] *= 1.0 / aice;
            z.vice += v - col.vicen[n];
            z.vsno += s - col.vsnon[n];
        }
        *col.aice = 1.0;
        // Icepack sets aice0 = 0 here, dropping the open water of categories zapped just
        // above (at most ncat·puny). pressridge keeps it, scaled like the ice, so the cell
        // stays whole.
        *col.aice0 *= 1.0 / aice;
    }
    Ok(())
}

/// The salinity (ppt) of the ice that a zapped category puts into the ocean: the reference
/// salinity, or with prognostic salinity the mean of the category's layer salinities
/// (`trc`, its tracers), summed layer by layer as Icepack does.
fn ice_salinity(trc: &[f64], c: &RidgeStepParams, layout: &TracerLayout) -> f64 {
    match c.salt_flux {
        SaltFlux::Constant => c.ice_ref_salinity,
        SaltFlux::Prognostic => {
            let nilyr = layout.nilyr as f64;
            let mut sicen = 0.0;
            for k in 0..layout.nilyr {
                sicen += trc[layout.nt_sice + k] / nilyr;
            }
            sicen
        }
    }
}

/// Icepack `zap_snow`: melts one category's snow into the ocean.
fn zap_snow(
    trc: &mut [f64],
    vsnon: &mut f64,
    dt: f64,
    c: &RidgeStepParams,
    layout: &TracerLayout,
    z: &mut Zapped,
) {
    let nslyr = layout.nslyr as f64;
    for (d, a) in z.aero.iter_mut().zip(&layout.aero) {
        *d += *vsnon * (trc[a[0]] + trc[a[1]]) / dt;
    }
    if let Some((isno, _, niso)) = layout.iso {
        for k in 0..niso {
            z.iso[k] += *vsnon * trc[isno + k] / dt;
        }
    }
    if let Some(b) = &layout.bgc {
        let dvssl = 0.5 * *vsnon / nslyr;
        let dvint = *vsnon - dvssl;
        for (d, snow) in z.bio.iter_mut().zip(b.snow_content(trc, dvssl, dvint)) {
            *d += snow / dt;
        }
    }
    for k in 0..layout.nslyr {
        let q = &mut trc[layout.nt_qsno + k];
        z.fhocn += *q / dt * *vsnon / nslyr;
        *q = 0.0;
    }
    z.fresh += c.rhos * *vsnon / dt;
    z.vsno += *vsnon;
    *vsnon = 0.0;
}

/// Icepack `zap_snow_temperature`: melts the snow of categories where a snow layer's
/// temperature from its enthalpy is below `tmin` or above a tiny positive limit.
fn zap_snow_temperature(
    col: &mut ColumnMut<'_>,
    dt: f64,
    puny: f64,
    c: &RidgeStepParams,
    layout: &TracerLayout,
    z: &mut Zapped,
) {
    let ncat = col.aicen.len();
    let nt = layout.ntrcr();
    let rnslyr = layout.nslyr as f64;
    for n in 0..ncat {
        let mut l_zap = false;
        if col.aicen[n] > puny {
            let hsn = col.vsnon[n] / col.aicen[n];
            for k in 0..layout.nslyr {
                let (zqsn, tmax) = if hsn > c.hs_min {
                    let q = col.trcrn[n * nt + layout.nt_qsno + k];
                    (q, -(q * puny * rnslyr / (c.rhos * c.cp_ice * col.vsnon[n])))
                } else {
                    (-(c.rhos * c.lfresh), puny)
                };
                let ztsn = (c.lfresh + zqsn / c.rhos) / c.cp_ice;
                if ztsn < c.tmin || ztsn > tmax {
                    l_zap = true;
                }
            }
        }
        if l_zap {
            let (trc, vs) = (&mut col.trcrn[n * nt..(n + 1) * nt], &mut col.vsnon[n]);
            zap_snow(trc, vs, dt, c, layout, z);
        }
    }
}

/// Which ice [`zap_bio_ice`] puts into the ocean.
#[derive(Clone, Copy)]
enum BioZap {
    /// A whole category of this area (Icepack's first loop of `zap_small_areas`).
    Category { area: f64 },
    /// This fraction of every category, the excess of a total area above 1 (its second loop).
    Excess { frac: f64 },
}

/// Icepack `zap_small_bgc` over a zapped category's bio tracers in the ice (`trc`, ice volume
/// `v`): the skeletal layer holds `area · sk_l` of water per unit area (for the excess,
/// Icepack's `(aice − 1)/aice · sk_l`); the vertical grid `vicen/nblyr · fbri` per level (for
/// the excess, times `(aice − 1)/aice`), half at its two ends.
fn zap_bio_ice(trc: &[f64], what: BioZap, v: f64, dt: f64, layout: &TracerLayout, z: &mut Zapped) {
    let Some(b) = &layout.bgc else { return };
    match b.kind {
        BgcKind::Skeletal { sk_l } => {
            let bvol = match what {
                BioZap::Category { area } => area * sk_l,
                BioZap::Excess { frac } => frac * sk_l,
            };
            for (d, &bi) in z.bio.iter_mut().zip(&b.bio_index) {
                *d += trc[bi] * bvol / dt;
            }
        }
        BgcKind::Vertical { nblyr } => {
            let fbri = trc[layout.nt_fbri.expect("checked by with_bgc")];
            let full = match what {
                BioZap::Category { .. } => v / nblyr as f64 * fbri,
                BioZap::Excess { frac } => frac * v / nblyr as f64 * fbri,
            };
            let nlev = nblyr + 1;
            for (d, &bi) in z.bio.iter_mut().zip(&b.bio_index) {
                for k in 0..nlev {
                    let bvol = if k == 0 || k == nlev - 1 {
                        0.5 * full
                    } else {
                        full
                    };
                    *d += trc[bi + k] * bvol / dt;
                }
            }
        }
    }
}
