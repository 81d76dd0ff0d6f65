//! The ridging passes of one column (Icepack `ridge_ice`): closing and opening from the
//! forcing (`ridge_prep`), repeated passes of participation (`ridge_itd`) and of area,
//! volume, snow and tracer transfer (`ridge_shift`) until the total area is 1, then the
//! ocean fluxes, the rates and the clean-up.

// Several parallel per-category arrays are indexed by the category number, as in Icepack.
#![allow(clippy::needless_range_loop)]

use super::area_volume::{asum_ridging, close_and_open};
use super::cleanup::cleanup_itd;
use super::{
    Closing, ColumnMut, OceanFluxes, RidgeStepOptions, StepContext, StepDiagnostics, StepForcing,
    StepWorkspace,
};
use crate::ColumnError;
use crate::redistribution::{RidgeGeometry, category_fractions_all};
use crate::tracers::{MAX_AERO, MAX_ISO, MAX_NBTRCR, TracerLayout};

/// Sums of one ridging pass and of the whole step (Icepack `ridge_ice` locals).
#[derive(Default)]
struct Sums {
    ardg1: f64,
    ardg2: f64,
    virdg: f64,
    aopen: f64,
    msnow_mlt: f64,
    esnow_mlt: f64,
    mpond: f64,
    vsno_ocean: f64,
    /// Aerosol and isotope mass put into the ocean with ridged snow (kg m⁻²).
    maero: [f64; MAX_AERO],
    miso: [f64; MAX_ISO],
    /// Bio tracer mass put into the ocean with ridged snow (tracer unit × m).
    mbio: [f64; MAX_NBTRCR],
}

pub(super) fn step(
    col: &mut ColumnMut<'_>,
    hin_max: &[f64],
    forcing: StepForcing,
    opts: &RidgeStepOptions,
    layout: &TracerLayout,
    fluxes: &mut OceanFluxes,
    ws: &mut StepWorkspace,
) -> Result<StepDiagnostics, ColumnError> {
    let p = &opts.params;
    let puny = p.puny;
    let dt = forcing.dt;
    ws.reset_diagnostics();
    let mut s = Sums::default();

    let mut asum = asum_ridging(col.aicen, *col.aice0);
    let (mut closing_net, mut opning, top) = match forcing.closing {
        Closing::Rates { closing, opening } => (closing, opening, hin_max[hin_max.len() - 1]),
        Closing::Deformation { convergence, shear } => {
            // ridge_prep
            let mut closing_net = p.cs * shear + convergence;
            let divu_adv = (1.0 - asum) / dt;
            if divu_adv < 0.0 {
                closing_net = f64::max(closing_net, -divu_adv);
            }
            (closing_net, closing_net + divu_adv, p.big)
        }
    };
    let mut d = StepDiagnostics {
        closing: closing_net,
        hin_max_top: top,
        ..Default::default()
    };

    let ctx = StepContext {
        hin_max,
        dt,
        tf: forcing.tf,
        opts,
        layout,
    };
    let mut niter = 0;
    ws.mu_rdg_clamped = false;
    loop {
        niter += 1;
        let aksum = ridge_itd(col, opts, ws);
        let pass = Pass {
            top,
            aksum,
            closing_net,
        };
        ridge_shift(col, &ctx, pass, &mut opning, &mut s, ws)?;
        asum = asum_ridging(col.aicen, *col.aice0);
        if (asum - 1.0).abs() < puny {
            break;
        }
        if niter >= p.nitermax {
            return Err(ColumnError::NoConvergence { niter, total: asum });
        }
        let divu_adv = (1.0 - asum) / dt;
        closing_net = f64::max(0.0, -divu_adv);
        opning = f64::max(0.0, divu_adv);
    }

    let dti = 1.0 / dt;
    d.dardg1dt = s.ardg1 * dti;
    d.dardg2dt = s.ardg2 * dti;
    d.dvirdgdt = s.virdg * dti;
    d.opening = s.aopen * dti;
    d.niter = niter;
    d.mu_rdg_clamped = ws.mu_rdg_clamped;
    for n in 0..ws.ncat() {
        ws.dardg1ndt[n] = ws.core.ardg1n[n] * dti;
        ws.dardg2ndt[n] = ws.core.ardg2n[n] * dti;
        ws.dvirdgndt[n] = ws.core.virdgn[n] * dti;
        ws.araftn[n] = ws.mraft[n] * ws.core.ardg2n[n];
        ws.vraftn[n] = ws.mraft[n] * ws.core.virdgn[n];
    }
    let dti = 1.0 / (f64::from(forcing.ndtd) * dt);
    fluxes.fresh += s.msnow_mlt * dti;
    fluxes.fhocn += s.esnow_mlt * dti;
    for (f, m) in fluxes.faero_ocn.iter_mut().zip(&s.maero) {
        *f += m * dti;
    }
    for (f, m) in fluxes.fiso_ocn.iter_mut().zip(&s.miso) {
        *f += m * dti;
    }
    for (f, m) in fluxes.flux_bio.iter_mut().zip(&s.mbio).take(layout.n_bio()) {
        *f += m * dti;
    }
    fluxes.fpond -= s.mpond;
    fluxes.dpnd_ridge = s.mpond;
    d.snow_to_ocean = s.vsno_ocean;

    if opts.cleanup {
        let ctx = StepContext {
            dt: dt * f64::from(forcing.ndtd),
            ..ctx
        };
        let (vice, vsno) = cleanup_itd(col, &ctx, fluxes, ws)?;
        d.ice_to_ocean = vice;
        d.snow_to_ocean += vsno;
    }
    Ok(d)
}

/// Icepack `ridge_itd`: participation, ridge geometry, rafting mask; returns `aksum`.
fn ridge_itd(col: &ColumnMut<'_>, opts: &RidgeStepOptions, ws: &mut StepWorkspace) -> f64 {
    let p = &opts.params;
    let w = &mut ws.core;
    let aksum = w.prepare_ridging(
        opts.participation,
        &opts.redistribution,
        p,
        *col.aice0,
        col.aicen,
        col.vicen,
    );
    for n in 0..w.ncat() {
        if opts.redistribution.is_exponential() && col.aicen[n] > p.puny {
            // Rafting mask: 1 where h_min = 2h (the ice rafts), as Icepack's `mraft`.
            let hi = f64::max(w.hi[n], p.puny);
            let m = f64::max(0.0, 1.0f64.copysign(hi + p.maxraft - w.hrmin[n]));
            let x = m * ((2.0 * hi + w.hrexp[n]) / hi - w.krdg[n]);
            ws.mraft[n] = f64::max(0.0, 1.0f64.copysign(p.puny - x.abs()));
        }
        ws.aparticn[n] = w.apartic[n + 1];
        ws.krdgn[n] = w.krdg[n];
    }
    aksum
}

/// What ridging category `n` loses to the ocean with the snow it sheds (the fraction
/// `1 − fsnowrdg` of its ridged snow `vsrdgn`, m) and the pond water on its ridging area
/// `ardg1n`: snow mass and enthalpy, aerosols, isotopes, snow bio tracers and pond water,
/// added to the step's sums in Icepack's order. `trc`: the category's tracers.
fn book_ridged_losses(
    s: &mut Sums,
    layout: &TracerLayout,
    trc: &[f64],
    (ardg1n, vsrdgn): (f64, f64),
    one_minus_f: f64,
    rhos: f64,
) {
    let nslyr = layout.nslyr as f64;
    s.msnow_mlt += rhos * vsrdgn * one_minus_f;
    s.vsno_ocean += vsrdgn * one_minus_f;
    for (m, a) in s.maero.iter_mut().zip(&layout.aero) {
        *m += vsrdgn * one_minus_f * (trc[a[0]] + trc[a[1]]);
    }
    if let Some((isno, iice, niso)) = layout.iso {
        // Icepack counts the ice's isotopes with the snow's here.
        for k in 0..niso {
            s.miso[k] += vsrdgn * one_minus_f * (trc[isno + k] + trc[iice + k]);
        }
    }
    // Vertical bio tracers in the ridged snow: its surface layer (half the top snow
    // layer) and interior, as fractions of the snow depth (Icepack's dzssl, dzint).
    if let Some(b) = &layout.bgc {
        let dzssl = 0.5 / layout.nslyr as f64;
        let dzint = 1.0 - dzssl;
        for (m, snow) in s.mbio.iter_mut().zip(b.snow_content(trc, dzssl, dzint)) {
            *m += vsrdgn * one_minus_f * snow;
        }
    }
    // Pond water on the ridging ice (Icepack's diagnostic of every pond scheme).
    if let (Some(ip), Some(ih)) = (layout.nt_apnd, layout.nt_hpnd) {
        match layout.nt_alvl {
            Some(ia) if layout.ponds_on_level_ice => {
                s.mpond += ardg1n * trc[ip] * trc[ih] * trc[ia];
            }
            _ => s.mpond += ardg1n * trc[ip] * trc[ih],
        }
    }
    for k in 0..layout.nslyr {
        let esrdgn = vsrdgn * trc[layout.nt_qsno + k] / nslyr;
        s.esnow_mlt += esrdgn * one_minus_f;
    }
}

/// One ridging pass's inputs: the top bound of the thickest category (m), the participating
/// area `aksum` (1) and the net closing rate (1/s).
#[derive(Clone, Copy)]
struct Pass {
    top: f64,
    aksum: f64,
    closing_net: f64,
}

/// Icepack `ridge_shift`: one ridging pass with area, volume, snow and tracers; `opning`
/// the opening rate (1/s), raised where nothing can ridge.
fn ridge_shift(
    col: &mut ColumnMut<'_>,
    ctx: &StepContext<'_>,
    pass: Pass,
    opning: &mut f64,
    s: &mut Sums,
    ws: &mut StepWorkspace,
) -> Result<(), ColumnError> {
    let StepContext {
        hin_max,
        dt,
        tf,
        opts,
        layout,
    } = *ctx;
    let Pass {
        top,
        aksum,
        closing_net,
    } = pass;
    let p = &opts.params;
    let c = &opts.step;
    let puny = p.puny;
    let ncat = ws.ncat();
    let nt = layout.ntrcr();
    ws.core.aicen_init.copy_from_slice(col.aicen);
    ws.core.vicen_init.copy_from_slice(col.vicen);
    ws.vsnon_init.copy_from_slice(col.vsnon);
    col.tracer_amounts(layout, &mut ws.atrcrn);
    // pressridge: with no area above puny nothing can ridge (Icepack divides by aksum = 0);
    // the missing area opens.
    let closing_gross = close_and_open(
        &ws.core.apartic,
        aksum,
        closing_net,
        col.aicen,
        col.aice0,
        puny,
        dt,
        opning,
    )?;
    s.aopen = *opning * dt;

    let one_minus_f = 1.0 - c.fsnowrdg;
    for n in 0..ncat {
        let ap = ws.core.apartic[n + 1];
        let a_init = ws.core.aicen_init[n];
        if !(a_init > puny && ap > 0.0 && closing_gross > 0.0) {
            continue;
        }
        let mut ardg1n = ap * closing_gross * dt;
        if ardg1n > a_init + puny {
            return Err(ColumnError::StepFailed {
                routine: "ridge_shift",
                what: "ridging area exceeds the category's",
                category: Some(n),
                value: ardg1n,
            });
        }
        ardg1n = f64::min(a_init, ardg1n);
        let ardg2n = ardg1n / ws.core.krdg[n];
        let afrac = ardg1n / a_init;
        let virdgn = ws.core.vicen_init[n] * afrac;
        let vsrdgn = ws.vsnon_init[n] * afrac;
        col.aicen[n] -= ardg1n;
        col.vicen[n] -= virdgn;
        col.vsnon[n] -= vsrdgn;
        s.ardg1 += ardg1n;
        s.ardg2 += ardg2n;
        s.virdg += virdgn;
        ws.core.ardg1n[n] = ardg1n;
        ws.core.ardg2n[n] = ardg2n;
        ws.core.virdgn[n] = virdgn;

        let trc = &col.trcrn[n * nt..(n + 1) * nt];
        book_ridged_losses(s, layout, trc, (ardg1n, vsrdgn), one_minus_f, c.rhos);
        for it in 0..nt {
            ws.atrcrn[n * nt + it] -= layout.amount(it, trc, ardg1n, virdgn, vsrdgn);
        }

        let g = RidgeGeometry {
            hi: ws.core.hi[n],
            hrmin: ws.core.hrmin[n],
            hrmax: ws.core.hrmax[n],
            hrexp: ws.core.hrexp[n],
            krdg: ws.core.krdg[n],
            mu_clamped: ws.core.mu_clamped[n],
        };
        ws.mu_rdg_clamped |= g.mu_clamped;
        category_fractions_all(
            &opts.redistribution,
            p,
            &g,
            hin_max,
            top,
            &mut ws.farea,
            &mut ws.fvol,
        );
        let exponential = opts.redistribution.is_exponential();
        for nr in 0..ncat {
            let (farea, fvol) = (ws.farea[nr], ws.fvol[nr]);
            if n == 0 && exponential {
                ws.aredistn[nr] = farea * ardg2n;
                ws.vredistn[nr] = fvol * virdgn;
            }
            if farea == 0.0 && fvol == 0.0 {
                continue; // adds nothing (Icepack adds zeros)
            }
            col.aicen[nr] += farea * ardg2n;
            col.vicen[nr] += fvol * virdgn;
            col.vsnon[nr] += fvol * vsrdgn * c.fsnowrdg;
            let f = [ardg2n * farea, virdgn * fvol, vsrdgn * fvol * c.fsnowrdg];
            let dst = &mut ws.atrcrn[nr * nt..(nr + 1) * nt];
            for (k, list) in layout.ridge_lists.iter().enumerate() {
                for &it in list {
                    dst[it] += f[k] * trc[it];
                }
            }
            // Tracers carried on the brine fraction go with it.
            if let Some(ib) = layout.nt_fbri {
                for (k, list) in layout.ridge_lists_brine.iter().enumerate() {
                    for &it in list {
                        dst[it] += f[k] * trc[it] * trc[ib];
                    }
                }
            }
        }
    }
    col.tracers_from_amounts(layout, &ws.atrcrn, puny, tf);
    Ok(())
}
