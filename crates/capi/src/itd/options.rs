//! The options of the strength and ridging calls in C layout: the codes of the participation,
//! redistribution, strength law and C_f source, `PressridgeParams` (the `ItdParams` fields)
//! and `PressridgeOptions`, with their conversion to the library's options and their checks.
//! Re-exported by `ffi::itd`, their one public path.

use super::*;

/// Participation function of Thorndike et al. (1975), G* (CICE `krdg_partic = 0`).
pub const PRESSRIDGE_PARTICIPATION_THORNDIKE: i32 = 0;
/// Exponential participation of Lipscomb et al. (2007), a* (CICE `krdg_partic = 1`, default).
pub const PRESSRIDGE_PARTICIPATION_EXPONENTIAL: i32 = 1;
/// Uniform redistribution of Hibler (1980), H* (CICE `krdg_redist = 0`).
pub const PRESSRIDGE_REDISTRIBUTION_UNIFORM: i32 = 0;
/// Exponential redistribution of Lipscomb et al. (2007), μ (CICE `krdg_redist = 1`, default).
pub const PRESSRIDGE_REDISTRIBUTION_EXPONENTIAL: i32 = 1;
/// Lipscomb's exponential with μ_rdg per category thickness from the table
/// `PressridgeOptions::mu_rdg_table` (simulated ridges, issue 34).
pub const PRESSRIDGE_REDISTRIBUTION_TABLE: i32 = 2;
/// Strength of Hibler (1979), P = P*·h·exp(−C*(1 − A)) (CICE `kstrength = 0`).
pub const PRESSRIDGE_STRENGTH_HIBLER1979: i32 = 0;
/// Strength of Rothrock (1975) with the frictional factor C_f (CICE `kstrength = 1`, default).
pub const PRESSRIDGE_STRENGTH_ROTHROCK: i32 = 1;
/// C_f is the constant `PressridgeOptions::cf`.
pub const PRESSRIDGE_CF_SOURCE_CONSTANT: i32 = 0;
/// C_f is looked up in `PressridgeOptions::cf_table` at the ridging category's thickness.
pub const PRESSRIDGE_CF_SOURCE_TABLE: i32 = 1;
/// C_f of Hibler (1980) (dimensionless).
pub const PRESSRIDGE_CF_HIBLER1980: f64 = 2.0;
/// C_f of Flato (1991) (dimensionless).
pub const PRESSRIDGE_CF_FLATO1991: f64 = 15.0;
/// C_f of CICE/Icepack, the default (dimensionless).
pub const PRESSRIDGE_CF_CICE: f64 = 17.0;

/// Physical constants and tunables (the fields of `pressridge::itd::ItdParams`, CICE's
/// defaults from [`pressridge_options_default`]).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PressridgeParams {
    /// Density of sea ice ρ_i (kg/m³), CICE `rhoi` = 917.
    pub rhoi: f64,
    /// Density of sea water ρ_w (kg/m³), CICE `rhow` = 1026.
    pub rhow: f64,
    /// Gravitational acceleration g (m/s²), CICE `gravit` = 9.80616.
    pub gravit: f64,
    /// Participation cut-off G* (dimensionless), CICE `Gstar` = 0.15.
    pub gstar: f64,
    /// Exponential participation scale a* (dimensionless), CICE `astar` = 0.05.
    pub astar: f64,
    /// Ridge thickness scale H* of the uniform redistribution (m), CICE `Hstar` = 25.
    pub hstar: f64,
    /// Largest thickness of ice that rafts (m), CICE `maxraft` = 1.
    pub maxraft: f64,
    /// e-folding parameter μ of the exponential redistribution (m^½), CICE `mu_rdg` = 3.
    pub mu_rdg: f64,
    /// Fraction of shear energy that goes into ridging C_s (dimensionless), CICE `Cs` = 0.25.
    pub cs: f64,
    /// Hibler (1979) P* (N/m²), CICE `Pstar` = 2.75e4.
    pub pstar: f64,
    /// Hibler (1979) C* (dimensionless), CICE `Cstar` = 20.
    pub cstar: f64,
    /// Smallest area treated as non-zero (dimensionless), CICE `puny` = 1e-11.
    pub puny: f64,
    /// Largest argument of the exponentials (dimensionless), CICE `exp_argmax` = 100.
    pub exp_argmax: f64,
    /// Upper bound given to the thickest category in the ridging step (m), 1e8.
    pub big: f64,
    /// Tolerance on |aice0 + Σ aicen − 1| of the strength input (dimensionless), 1e-6.
    pub area_tolerance: f64,
    /// Largest total area accepted by the ridging step (dimensionless), 2.
    pub max_area_before_ridging: f64,
    /// Maximum number of ridging iterations, CICE `nitermax` = 20.
    pub nitermax: i64,
}

/// Options of the strength and ridging calls; fill with [`pressridge_options_default`]
/// (CICE's defaults), then change fields. The ridging step uses `participation`,
/// `redistribution` and `params` only.
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct PressridgeOptions {
    /// `PRESSRIDGE_PARTICIPATION_*` (CICE `krdg_partic`: 0 Thorndike, 1 exponential).
    pub participation: i32,
    /// `PRESSRIDGE_REDISTRIBUTION_*` (CICE `krdg_redist`: 0 uniform, 1 exponential; 2 the
    /// exponential with μ_rdg from `mu_rdg_table`).
    pub redistribution: i32,
    /// `PRESSRIDGE_STRENGTH_*` (CICE `kstrength`: 0 Hibler 1979, 1 Rothrock 1975).
    pub strength_law: i32,
    /// `PRESSRIDGE_CF_SOURCE_CONSTANT` or `PRESSRIDGE_CF_SOURCE_TABLE`.
    pub cf_source: i32,
    /// Constant C_f (dimensionless, finite, > 0), used with
    /// `PRESSRIDGE_CF_SOURCE_CONSTANT`; presets `PRESSRIDGE_CF_HIBLER1980`,
    /// `PRESSRIDGE_CF_FLATO1991`, `PRESSRIDGE_CF_CICE`.
    pub cf: f64,
    /// Value written to the outputs of columns whose `valid` flag is 0 (N/m for strength,
    /// 1/s or m/s for the ridging rates). Default 0.
    pub fill: f64,
    /// C_f table handle used with `PRESSRIDGE_CF_SOURCE_TABLE` (borrowed, not freed by the
    /// call).
    pub cf_table: *const PressridgeCfTable,
    /// μ_rdg table handle used with `PRESSRIDGE_REDISTRIBUTION_TABLE` (borrowed, not freed by
    /// the call).
    pub mu_rdg_table: *const PressridgeMuRdgTable,
    /// Physical constants and tunables.
    pub params: PressridgeParams,
}

// The two conversions name every field of both structs once, without `..`: a field added
// to either struct does not compile until both are updated, and `name: name` shorthand
// cannot pair two different fields. `tests/params_faces.rs` checks the C and Fortran
// field lists against `ItdParams::FIELDS`.
impl From<&ItdParams> for PressridgeParams {
    fn from(p: &ItdParams) -> Self {
        let &ItdParams {
            rhoi,
            rhow,
            gravit,
            gstar,
            astar,
            hstar,
            maxraft,
            mu_rdg,
            cs,
            pstar,
            cstar,
            puny,
            exp_argmax,
            big,
            nitermax,
            area_tolerance,
            max_area_before_ridging,
        } = p;
        Self {
            rhoi,
            rhow,
            gravit,
            gstar,
            astar,
            hstar,
            maxraft,
            mu_rdg,
            cs,
            pstar,
            cstar,
            puny,
            exp_argmax,
            big,
            area_tolerance,
            max_area_before_ridging,
            nitermax: nitermax as i64,
        }
    }
}

impl PressridgeParams {
    /// The library's parameters, every field checked by `ItdParams::set`.
    fn to_itd(self) -> FfiResult<ItdParams> {
        let Self {
            rhoi,
            rhow,
            gravit,
            gstar,
            astar,
            hstar,
            maxraft,
            mu_rdg,
            cs,
            pstar,
            cstar,
            puny,
            exp_argmax,
            big,
            area_tolerance,
            max_area_before_ridging,
            nitermax,
        } = self;
        if nitermax < 1 {
            return Err(FfiError::new(
                PRESSRIDGE_ERR_BAD_VALUE,
                format!("invalid parameter nitermax = {nitermax}: must be >= 1"),
            ));
        }
        let p = ItdParams {
            rhoi,
            rhow,
            gravit,
            gstar,
            astar,
            hstar,
            maxraft,
            mu_rdg,
            cs,
            pstar,
            cstar,
            puny,
            exp_argmax,
            big,
            nitermax: nitermax as usize,
            area_tolerance,
            max_area_before_ridging,
        };
        // Hosts pass the same parameters on every call: skip the checks for the parameters
        // this thread validated last time.
        if LAST_VALID_PARAMS.with(|c| c.get() == Some(self)) {
            return Ok(p);
        }
        // `set` validates one field against the others, which already hold their final
        // values, so the order of the checks does not matter.
        let mut checked = p;
        for f in ItdParams::FIELDS {
            checked.set(f.name, p.get(f.name).expect("a listed parameter"))?;
        }
        debug_assert_eq!(checked, p);
        LAST_VALID_PARAMS.with(|c| c.set(Some(self)));
        Ok(p)
    }
}

impl Default for PressridgeOptions {
    fn default() -> Self {
        let s = StrengthOptions::default();
        Self {
            participation: participation_code(s.participation),
            redistribution: redistribution_code(s.redistribution),
            strength_law: match s.formula {
                StrengthFormula::Hibler1979 => PRESSRIDGE_STRENGTH_HIBLER1979,
                StrengthFormula::Rothrock => PRESSRIDGE_STRENGTH_ROTHROCK,
            },
            cf_source: PRESSRIDGE_CF_SOURCE_CONSTANT,
            cf: match s.cf {
                Cf::Constant(c) => c,
                _ => CfPreset::Cice.value(),
            },
            fill: 0.0,
            cf_table: std::ptr::null(),
            mu_rdg_table: std::ptr::null(),
            params: PressridgeParams::from(&s.params),
        }
    }
}

fn participation_code(p: Participation) -> i32 {
    match p {
        Participation::Thorndike => PRESSRIDGE_PARTICIPATION_THORNDIKE,
        Participation::Exponential => PRESSRIDGE_PARTICIPATION_EXPONENTIAL,
    }
}

fn redistribution_code(r: Redistribution) -> i32 {
    match r {
        Redistribution::Uniform => PRESSRIDGE_REDISTRIBUTION_UNIFORM,
        Redistribution::Exponential => PRESSRIDGE_REDISTRIBUTION_EXPONENTIAL,
        Redistribution::Table(_) => PRESSRIDGE_REDISTRIBUTION_TABLE,
    }
}

fn bad_code(name: &str, v: i32, allowed: &str) -> FfiError {
    FfiError::new(
        PRESSRIDGE_ERR_BAD_VALUE,
        format!("options.{name} = {v} is not one of {allowed}"),
    )
}

impl PressridgeOptions {
    fn participation(&self) -> FfiResult<Participation> {
        match self.participation {
            PRESSRIDGE_PARTICIPATION_THORNDIKE => Ok(Participation::Thorndike),
            PRESSRIDGE_PARTICIPATION_EXPONENTIAL => Ok(Participation::Exponential),
            v => Err(bad_code(
                "participation",
                v,
                "0 (Thorndike), 1 (exponential)",
            )),
        }
    }

    /// # Safety
    /// `mu_rdg_table` must be null or a live handle.
    unsafe fn redistribution(&self) -> FfiResult<Redistribution> {
        match self.redistribution {
            PRESSRIDGE_REDISTRIBUTION_UNIFORM => Ok(Redistribution::Uniform),
            PRESSRIDGE_REDISTRIBUTION_EXPONENTIAL => Ok(Redistribution::Exponential),
            PRESSRIDGE_REDISTRIBUTION_TABLE => {
                check_ptr(self.mu_rdg_table, "options.mu_rdg_table")?;
                // SAFETY: checked non-null; a live handle is the caller's promise.
                Ok(Redistribution::Table(unsafe { (*self.mu_rdg_table).table }))
            }
            v => Err(bad_code(
                "redistribution",
                v,
                "0 (uniform), 1 (exponential), 2 (table)",
            )),
        }
    }

    /// The library's strength options (C_f table shared, not copied).
    ///
    /// # Safety
    /// `cf_table` must be null or a live handle.
    pub(crate) unsafe fn strength_options(&self) -> FfiResult<StrengthOptions> {
        let formula = match self.strength_law {
            PRESSRIDGE_STRENGTH_HIBLER1979 => StrengthFormula::Hibler1979,
            PRESSRIDGE_STRENGTH_ROTHROCK => StrengthFormula::Rothrock,
            v => return Err(bad_code("strength_law", v, "0 (Hibler 1979), 1 (Rothrock)")),
        };
        let cf = match self.cf_source {
            PRESSRIDGE_CF_SOURCE_CONSTANT => Cf::Constant(self.cf),
            PRESSRIDGE_CF_SOURCE_TABLE => {
                check_ptr(self.cf_table, "options.cf_table")?;
                // SAFETY: checked non-null; a live handle is the caller's promise.
                Cf::Table(Arc::clone(unsafe { &(*self.cf_table).table }))
            }
            v => return Err(bad_code("cf_source", v, "0 (constant), 1 (table)")),
        };
        Ok(StrengthOptions {
            participation: self.participation()?,
            // SAFETY: the caller's promise covers `mu_rdg_table` too.
            redistribution: unsafe { self.redistribution()? },
            formula,
            cf,
            params: self.params.to_itd()?,
        })
    }

    /// # Safety
    /// `mu_rdg_table` must be null or a live handle.
    pub(crate) unsafe fn ridge_options(&self) -> FfiResult<RidgeOptions> {
        Ok(RidgeOptions {
            participation: self.participation()?,
            // SAFETY: the caller's promise.
            redistribution: unsafe { self.redistribution()? },
            params: self.params.to_itd()?,
        })
    }

    /// The options behind a caller's pointer, or the defaults for null.
    ///
    /// # Safety
    /// `p` must be null or point to valid options.
    pub(crate) unsafe fn from_ptr(p: *const PressridgeOptions) -> FfiResult<Self> {
        if p.is_null() {
            return Ok(Self::default());
        }
        check_ptr(p, "options")?;
        // SAFETY: checked non-null and aligned; validity is the caller's promise.
        Ok(unsafe { *p })
    }
}

/// Fills `*options` with CICE/Icepack's defaults: exponential participation and
/// redistribution, Rothrock strength, constant C_f = 17, fill 0, the `ItdParams` defaults.
///
/// # Safety
/// `options` must be valid for one write.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn pressridge_options_default(options: *mut PressridgeOptions) -> i32 {
    // SAFETY: checked by `put`.
    guard(|| unsafe { put(options, PressridgeOptions::default(), "options") })
}
