//! The complete ridging step (snow, tracers, ocean fluxes; `pressridge::itd::ridge_step`) through
//! the C ABI: a [`PressridgeRidger`] handle holds the tracer layout and the options, made once
//! at initialisation; then one call per cell (`pressridge_ridge_cell`, the argument list of
//! Icepack's `icepack_step_ridge`) or one call per block of cells (`pressridge_ridge_cells`).

// Per-category and per-tracer tables are indexed by number, as in Icepack.
#![allow(clippy::needless_range_loop)]

use std::cell::RefCell;

use super::layout::{Region, check_disjoint, check_ptr};
use super::{FfiError, FfiResult, PRESSRIDGE_ERR_BAD_SIZE, guard, put};
use pressridge::itd::{
    ColumnMut, ItdError, StepDiagnostics, StepForcing, StepWorkspace,
    details::{
        CellForcing, CellOutputs, CellState, Closing, MAX_AERO, MAX_ISO, MAX_NBTRCR, OceanFluxes,
        species_counts,
    },
    ridge_step_cells, ridge_step_column,
};

mod ridger;
pub use ridger::{
    PRESSRIDGE_BGC_NONE, PRESSRIDGE_BGC_SKELETAL, PRESSRIDGE_BGC_VERTICAL, PRESSRIDGE_TRACER_AGE,
    PRESSRIDGE_TRACER_BRINE, PRESSRIDGE_TRACER_FIRST_YEAR, PRESSRIDGE_TRACER_LEVEL_ICE,
    PRESSRIDGE_TRACER_POND_SEALVL, PRESSRIDGE_TRACER_POND_TOPO, PRESSRIDGE_TRACER_PONDS,
    PRESSRIDGE_TRACER_SNOW, PressridgeRidger, PressridgeStepParams, PressridgeTracers,
    pressridge_ridger_free, pressridge_ridger_new, pressridge_ridger_tracer_field,
    pressridge_ridger_tracers, pressridge_step_params_default,
};
use ridger::{bad_value, ridger_ref};

/// Fluxes to the ocean of one cell; the ridging step **adds** to them (as Icepack adds to
/// its arguments), except `dpnd_ridge`, which it overwrites.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct PressridgeOceanFluxes {
    /// Fresh water into the ocean (kg m⁻² s⁻¹, averaged over `ndtd·dt`), Icepack `fresh`.
    pub fresh: f64,
    /// Salt into the ocean (kg m⁻² s⁻¹), Icepack `fsalt`.
    pub fsalt: f64,
    /// Heat flux to the ocean (W m⁻², negative: the ocean melts what it receives), `fhocn`.
    pub fhocn: f64,
    /// Pond water lost by ridging, with sign (m over the cell, per step), Icepack `fpond`.
    pub fpond: f64,
    /// Pond water drained by ridging (m over the cell, per step), Icepack `dpnd_ridge`.
    pub dpnd_ridge: f64,
    /// Aerosol into the ocean per species (kg m⁻² s⁻¹, over `ndtd·dt`), Icepack
    /// `faero_ocn`; the ridger's `n_aero` first values are added to, the rest left as they are.
    pub faero_ocn: [f64; 6],
    /// Water isotopes into the ocean per species (kg m⁻² s⁻¹), Icepack `fiso_ocn`; the first
    /// `n_iso` values are added to.
    pub fiso_ocn: [f64; 3],
    /// Biogeochemical flux into the ocean per bio tracer (the tracer's unit times m s⁻¹:
    /// mmol m⁻² s⁻¹, kg m⁻² s⁻¹ for aerosols), Icepack `flux_bio`; the first `nbtrcr` values
    /// are added to.
    pub flux_bio: [f64; 29],
}

// The C struct's arrays hold every species a layout may have.
const _: () = assert!(MAX_AERO == 6 && MAX_ISO == 3 && MAX_NBTRCR == 29);

/// Cell diagnostics of one ridging step (all written).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct PressridgeStepDiagnostics {
    /// Net closing rate of the first pass (1/s).
    pub closing: f64,
    /// Opening rate of the last pass (1/s), Icepack `opening`.
    pub opening: f64,
    /// Area of ridging ice per unit time (1/s), `dardg1dt`.
    pub dardg1dt: f64,
    /// Area of new ridges per unit time (1/s), `dardg2dt`.
    pub dardg2dt: f64,
    /// Volume of ridging ice per unit time (m/s), `dvirdgdt`.
    pub dvirdgdt: f64,
    /// Ice volume put into the ocean (m over the cell).
    pub ice_to_ocean: f64,
    /// Snow volume put into the ocean (m over the cell).
    pub snow_to_ocean: f64,
    /// Ridging passes.
    pub niter: i64,
}

impl From<&StepDiagnostics> for PressridgeStepDiagnostics {
    fn from(d: &StepDiagnostics) -> Self {
        Self {
            closing: d.closing,
            opening: d.opening,
            dardg1dt: d.dardg1dt,
            dardg2dt: d.dardg2dt,
            dvirdgdt: d.dvirdgdt,
            ice_to_ocean: d.ice_to_ocean,
            snow_to_ocean: d.snow_to_ocean,
            niter: d.niter as i64,
        }
    }
}

/// Per-category diagnostics of one cell (Icepack's names and units); each pointer may be
/// null (not returned) or point to `ncat` values.
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct PressridgeCategoryDiagnostics {
    /// Area of ridging ice per unit time, last pass the category ridged (1/s).
    pub dardg1ndt: *mut f64,
    /// Area of new ridges per unit time (1/s).
    pub dardg2ndt: *mut f64,
    /// Volume of ridging ice per unit time (m/s).
    pub dvirdgndt: *mut f64,
    /// Participation function, last pass (1).
    pub aparticn: *mut f64,
    /// Mean ridge thickness / ridging-ice thickness, last pass (1).
    pub krdgn: *mut f64,
    /// Rafted new-ridge area per step (1).
    pub araftn: *mut f64,
    /// Rafting ice volume per step (m).
    pub vraftn: *mut f64,
    /// New-ridge area from category 1 landing in each category, per step (1).
    pub aredistn: *mut f64,
    /// New-ridge volume from category 1 landing in each category, per step (m).
    pub vredistn: *mut f64,
    /// Set to 1 for categories emptied by the clean-up (Icepack `first_ice`), else unchanged.
    pub first_ice: *mut i32,
}

struct StepScratch {
    ws: StepWorkspace,
}

thread_local! {
    static STEP_SCRATCH: RefCell<Option<StepScratch>> = const { RefCell::new(None) };
}

fn with_step_scratch<T>(ncat: usize, ntrcr: usize, f: impl FnOnce(&mut StepWorkspace) -> T) -> T {
    STEP_SCRATCH.with(|cell| {
        let mut slot = cell.borrow_mut();
        if slot
            .as_ref()
            .is_none_or(|s| s.ws.ncat() != ncat || s.ws.ntrcr() != ntrcr)
        {
            *slot = Some(StepScratch {
                ws: StepWorkspace::new(ncat, ntrcr),
            });
        }
        f(&mut slot.as_mut().expect("just filled").ws)
    })
}

/// # Safety
/// A non-null `p` must point to `n` initialised, aligned f64 that nothing else reads or
/// writes for `'a` (the C caller's promise).
unsafe fn slice_mut<'a>(p: *mut f64, n: usize, what: &str) -> FfiResult<&'a mut [f64]> {
    check_ptr(p, what)?;
    // SAFETY: non-null, aligned; length is the caller's promise.
    Ok(unsafe { std::slice::from_raw_parts_mut(p, n) })
}

/// # Safety
/// A non-null `p` must point to `n` initialised, aligned f64 that nothing writes for `'a`.
unsafe fn slice<'a>(p: *const f64, n: usize, what: &str) -> FfiResult<&'a [f64]> {
    check_ptr(p, what)?;
    // SAFETY: non-null, aligned; length is the caller's promise.
    Ok(unsafe { std::slice::from_raw_parts(p, n) })
}

/// Writes the per-category diagnostics of `ws` where the caller asked for them.
unsafe fn put_categories(
    c: &PressridgeCategoryDiagnostics,
    ws: &StepWorkspace,
    ncat: usize,
) -> FfiResult<()> {
    for (p, v, name) in [
        (c.dardg1ndt, &ws.dardg1ndt, "dardg1ndt"),
        (c.dardg2ndt, &ws.dardg2ndt, "dardg2ndt"),
        (c.dvirdgndt, &ws.dvirdgndt, "dvirdgndt"),
        (c.aparticn, &ws.aparticn, "aparticn"),
        (c.krdgn, &ws.krdgn, "krdgn"),
        (c.araftn, &ws.araftn, "araftn"),
        (c.vraftn, &ws.vraftn, "vraftn"),
        (c.aredistn, &ws.aredistn, "aredistn"),
        (c.vredistn, &ws.vredistn, "vredistn"),
    ] {
        if !p.is_null() {
            // SAFETY: as `slice_mut`.
            unsafe { slice_mut(p, ncat, name)? }.copy_from_slice(v);
        }
    }
    if !c.first_ice.is_null() {
        check_ptr(c.first_ice, "first_ice")?;
        for (n, z) in ws.zapped.iter().enumerate() {
            if *z {
                // SAFETY: checked pointer, `ncat` elements promised.
                unsafe { c.first_ice.add(n).write(1) };
            }
        }
    }
    Ok(())
}

/// One ridging step of one grid cell, in place: Icepack's `icepack_step_ridge` (ridging with
/// snow, tracers and ocean fluxes, then the clean-up), see `docs/strength.md`.
///
/// - `dt` (s, > 0), `ndtd` (≥ 1: fluxes are averaged over `ndtd·dt`), `tf` freezing
///   temperature (°C) for emptied categories;
/// - `hin_max`: `ncat + 1` category bounds (m), in/out: with `closing` null its last value is
///   set to `params.big` (as Icepack does);
/// - `rdg_conv`, `rdg_shear` (1/s, ≥ 0): Icepack's deformation terms, used when `closing` is
///   null (CICE convention);
/// - `closing` (1/s): null, or the host's net closing rate (SIS2 convention), with the
///   opening rate in `*opening`;
/// - `opening` (1/s, may be null when `closing` is null): out: the opening rate of the last
///   ridging pass;
/// - in/out state: `aicen`, `vicen`, `vsnon` (`ncat` each; 1, m, m), `trcrn` (`ntrcr·ncat`,
///   Fortran `trcrn(ntrcr, ncat)`), `aice0`, `aice` (1; `aice` is recomputed by the clean-up);
/// - `fluxes` (may be null): added to; `diag`, `categories` (may be null): written.
///
/// On error (bad input, or a state where Icepack aborts or would return a negative area,
/// volume or snow volume) the cell and the fluxes are unchanged and the message says why.
///
/// # Safety
/// Every non-null pointer must be valid for the reads and writes described.
#[unsafe(no_mangle)]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn pressridge_ridge_cell(
    ridger: *const PressridgeRidger,
    dt: f64,
    ndtd: i32,
    hin_max: *mut f64,
    rdg_conv: f64,
    rdg_shear: f64,
    closing: *const f64,
    opening: *mut f64,
    aicen: *mut f64,
    trcrn: *mut f64,
    vicen: *mut f64,
    vsnon: *mut f64,
    aice0: *mut f64,
    aice: *mut f64,
    tf: f64,
    fluxes: *mut PressridgeOceanFluxes,
    diag: *mut PressridgeStepDiagnostics,
    categories: *const PressridgeCategoryDiagnostics,
) -> i32 {
    // SAFETY: pointers checked before use; validity is the caller's promise.
    guard(|| unsafe {
        let r = ridger_ref(ridger)?;
        let (ncat, nt) = (r.ncat, r.layout.ntrcr());
        if ndtd < 1 {
            return Err(bad_value(format!("ndtd = {ndtd}: must be >= 1")));
        }
        let hin = slice_mut(hin_max, ncat + 1, "hin_max")?;
        let mode = if closing.is_null() {
            Closing::Deformation {
                convergence: rdg_conv,
                shear: rdg_shear,
            }
        } else {
            check_ptr(closing, "closing")?;
            check_ptr(opening, "opening")?;
            Closing::Rates {
                closing: *closing,
                opening: *opening,
            }
        };
        check_ptr(aice0, "aice0")?;
        check_ptr(aice, "aice")?;
        check_disjoint(
            &[
                Region::new(hin_max, ncat + 1, "hin_max"),
                Region::new(aicen, ncat, "aicen"),
                Region::new(vicen, ncat, "vicen"),
                Region::new(vsnon, ncat, "vsnon"),
                Region::new(trcrn, ncat * nt, "trcrn"),
                Region::new(aice0, 1, "aice0"),
                Region::new(aice, 1, "aice"),
                Region::new(opening, 1, "opening"),
            ],
            &[Region::new(closing, 1, "closing")],
        )?;
        let mut col = ColumnMut {
            aicen: slice_mut(aicen, ncat, "aicen")?,
            vicen: slice_mut(vicen, ncat, "vicen")?,
            vsnon: slice_mut(vsnon, ncat, "vsnon")?,
            trcrn: slice_mut(trcrn, ncat * nt, "trcrn")?,
            aice0: &mut *aice0,
            aice: &mut *aice,
        };
        let forcing = StepForcing {
            closing: mode,
            dt,
            ndtd: ndtd as u32,
            tf,
        };
        let mut fl = if fluxes.is_null() {
            OceanFluxes::default()
        } else {
            check_ptr(fluxes, "fluxes")?;
            let f = *fluxes;
            OceanFluxes {
                fresh: f.fresh,
                fsalt: f.fsalt,
                fhocn: f.fhocn,
                fpond: f.fpond,
                dpnd_ridge: f.dpnd_ridge,
                faero_ocn: f.faero_ocn,
                fiso_ocn: f.fiso_ocn,
                flux_bio: f.flux_bio,
            }
        };
        with_step_scratch(ncat, nt, |ws| -> FfiResult<()> {
            let d = ridge_step_column(&mut col, hin, forcing, &r.opts, &r.layout, &mut fl, ws)
                .map_err(|source| FfiError::from(ItdError::Column { column: 0, source }))?;
            hin[ncat] = d.hin_max_top;
            if !opening.is_null() {
                put(opening, d.opening, "opening")?;
            }
            if !fluxes.is_null() {
                fluxes.write(PressridgeOceanFluxes {
                    fresh: fl.fresh,
                    fsalt: fl.fsalt,
                    fhocn: fl.fhocn,
                    fpond: fl.fpond,
                    dpnd_ridge: fl.dpnd_ridge,
                    faero_ocn: fl.faero_ocn,
                    fiso_ocn: fl.fiso_ocn,
                    flux_bio: fl.flux_bio,
                });
            }
            if !diag.is_null() {
                put(diag, PressridgeStepDiagnostics::from(&d), "diag")?;
            }
            if !categories.is_null() {
                check_ptr(categories, "categories")?;
                put_categories(&*categories, ws, ncat)?;
            }
            Ok(())
        })
    })
}

/// Per-cell arrays of [`pressridge_ridge_cells`], each `ncol` values (column c at index c).
/// Inputs may be null where stated; outputs may be null (not returned).
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct PressridgeCellArrays {
    /// Icepack `rdg_conv` (1/s, ≥ 0); used when `closing` is null. Null: 0.
    pub rdg_conv: *const f64,
    /// Icepack `rdg_shear` (1/s, ≥ 0); used when `closing` is null. Null: 0.
    pub rdg_shear: *const f64,
    /// Host net closing rates (1/s); null for the CICE convention.
    pub closing: *const f64,
    /// Opening rate (1/s): input with `closing`; out: last pass's opening rate.
    pub opening: *mut f64,
    /// Freezing temperature (°C); null: −1.8 °C.
    pub tf: *const f64,
    /// Nonzero: step the cell; zero: leave it untouched. Null: every cell.
    pub valid: *const i32,
    /// Fresh-water flux (kg m⁻² s⁻¹), added to.
    pub fresh: *mut f64,
    /// Salt flux (kg m⁻² s⁻¹), added to.
    pub fsalt: *mut f64,
    /// Heat flux to the ocean (W m⁻²), added to.
    pub fhocn: *mut f64,
    /// Pond water lost by ridging (m, with sign), added to.
    pub fpond: *mut f64,
    /// Rate of area loss by ridging ice (1/s), written.
    pub dardg1dt: *mut f64,
    /// Rate of area gain by new ridges (1/s), written.
    pub dardg2dt: *mut f64,
    /// Rate of ice volume ridged (m/s), written.
    pub dvirdgdt: *mut f64,
    /// Aerosol flux to the ocean (kg m⁻² s⁻¹), `n_aero·ncol` values (Fortran
    /// `faero_ocn(n_aero, ncol)`: species fastest), added to. Null: not returned.
    pub faero_ocn: *mut f64,
    /// Water-isotope flux to the ocean (kg m⁻² s⁻¹), `n_iso·ncol` values
    /// (`fiso_ocn(n_iso, ncol)`), added to. Null: not returned.
    pub fiso_ocn: *mut f64,
    /// Biogeochemical flux to the ocean (mmol or kg m⁻² s⁻¹), `nbtrcr·ncol` values
    /// (`flux_bio(nbtrcr, ncol)`), added to. Null: not returned.
    pub flux_bio: *mut f64,
}

/// The ridging step of `ncol` cells in one call (arrays Fortran-ordered and contiguous:
/// `aicen(ncat, ncol)`, `vicen`, `vsnon` likewise, `trcrn(ntrcr, ncat, ncol)`, `aice0(ncol)`,
/// `aice(ncol)`; per-cell forcing and outputs in `cells`). `hin_max` (`ncat + 1` bounds, m)
/// is shared and not modified (with `cells.closing` null the top bound used is
/// `params.big`). Same semantics per cell as [`pressridge_ridge_cell`]. Stops at the first
/// failing cell (its 0-based index in the error; earlier cells are stepped, it and later ones
/// unchanged).
///
/// # Safety
/// Every non-null pointer must be valid for the reads and writes described.
#[unsafe(no_mangle)]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn pressridge_ridge_cells(
    ridger: *const PressridgeRidger,
    ncol: i64,
    dt: f64,
    ndtd: i32,
    hin_max: *const f64,
    aicen: *mut f64,
    trcrn: *mut f64,
    vicen: *mut f64,
    vsnon: *mut f64,
    aice0: *mut f64,
    aice: *mut f64,
    cells: *const PressridgeCellArrays,
) -> i32 {
    // SAFETY: pointers checked before use; validity is the caller's promise.
    guard(|| unsafe {
        let r = ridger_ref(ridger)?;
        let (ncat, nt) = (r.ncat, r.layout.ntrcr());
        if ncol < 1 {
            return Err(FfiError::new(
                PRESSRIDGE_ERR_BAD_SIZE,
                format!("ncol = {ncol}: must be at least 1"),
            ));
        }
        if ndtd < 1 {
            return Err(bad_value(format!("ndtd = {ndtd}: must be >= 1")));
        }
        let n = ncol as usize;
        check_ptr(cells, "cells")?;
        let c = *cells;
        let hin = slice(hin_max, ncat + 1, "hin_max")?;
        let written = [
            Region::new(aicen, ncat * n, "aicen"),
            Region::new(vicen, ncat * n, "vicen"),
            Region::new(vsnon, ncat * n, "vsnon"),
            Region::new(trcrn, nt * ncat * n, "trcrn"),
            Region::new(aice0, n, "aice0"),
            Region::new(aice, n, "aice"),
            Region::new(c.opening, n, "cells.opening"),
            Region::new(c.fresh, n, "cells.fresh"),
            Region::new(c.fsalt, n, "cells.fsalt"),
            Region::new(c.fhocn, n, "cells.fhocn"),
            Region::new(c.fpond, n, "cells.fpond"),
            Region::new(c.dardg1dt, n, "cells.dardg1dt"),
            Region::new(c.dardg2dt, n, "cells.dardg2dt"),
            Region::new(c.dvirdgdt, n, "cells.dvirdgdt"),
            Region::new(c.faero_ocn, r.layout.n_aero() * n, "cells.faero_ocn"),
            Region::new(c.fiso_ocn, r.layout.n_iso() * n, "cells.fiso_ocn"),
            Region::new(c.flux_bio, r.layout.n_bio() * n, "cells.flux_bio"),
        ];
        let read = [
            Region::new(hin_max, ncat + 1, "hin_max"),
            Region::new(c.rdg_conv, n, "cells.rdg_conv"),
            Region::new(c.rdg_shear, n, "cells.rdg_shear"),
            Region::new(c.closing, n, "cells.closing"),
            Region::new(c.tf, n, "cells.tf"),
            Region::new(c.valid, n, "cells.valid"),
        ];
        check_disjoint(&written, &read)?;
        let opt_in = |p: *const f64, what: &str| -> FfiResult<Option<&[f64]>> {
            if p.is_null() {
                Ok(None)
            } else {
                slice(p, n, what).map(Some)
            }
        };
        let opt_out = |p: *mut f64, what: &str| -> FfiResult<Option<&mut [f64]>> {
            if p.is_null() {
                Ok(None)
            } else {
                slice_mut(p, n, what).map(Some)
            }
        };
        let state = CellState {
            aicen: slice_mut(aicen, ncat * n, "aicen")?,
            vicen: slice_mut(vicen, ncat * n, "vicen")?,
            vsnon: slice_mut(vsnon, ncat * n, "vsnon")?,
            trcrn: slice_mut(trcrn, nt * ncat * n, "trcrn")?,
            aice0: slice_mut(aice0, n, "aice0")?,
            aice: slice_mut(aice, n, "aice")?,
        };
        let convergence = opt_in(c.rdg_conv, "cells.rdg_conv")?;
        let shear = opt_in(c.rdg_shear, "cells.rdg_shear")?;
        let closing = opt_in(c.closing, "cells.closing")?;
        let tf = opt_in(c.tf, "cells.tf")?;
        let opening = opt_out(c.opening, "cells.opening")?;
        if closing.is_some() && opening.is_none() {
            return Err(FfiError::new(
                super::PRESSRIDGE_ERR_NULL_POINTER,
                "cells.opening is null: the host's opening rates are needed with cells.closing",
            ));
        }
        let valid: Option<&[i32]> = if c.valid.is_null() {
            None
        } else {
            check_ptr(c.valid, "cells.valid")?;
            Some(std::slice::from_raw_parts(c.valid, n))
        };
        let fluxes = [
            opt_out(c.fresh, "cells.fresh")?,
            opt_out(c.fsalt, "cells.fsalt")?,
            opt_out(c.fhocn, "cells.fhocn")?,
            opt_out(c.fpond, "cells.fpond")?,
        ];
        let species_out = |p: *mut f64, k: usize, what: &str| -> FfiResult<Option<&mut [f64]>> {
            if p.is_null() || k == 0 {
                Ok(None)
            } else {
                slice_mut(p, k * n, what).map(Some)
            }
        };
        let [na, ni, nb] = species_counts(&r.layout);
        let species = [
            species_out(c.faero_ocn, na, "cells.faero_ocn")?,
            species_out(c.fiso_ocn, ni, "cells.fiso_ocn")?,
            species_out(c.flux_bio, nb, "cells.flux_bio")?,
        ];
        let rates = [
            opt_out(c.dardg1dt, "cells.dardg1dt")?,
            opt_out(c.dardg2dt, "cells.dardg2dt")?,
            opt_out(c.dvirdgdt, "cells.dvirdgdt")?,
        ];
        let out = CellOutputs {
            opening,
            fluxes,
            rates,
            species,
        };
        let selected = |i: usize| valid.is_none_or(|m| m[i] != 0);
        let forcing = CellForcing {
            convergence,
            shear,
            closing,
            tf,
            dt,
            ndtd: ndtd as u32,
            step: Some(&selected),
        };
        with_step_scratch(ncat, nt, |ws| {
            ridge_step_cells(state, forcing, out, hin, &r.opts, &r.layout, ws)
                .map_err(FfiError::from)
        })
    })
}
