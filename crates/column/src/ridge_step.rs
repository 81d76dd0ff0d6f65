//! The complete ridging step of one grid cell for a host model: ice area, ice volume, snow
//! volume and every tracer move together, and the snow, pond water and cleaned-up ice that
//! leave the ice go to the ocean fluxes. Semantics of Icepack's public `icepack_step_ridge`
//! (`icepack_mechred.F90`: `ridge_ice` with `asum_ridging`, `ridge_prep`, `ridge_itd`,
//! `ridge_shift` and the repeated ridging passes; then `cleanup_itd` of `icepack_itd.F90`),
//! written anew on the participation and redistribution of [`super::participation`] and
//! [`super::redistribution`].
//!
//! Two calling conventions:
//! - [`Closing::Deformation`] (CICE): the net closing rate is the Flato–Hibler rate
//!   `C_s·shear + convergence` (1/s), raised to remove any area above 1 in one step, and the
//!   opening rate makes the total area 1 (`ridge_prep`). The top category bound is then taken
//!   as [`ItdParams::big`] so all ridged ice fits (Icepack overwrites `hin_max(ncat)`).
//! - [`Closing::Rates`] (SIS2): the host gives the closing and opening rates (1/s) and the
//!   category bounds are used as given.
//!
//! Where Icepack aborts or returns negative areas or volumes (see `docs/strength.md`),
//! this step returns a [`ColumnError`] naming the cause, and the column is left unchanged.
//! Two Icepack defects are removed because they produce garbage from valid input, and both
//! change nothing above round-off elsewhere: a thickness range entirely beyond the
//! `exp_argmax` cut-off of the exponential redistribution gets no ridged ice (Icepack gives
//! it a negative volume of order e⁻¹⁰⁰), and a cell with no area above `puny` does not ridge
//! (Icepack divides by zero).
//!
//! Files: this one holds the step's interface (options, forcing, column, fluxes,
//! diagnostics) and [`ridge_step_column`]; `constants.rs` the thermodynamic constants,
//! `workspace.rs` the scratch, `passes.rs` the ridging passes, `checks.rs` the input and
//! output checks; `batch.rs` the step over `ndarray` views and `cells.rs` over a host's
//! contiguous cell arrays.

pub(crate) mod area_volume;
pub(crate) mod batch;
pub(crate) mod cells;
mod checks;
mod cleanup;
mod constants;
mod passes;
mod workspace;

pub use constants::{RidgeStepParams, SaltFlux, StepParamMeta};
pub use workspace::StepWorkspace;

use super::ColumnError;
use super::params::{ItdParams, Participation, Redistribution};
use super::tracers::{MAX_AERO, MAX_ISO, MAX_NBTRCR, TracerLayout};
use checks::{check_inputs, check_outputs};
use passes::step;
use workspace::Saved;

/// What every routine of one column's step reads and none changes: the category bounds
/// (m), the time step (s; the clean-up's is `ndtd` times the ridging passes'), the freezing
/// temperature (°C), the options and the tracer layout.
#[derive(Clone, Copy)]
pub(crate) struct StepContext<'a> {
    pub(crate) hin_max: &'a [f64],
    pub(crate) dt: f64,
    pub(crate) tf: f64,
    pub(crate) opts: &'a RidgeStepOptions,
    pub(crate) layout: &'a TracerLayout,
}

/// Options of the ridging step; the default is Icepack's.
#[derive(Debug, Clone, Copy)]
pub struct RidgeStepOptions {
    /// Participation function (Icepack `krdg_partic`).
    pub participation: Participation,
    /// Ridged-ice redistribution (Icepack `krdg_redist`).
    pub redistribution: Redistribution,
    /// Ridging constants (`mu_rdg`, `Cs`, `puny`, ...).
    pub params: ItdParams,
    /// Thermodynamic constants and clean-up thresholds.
    pub step: RidgeStepParams,
    /// Run the clean-up after ridging (Icepack `docleanup`, default true).
    pub cleanup: bool,
    /// Rebin categories in the clean-up (Icepack `dorebin`, default true).
    pub rebin: bool,
}

impl Default for RidgeStepOptions {
    fn default() -> Self {
        Self {
            participation: Participation::default(),
            redistribution: Redistribution::default(),
            params: ItdParams::default(),
            step: RidgeStepParams::default(),
            cleanup: true,
            rebin: true,
        }
    }
}

/// Where the closing and opening rates come from.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Closing {
    /// CICE: from the deformation, Icepack `rdg_conv` = −min(div u, 0) (1/s, ≥ 0) and
    /// `rdg_shear` = ½(Δ − |div u|) (1/s, ≥ 0); see [`deformation_terms`].
    Deformation {
        /// Convergence term (1/s).
        convergence: f64,
        /// Shear term (1/s); a fraction C_s of it closes.
        shear: f64,
    },
    /// SIS2: the host's net closing and opening rates (1/s, ≥ 0).
    Rates {
        /// Net closing rate (1/s).
        closing: f64,
        /// Opening rate (1/s).
        opening: f64,
    },
}

/// Forcing of one column over one dynamics step.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StepForcing {
    /// Closing and opening.
    pub closing: Closing,
    /// Dynamics time step (s, > 0).
    pub dt: f64,
    /// Dynamics subcycles per thermodynamic step (≥ 1); the ocean fluxes are averaged over
    /// `ndtd · dt`.
    pub ndtd: u32,
    /// Freezing temperature (°C), given to emptied categories' surface temperature.
    pub tf: f64,
}

/// One column's state, updated in place.
#[derive(Debug)]
pub struct ColumnMut<'a> {
    /// Ice area per category (1), length `ncat`.
    pub aicen: &'a mut [f64],
    /// Ice volume per unit cell area (m), length `ncat`.
    pub vicen: &'a mut [f64],
    /// Snow volume per unit cell area (m), length `ncat`.
    pub vsnon: &'a mut [f64],
    /// Tracers, `trcrn[n * ntrcr + it]` (units per tracer, see [`TracerLayout`]).
    pub trcrn: &'a mut [f64],
    /// Open-water fraction (1).
    pub aice0: &'a mut f64,
    /// Total ice area (1); recomputed only by the clean-up.
    pub aice: &'a mut f64,
}

impl ColumnMut<'_> {
    /// Icepack's `atrcrn`: the conserved amount of every tracer of every category
    /// ([`TracerLayout::amount`] with the category's area, ice and snow volume), into
    /// `atrc[n * ntrcr + it]`. The ridging passes and `shift_ice` start from it.
    pub(crate) fn tracer_amounts(&self, layout: &TracerLayout, atrc: &mut [f64]) {
        let nt = layout.ntrcr();
        for n in 0..self.aicen.len() {
            let trc = &self.trcrn[n * nt..(n + 1) * nt];
            for it in 0..nt {
                atrc[n * nt + it] =
                    layout.amount(it, trc, self.aicen[n], self.vicen[n], self.vsnon[n]);
            }
        }
    }

    /// Every category's tracers from the conserved amounts `atrc` (as
    /// [`ColumnMut::tracer_amounts`] lays them out) and its new area, ice and snow volume
    /// ([`TracerLayout::compute`], Icepack's `icepack_compute_tracers`). The ridging passes and
    /// `shift_ice` end with it.
    pub(crate) fn tracers_from_amounts(
        &mut self,
        layout: &TracerLayout,
        atrc: &[f64],
        puny: f64,
        tf: f64,
    ) {
        let nt = layout.ntrcr();
        for n in 0..self.aicen.len() {
            layout.compute(
                &atrc[n * nt..(n + 1) * nt],
                self.aicen[n],
                self.vicen[n],
                self.vsnon[n],
                puny,
                tf,
                &mut self.trcrn[n * nt..(n + 1) * nt],
            );
        }
    }
}

/// Fluxes to the ocean. The step **adds** to these (as Icepack adds to its arguments);
/// zero them first to get one step's values.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct OceanFluxes {
    /// Fresh water into the ocean (kg m⁻² s⁻¹, averaged over `ndtd·dt`): half the snow on
    /// ridging ice, and the ice and snow of zapped categories.
    pub fresh: f64,
    /// Salt into the ocean (kg m⁻² s⁻¹, over `ndtd·dt`) from zapped ice.
    pub fsalt: f64,
    /// Heat flux to the ocean (W m⁻², over `ndtd·dt`); negative: the ocean melts the snow and
    /// ice put into it.
    pub fhocn: f64,
    /// Pond water lost by ridging, with sign (m over the cell, per step, not a rate):
    /// Icepack's `fpond`, `−dpnd_ridge`.
    pub fpond: f64,
    /// Pond water drained by ridging (m over the cell, per step; Icepack `dpnd_ridge`;
    /// overwritten, not added).
    pub dpnd_ridge: f64,
    /// Aerosol into the ocean per species (kg m⁻² s⁻¹, over `ndtd·dt`; Icepack `faero_ocn`):
    /// with the snow that ridging puts into the ocean, and with zapped and excess ice and snow.
    /// The layout's species first; the rest stay as they are.
    pub faero_ocn: [f64; MAX_AERO],
    /// Water isotopes into the ocean per species (kg m⁻² s⁻¹, over `ndtd·dt`; Icepack
    /// `fiso_ocn`), as `faero_ocn`.
    pub fiso_ocn: [f64; MAX_ISO],
    /// Biogeochemical tracers into the ocean per bio tracer (the tracer's unit times m s⁻¹,
    /// e.g. mmol m⁻² s⁻¹, over `ndtd·dt`; Icepack `flux_bio`), as `faero_ocn`: with ridged
    /// snow (vertical bio tracers) and with zapped ice and snow
    /// ([`TracerLayout::with_bgc`](crate::details::TracerLayout::with_bgc)).
    pub flux_bio: [f64; MAX_NBTRCR],
}

/// Cell diagnostics of one step.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct StepDiagnostics {
    /// Opening rate of the last ridging pass (1/s; Icepack `opening`).
    pub opening: f64,
    /// Net closing rate of the first pass (1/s): the host's, or `ridge_prep`'s.
    pub closing: f64,
    /// Area of ridging ice removed per unit time, all passes (1/s; `dardg1dt`).
    pub dardg1dt: f64,
    /// Area of new ridges per unit time, all passes (1/s; `dardg2dt`).
    pub dardg2dt: f64,
    /// Volume of ridging ice per unit time, all passes (m/s; `dvirdgdt`).
    pub dvirdgdt: f64,
    /// Top category bound used (m): `params.big` for [`Closing::Deformation`], else
    /// `hin_max[ncat]` (Icepack's `hin_max(ncat)` after the call).
    pub hin_max_top: f64,
    /// Ridging passes done.
    pub niter: usize,
    /// Ice volume put into the ocean (m over the cell): zapped and excess ice (pressridge,
    /// not Icepack; for the host's budgets).
    pub ice_to_ocean: f64,
    /// Snow volume put into the ocean (m over the cell): the share `1 − fsnowrdg` of the snow
    /// on ridging ice, zapped and excess snow (pressridge, not Icepack).
    pub snow_to_ocean: f64,
    /// A category ridged with μ_rdg from a table queried outside its thickness range (the
    /// end value used; [`Redistribution::Table`]).
    pub mu_rdg_clamped: bool,
}

/// Icepack's ridging terms from the host's strain rates (all 1/s): `rdg_conv` = −min(div u, 0)
/// and `rdg_shear` = ½(Δ − |div u|) with Δ = √(div u² + (shear/e)²), e = 2 the ellipse aspect
/// ratio, `shear` the shear strain-rate magnitude √((u_x − v_y)² + (u_y + v_x)²) (CICE history
/// `shear`, converted to 1/s). Returns `(convergence, shear_term)`.
pub fn deformation_terms(divu: f64, shear: f64) -> (f64, f64) {
    let e_inv2 = 0.25;
    let delta = (divu * divu + e_inv2 * shear * shear).sqrt();
    (-f64::min(divu, 0.0), 0.5 * (delta - divu.abs()))
}

/// Seconds per day, for the %/day strain rates of CICE history files.
pub const SECONDS_PER_DAY: f64 = 86_400.0;

/// Converts a CICE history strain rate (`divu`, `shear`: units "%/day") to 1/s.
pub fn percent_per_day_to_per_second(x: f64) -> f64 {
    x / 100.0 / SECONDS_PER_DAY
}

/// The ridging step of one column, in place (Icepack `icepack_step_ridge`).
///
/// `hin_max` (m) has `ncat + 1` bounds, `col` the column's state, `layout` its tracers.
/// Adds the ocean fluxes to `fluxes`; per-category diagnostics are left in `ws`. On error
/// the column and the fluxes are unchanged. Does not allocate.
///
/// # Panics
/// If the slice lengths do not match `ws` (the batched drivers check shapes first).
///
/// # Example
///
/// A five-category CICE column (one ice and one snow layer, no optional tracers) closing
/// under convergence for one hour: ice moves into thicker categories, area and ice volume
/// are conserved with the open water and the fluxes (what snow does not stay on the ridges
/// goes to the ocean).
///
/// ```
/// use pressridge_column::details::{Closing, OceanFluxes, TracerLayout};
/// use pressridge_column::details::CiceTracerFlags;
/// use pressridge_column::{
///     ColumnMut, RidgeStepOptions, StepForcing, StepWorkspace, ridge_step_column,
/// };
/// let layout = TracerLayout::cice(1, 1, CiceTracerFlags::default()).unwrap();
/// let (ncat, nt) = (5, layout.ntrcr());
/// let hin_max = [0.0, 0.64, 1.39, 2.47, 4.57, 9.33]; // category bounds (m)
/// let mut aicen = vec![0.3, 0.25, 0.2, 0.1, 0.05]; // area fractions (1)
/// let mut vicen = vec![0.12, 0.25, 0.38, 0.33, 0.3]; // ice volume (m)
/// let mut vsnon = vec![0.01, 0.02, 0.03, 0.02, 0.01]; // snow volume (m)
/// let mut trcrn = vec![0.0; ncat * nt];
/// let (mut aice0, mut aice) = (0.1, 0.9);
/// let (area0, ice0) = (aice0 + aicen.iter().sum::<f64>(), vicen.iter().sum::<f64>());
/// let mut fluxes = OceanFluxes::default();
/// let mut ws = StepWorkspace::new(ncat, nt);
/// let forcing = StepForcing {
///     closing: Closing::Deformation { convergence: 1e-6, shear: 0.0 }, // 1/s
///     dt: 3600.0, // s
///     ndtd: 1,
///     tf: -1.8, // °C
/// };
/// let mut col = ColumnMut {
///     aicen: &mut aicen,
///     vicen: &mut vicen,
///     vsnon: &mut vsnon,
///     trcrn: &mut trcrn,
///     aice0: &mut aice0,
///     aice: &mut aice,
/// };
/// ridge_step_column(&mut col, &hin_max, forcing, &RidgeStepOptions::default(), &layout,
///     &mut fluxes, &mut ws).unwrap();
/// let area = aice0 + aicen.iter().sum::<f64>();
/// assert!((area - area0).abs() < 1e-12 && (vicen.iter().sum::<f64>() - ice0).abs() < 1e-12);
/// assert!(aicen[0] < 0.3 && aicen[4] > 0.05); // thin ice ridged into thick
/// ```
pub fn ridge_step_column(
    col: &mut ColumnMut<'_>,
    hin_max: &[f64],
    forcing: StepForcing,
    opts: &RidgeStepOptions,
    layout: &TracerLayout,
    fluxes: &mut OceanFluxes,
    ws: &mut StepWorkspace,
) -> Result<StepDiagnostics, ColumnError> {
    let ncat = ws.ncat();
    let nt = layout.ntrcr();
    assert!(
        col.aicen.len() == ncat
            && col.vicen.len() == ncat
            && col.vsnon.len() == ncat
            && col.trcrn.len() == ncat * nt
            && ws.ntrcr == nt
            && hin_max.len() == ncat + 1,
        "column lengths differ from the workspace"
    );
    check_inputs(col, hin_max, &forcing)?;
    // The result is checked after the fact; keep the input (in reused scratch, no
    // allocation) to leave the column unchanged on error.
    let saved = Saved::take(col, ws);
    let mut f = *fluxes;
    let r = step(col, hin_max, forcing, opts, layout, &mut f, ws).and_then(|d| {
        check_outputs(col, &f, layout.n_bio())?;
        Ok(d)
    });
    match r {
        Ok(d) => {
            *fluxes = f;
            Ok(d)
        }
        Err(e) => {
            saved.restore(col, ws);
            Err(e)
        }
    }
}
