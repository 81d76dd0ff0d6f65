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

// Several parallel per-category arrays are indexed by the category number, as in Icepack.
#![allow(clippy::needless_range_loop)]

use super::cleanup::cleanup_itd;
use super::params::{ItdParams, Participation, Redistribution};
use super::redistribution::{RidgeGeometry, category_fractions_all};
use super::ridging::close_and_open;
use super::tracers::TracerLayout;
use super::{ColumnError, Workspace};

/// How the zapped ice's salt flux is computed (Icepack `saltflux_option`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum SaltFlux {
    /// Zapped ice carries [`RidgeStepParams::ice_ref_salinity`] (Icepack's default
    /// `"constant"`; salt is then not conserved by the clean-up).
    #[default]
    Constant,
    /// Zapped ice carries its own mean layer salinity (`"prognostic"`; conserving).
    Prognostic,
}

impl SaltFlux {
    /// Icepack's `saltflux_option` name: `constant` or `prognostic` (the command line's and
    /// Python's spelling too).
    pub fn name(self) -> &'static str {
        match self {
            SaltFlux::Constant => "constant",
            SaltFlux::Prognostic => "prognostic",
        }
    }

    /// The option called `name` (`constant` or `prognostic`).
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "constant" => Some(SaltFlux::Constant),
            "prognostic" => Some(SaltFlux::Prognostic),
            _ => None,
        }
    }
}

/// Thermodynamic constants and clean-up thresholds of the ridging step. `Default` is
/// Icepack's (`icepack_parameters.F90`, `icepack_therm_shared.F90`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RidgeStepParams {
    /// Snow density ρ_s (kg/m³). Icepack `rhos` = 330.
    pub rhos: f64,
    /// Latent heat of melting of fresh ice L_f (J/kg). Icepack `Lfresh` = Lsub − Lvap = 3.34e5.
    pub lfresh: f64,
    /// Specific heat of fresh ice (J kg⁻¹ K⁻¹). Icepack `cp_ice` = 2106.
    pub cp_ice: f64,
    /// Fraction of the snow on ridging ice that stays on the new ridge (1); the rest goes to
    /// the ocean. Icepack `fsnowrdg` = 0.5.
    pub fsnowrdg: f64,
    /// Salinity of zapped ice for [`SaltFlux::Constant`] (ppt). Icepack `ice_ref_salinity` = 4.
    pub ice_ref_salinity: f64,
    /// Salt-flux option of the clean-up.
    pub salt_flux: SaltFlux,
    /// Cell ice area (1) below which all ice is zapped. Icepack `itd_area_min` = 1e-11.
    pub itd_area_min: f64,
    /// Cell ice mass ρ_i·aice (kg/m², as Icepack computes it) below which all ice is zapped.
    /// Icepack `itd_mass_min` = 1e-10.
    pub itd_mass_min: f64,
    /// Snow thickness (m) above which the snow temperature is checked. Icepack `hs_min` = 1e-4.
    pub hs_min: f64,
    /// Lowest physical snow temperature (°C). Icepack `Tmin` = −100.
    pub tmin: f64,
}

impl Default for RidgeStepParams {
    fn default() -> Self {
        Self {
            rhos: 330.0,
            lfresh: 2.835e6 - 2.501e6,
            cp_ice: 2106.0,
            fsnowrdg: 0.5,
            ice_ref_salinity: 4.0,
            salt_flux: SaltFlux::Constant,
            itd_area_min: 1e-11,
            itd_mass_min: 1e-10,
            hs_min: 1e-4,
            tmin: -100.0,
        }
    }
}

/// Name, units and meaning of one settable constant of [`RidgeStepParams`] (the type the
/// [`ItdParams`](super::ItdParams) fields are listed with too).
pub type StepParamMeta = super::params::ParamMeta;

const fn step_param(
    name: &'static str,
    units: &'static str,
    description: &'static str,
) -> StepParamMeta {
    StepParamMeta {
        name,
        units,
        description,
    }
}

impl RidgeStepParams {
    /// The numeric constants, in field order: the one list the faces (command line
    /// `--param`, Python keywords, output attributes) take their names and units from.
    /// [`RidgeStepParams::salt_flux`] is an option, not a number, and is not in it.
    pub const FIELDS: &'static [StepParamMeta] = &[
        step_param("rhos", "kg m-3", "snow density (Icepack rhos)"),
        step_param(
            "lfresh",
            "J kg-1",
            "latent heat of melting of fresh ice (Icepack Lfresh)",
        ),
        step_param(
            "cp_ice",
            "J kg-1 K-1",
            "specific heat of fresh ice (Icepack cp_ice)",
        ),
        step_param(
            "fsnowrdg",
            "1",
            "fraction of the snow on ridging ice that stays on the ridge (Icepack fsnowrdg)",
        ),
        step_param(
            "ice_ref_salinity",
            "ppt",
            "salinity of zapped ice with the constant salt flux (Icepack ice_ref_salinity)",
        ),
        step_param(
            "itd_area_min",
            "1",
            "cell ice area below which all ice is zapped (Icepack itd_area_min)",
        ),
        step_param(
            "itd_mass_min",
            "kg m-2",
            "cell ice mass below which all ice is zapped (Icepack itd_mass_min)",
        ),
        step_param(
            "hs_min",
            "m",
            "snow thickness above which the snow temperature is checked (Icepack hs_min)",
        ),
        step_param(
            "tmin",
            "degC",
            "lowest physical snow temperature (Icepack Tmin)",
        ),
    ];

    /// The value of the constant `name` (a [`RidgeStepParams::FIELDS`] name), in its units.
    pub fn get(&self, name: &str) -> Option<f64> {
        Some(match name {
            "rhos" => self.rhos,
            "lfresh" => self.lfresh,
            "cp_ice" => self.cp_ice,
            "fsnowrdg" => self.fsnowrdg,
            "ice_ref_salinity" => self.ice_ref_salinity,
            "itd_area_min" => self.itd_area_min,
            "itd_mass_min" => self.itd_mass_min,
            "hs_min" => self.hs_min,
            "tmin" => self.tmin,
            _ => return None,
        })
    }

    /// Sets the constant `name` (a [`RidgeStepParams::FIELDS`] name, units as listed there).
    /// Rejects unknown names and values [`RidgeStepParams::validate`] refuses; a rejected
    /// value leaves `self` unchanged.
    pub fn set(&mut self, name: &str, value: f64) -> Result<(), super::ItdError> {
        let mut new = *self;
        let slot = match name {
            "rhos" => &mut new.rhos,
            "lfresh" => &mut new.lfresh,
            "cp_ice" => &mut new.cp_ice,
            "fsnowrdg" => &mut new.fsnowrdg,
            "ice_ref_salinity" => &mut new.ice_ref_salinity,
            "itd_area_min" => &mut new.itd_area_min,
            "itd_mass_min" => &mut new.itd_mass_min,
            "hs_min" => &mut new.hs_min,
            "tmin" => &mut new.tmin,
            _ => {
                return Err(super::ItdError::Parameter {
                    name: "unknown",
                    value,
                    reason: "unknown ridging-step constant (see RidgeStepParams::FIELDS)",
                });
            }
        };
        *slot = value;
        new.validate()?;
        *self = new;
        Ok(())
    }

    /// Checks every value (finite; densities, heats and thresholds positive; `fsnowrdg` in
    /// [0, 1]; `ice_ref_salinity` ≥ 0).
    pub fn validate(&self) -> Result<(), super::ItdError> {
        let bad = |name: &'static str, value: f64, reason: &'static str| {
            Err(super::ItdError::Parameter {
                name,
                value,
                reason,
            })
        };
        for (name, v) in [
            ("rhos", self.rhos),
            ("lfresh", self.lfresh),
            ("cp_ice", self.cp_ice),
            ("itd_area_min", self.itd_area_min),
            ("itd_mass_min", self.itd_mass_min),
            ("hs_min", self.hs_min),
        ] {
            if !(v.is_finite() && v > 0.0) {
                return bad(name, v, "must be finite and positive");
            }
        }
        if !(self.fsnowrdg >= 0.0 && self.fsnowrdg <= 1.0) {
            return bad("fsnowrdg", self.fsnowrdg, "must be in [0, 1]");
        }
        if !(self.ice_ref_salinity.is_finite() && self.ice_ref_salinity >= 0.0) {
            return bad("ice_ref_salinity", self.ice_ref_salinity, "must be >= 0");
        }
        if !self.tmin.is_finite() {
            return bad("tmin", self.tmin, "must be finite");
        }
        Ok(())
    }
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
}

/// Scratch and per-category diagnostics of the ridging step, sized once for `ncat`
/// categories and `ntrcr` tracers. One per thread gives allocation-free column calls.
#[derive(Debug, Clone)]
pub struct StepWorkspace {
    pub(crate) core: Workspace,
    ntrcr: usize,
    pub(crate) vsnon_init: Vec<f64>,
    pub(crate) atrcrn: Vec<f64>,
    pub(crate) hicen: Vec<f64>,
    mraft: Vec<f64>,
    farea: Vec<f64>,
    fvol: Vec<f64>,
    /// The input state, kept to restore the column on error.
    save: Vec<f64>,
    /// Participation of each category, last pass (1; Icepack `aparticn`).
    pub aparticn: Vec<f64>,
    /// Mean ridge thickness / ridging-ice thickness, last pass (1; `krdgn`).
    pub krdgn: Vec<f64>,
    /// Area of ridging ice per unit time, last pass in which the category ridged (1/s;
    /// `dardg1ndt`).
    pub dardg1ndt: Vec<f64>,
    /// Area of new ridges per unit time, same pass (1/s; `dardg2ndt`).
    pub dardg2ndt: Vec<f64>,
    /// Volume of ridging ice per unit time, same pass (m/s; `dvirdgndt`).
    pub dvirdgndt: Vec<f64>,
    /// Rafted new-ridge area per step (1; exponential redistribution only; `araftn`).
    pub araftn: Vec<f64>,
    /// Rafting ice volume per step (m; exponential redistribution only; `vraftn`).
    pub vraftn: Vec<f64>,
    /// New-ridge area from category 1 landing in each category, per step (1; exponential
    /// redistribution only; `aredistn`).
    pub aredistn: Vec<f64>,
    /// Same for volume (m; `vredistn`).
    pub vredistn: Vec<f64>,
    /// Categories emptied by the clean-up (Icepack sets `first_ice` for them).
    pub zapped: Vec<bool>,
}

impl StepWorkspace {
    /// Scratch for `ncat` categories and `ntrcr` tracers (the only allocation).
    pub fn new(ncat: usize, ntrcr: usize) -> Self {
        let z = vec![0.0; ncat];
        Self {
            core: Workspace::new(ncat),
            ntrcr,
            vsnon_init: z.clone(),
            atrcrn: vec![0.0; ncat * ntrcr],
            hicen: z.clone(),
            mraft: z.clone(),
            farea: z.clone(),
            fvol: z.clone(),
            save: Vec::with_capacity(3 * ncat + ncat * ntrcr),
            aparticn: z.clone(),
            krdgn: z.clone(),
            dardg1ndt: z.clone(),
            dardg2ndt: z.clone(),
            dvirdgndt: z.clone(),
            araftn: z.clone(),
            vraftn: z.clone(),
            aredistn: z.clone(),
            vredistn: z,
            zapped: vec![false; ncat],
        }
    }

    /// Number of categories.
    pub fn ncat(&self) -> usize {
        self.core.ncat()
    }

    /// Number of tracers per category.
    pub fn ntrcr(&self) -> usize {
        self.ntrcr
    }

    fn reset_diagnostics(&mut self) {
        for v in [
            &mut self.aparticn,
            &mut self.krdgn,
            &mut self.dardg1ndt,
            &mut self.dardg2ndt,
            &mut self.dvirdgndt,
            &mut self.araftn,
            &mut self.vraftn,
            &mut self.aredistn,
            &mut self.vredistn,
            &mut self.mraft,
            &mut self.core.ardg1n,
            &mut self.core.ardg2n,
            &mut self.core.virdgn,
        ] {
            v.fill(0.0);
        }
        self.zapped.fill(false);
    }
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
        check_outputs(col, &f)?;
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

/// The input scalars kept for restoring the column on error (the arrays go to `ws.save`).
struct Saved {
    aice0: f64,
    aice: f64,
}

impl Saved {
    fn take(col: &ColumnMut<'_>, ws: &mut StepWorkspace) -> Self {
        ws.save.clear();
        ws.save.extend_from_slice(col.aicen);
        ws.save.extend_from_slice(col.vicen);
        ws.save.extend_from_slice(col.vsnon);
        ws.save.extend_from_slice(col.trcrn);
        Saved {
            aice0: *col.aice0,
            aice: *col.aice,
        }
    }

    fn restore(self, col: &mut ColumnMut<'_>, ws: &StepWorkspace) {
        let ncat = col.aicen.len();
        let s = &ws.save;
        col.aicen.copy_from_slice(&s[..ncat]);
        col.vicen.copy_from_slice(&s[ncat..2 * ncat]);
        col.vsnon.copy_from_slice(&s[2 * ncat..3 * ncat]);
        col.trcrn.copy_from_slice(&s[3 * ncat..]);
        *col.aice0 = self.aice0;
        *col.aice = self.aice;
    }
}

fn not_finite(var: &'static str, category: Option<usize>, value: f64) -> ColumnError {
    ColumnError::NotFinite {
        var,
        category,
        value,
    }
}

fn check_inputs(
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

fn check_outputs(col: &ColumnMut<'_>, f: &OceanFluxes) -> Result<(), ColumnError> {
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
    for (var, x) in [
        ("aice0", *col.aice0),
        ("fresh", f.fresh),
        ("fsalt", f.fsalt),
        ("fhocn", f.fhocn),
        ("fpond", f.fpond),
    ] {
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
}

fn step(
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

    let mut niter = 0;
    loop {
        niter += 1;
        let aksum = ridge_itd(col, opts, ws);
        ridge_shift(
            col,
            hin_max,
            top,
            dt,
            forcing.tf,
            opts,
            layout,
            aksum,
            closing_net,
            &mut opning,
            &mut s,
            ws,
        )?;
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
    fluxes.fpond -= s.mpond;
    fluxes.dpnd_ridge = s.mpond;
    d.snow_to_ocean = s.vsno_ocean;

    if opts.cleanup {
        let (vice, vsno) = cleanup_itd(
            col,
            hin_max,
            dt * f64::from(forcing.ndtd),
            forcing.tf,
            opts.rebin,
            puny,
            p.rhoi,
            &opts.step,
            layout,
            fluxes,
            ws,
        )?;
        d.ice_to_ocean = vice;
        d.snow_to_ocean += vsno;
    }
    Ok(d)
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

/// Icepack `ridge_itd`: participation, ridge geometry, rafting mask; returns `aksum`.
fn ridge_itd(col: &ColumnMut<'_>, opts: &RidgeStepOptions, ws: &mut StepWorkspace) -> f64 {
    let p = &opts.params;
    let w = &mut ws.core;
    let aksum = w.prepare_ridging(
        opts.participation,
        opts.redistribution,
        p,
        *col.aice0,
        col.aicen,
        col.vicen,
    );
    for n in 0..w.ncat() {
        if opts.redistribution == Redistribution::Exponential && col.aicen[n] > p.puny {
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

/// Icepack `ridge_shift`: one ridging pass with area, volume, snow and tracers.
#[allow(clippy::too_many_arguments)]
fn ridge_shift(
    col: &mut ColumnMut<'_>,
    hin_max: &[f64],
    top: f64,
    dt: f64,
    tf: f64,
    opts: &RidgeStepOptions,
    layout: &TracerLayout,
    aksum: f64,
    closing_net: f64,
    opning: &mut f64,
    s: &mut Sums,
    ws: &mut StepWorkspace,
) -> Result<(), ColumnError> {
    let p = &opts.params;
    let c = &opts.step;
    let puny = p.puny;
    let ncat = ws.ncat();
    let nt = layout.ntrcr();
    let nslyr = layout.nslyr as f64;
    for n in 0..ncat {
        ws.core.aicen_init[n] = col.aicen[n];
        ws.core.vicen_init[n] = col.vicen[n];
        ws.vsnon_init[n] = col.vsnon[n];
        let trc = &col.trcrn[n * nt..(n + 1) * nt];
        for it in 0..nt {
            ws.atrcrn[n * nt + it] =
                layout.amount(it, trc, col.aicen[n], col.vicen[n], col.vsnon[n]);
        }
    }
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
        s.msnow_mlt += c.rhos * vsrdgn * one_minus_f;
        s.vsno_ocean += vsrdgn * one_minus_f;
        if let (Some(ia), Some(ip), Some(ih)) = (layout.nt_alvl, layout.nt_apnd, layout.nt_hpnd) {
            s.mpond += ardg1n * trc[ip] * trc[ih] * trc[ia];
        }
        for k in 0..layout.nslyr {
            let esrdgn = vsrdgn * trc[layout.nt_qsno + k] / nslyr;
            s.esnow_mlt += esrdgn * one_minus_f;
        }
        for it in 0..nt {
            ws.atrcrn[n * nt + it] -= layout.amount(it, trc, ardg1n, virdgn, vsrdgn);
        }

        let g = RidgeGeometry {
            hi: ws.core.hi[n],
            hrmin: ws.core.hrmin[n],
            hrmax: ws.core.hrmax[n],
            hrexp: ws.core.hrexp[n],
            krdg: ws.core.krdg[n],
        };
        category_fractions_all(
            opts.redistribution,
            p,
            &g,
            hin_max,
            top,
            &mut ws.farea,
            &mut ws.fvol,
        );
        let exponential = opts.redistribution == Redistribution::Exponential;
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
        }
    }
    for n in 0..ncat {
        layout.compute(
            &ws.atrcrn[n * nt..(n + 1) * nt],
            col.aicen[n],
            col.vicen[n],
            col.vsnon[n],
            puny,
            tf,
            &mut col.trcrn[n * nt..(n + 1) * nt],
        );
    }
    Ok(())
}

#[cfg(test)]
mod step_param_tests {
    use super::*;

    /// Every listed constant reads and writes its own field; bad values are refused by name
    /// and leave the parameters unchanged.
    #[test]
    fn fields_list_get_and_set_agree() {
        let d = RidgeStepParams::default();
        for f in RidgeStepParams::FIELDS {
            let v = d.get(f.name).unwrap();
            let mut p = d;
            p.set(f.name, v * 0.5 + 0.25).unwrap();
            assert_eq!(p.get(f.name), Some(v * 0.5 + 0.25), "{}", f.name);
            for g in RidgeStepParams::FIELDS.iter().filter(|g| g.name != f.name) {
                assert_eq!(p.get(g.name), d.get(g.name), "{} moved {}", f.name, g.name);
            }
        }
        let mut p = d;
        let e = p.set("rhos", -1.0).unwrap_err().to_string();
        assert!(e.contains("rhos"), "{e}");
        assert!(
            p.set("fsnowrdg", 1.5)
                .unwrap_err()
                .to_string()
                .contains("fsnowrdg")
        );
        assert!(p.set("nope", 1.0).is_err());
        assert_eq!(p, d);
        assert_eq!(
            SaltFlux::from_name("prognostic"),
            Some(SaltFlux::Prognostic)
        );
        assert_eq!(
            SaltFlux::from_name(SaltFlux::Constant.name()),
            Some(SaltFlux::Constant)
        );
    }
}
